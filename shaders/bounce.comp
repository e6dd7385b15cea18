#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/voxel_data.h"

// One extra bounce per occupied voxel (paper section IX): the irradiance from
// six cones over the voxel's normal hemisphere, traced through the filtered
// directional volumes of the current radiance, times albedo / pi, added to the
// voxel's direct light + emission. Repeating it K times (re-filtering between)
// gives L_direct + T L_direct + ... + T^K L_direct.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(set = 0, binding = BIND_CONE_GRID) uniform Grid { VoxelGrid grid; };
layout(set = 0, binding = BIND_CONE_DIRECTIONAL) uniform sampler3D directional[6];
layout(set = 0, binding = BIND_BOUNCE_ACCUM, r32f) uniform readonly image3D accum;
layout(set = 0, binding = BIND_BOUNCE_DIRECT, rgba16f) uniform readonly image3D direct;
layout(set = 0, binding = BIND_BOUNCE_OUT, rgba16f) uniform writeonly image3D outRadiance;
layout(push_constant) uniform Push { BouncePush pc; };

#include "lib/voxel_attributes.glsl"
#include "lib/cone_trace.glsl"

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    int N = int(grid.dims.x);
    if (any(greaterThanEqual(v, ivec3(N)))) return;
    vec4 d = imageLoad(direct, v);
    if (voxelCount(v) <= 0.0) {
        imageStore(outRadiance, v, d);
        return;
    }
    vec3 n = voxelNormal(v);
    if (dot(n, n) < 0.5) {  // opposite faces cancelled: use the strongest weight's axis
        vec3 pos, neg;
        voxelNormalWeights(v, pos, neg);
        vec3 m = max(pos, neg);
        int a = m.x >= m.y && m.x >= m.z ? 0 : (m.y >= m.z ? 1 : 2);
        n = vec3(0.0);
        n[a] = pos[a] >= neg[a] ? 1.0 : -1.0;
    }
    float s = grid.originSize.w;
    // Start one voxel off the surface so the cones do not gather the voxel itself.
    vec3 origin = grid.originSize.xyz + (vec3(v) + 0.5 + n) * s;
    float occlusion;
    vec3 E = gatherIrradiance6(origin, n, s, pc.cone, 0.0, occlusion);
    vec3 albedo = voxelAlbedo(v);
    imageStore(outRadiance, v, vec4(d.rgb + albedo / 3.14159265 * E, d.a));
}
