#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_data.h"
#include "shared/inject_pass.h"
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"

// Direct light per occupied voxel (paper section VI), visible or not: Lambert
// radiance rho/pi * E * attenuation * visibility for every light, plus the
// voxel's emitted radiance. Writes it to the voxel's slot of the direct light
// (kept for the bounces) and to the radiance volume, alpha = opacity (1 for
// occupied voxels).
// One invocation per occupied voxel (an entry of the list); empty voxels keep
// the zero that clears left.
layout(local_size_x = VOXEL_LIST_GROUP) in;

layout(set = 0, binding = BIND_INJECT_GRID) uniform Grid { VoxelGrid grid; };
layout(set = 0, binding = BIND_INJECT_ACCUM, r32f) uniform readonly image3D accum;
layout(set = 0, binding = BIND_INJECT_LIGHTS, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = BIND_INJECT_SHADOW_VIEWS, std430) readonly buffer Views { GpuShadowView shadowViews[]; };
layout(set = 0, binding = BIND_INJECT_SHADOW_MAP) uniform sampler2DArrayShadow shadowMap;
layout(set = 0, binding = BIND_INJECT_DIRECT, rgba16f) uniform writeonly image3D outDirect;
layout(set = 0, binding = BIND_INJECT_OUT_RADIANCE, rgba16f) uniform writeonly image3D outRadiance;
VOXEL_INDEX_BLOCK(BIND_INJECT_INDEX, readonly);
VOXEL_LIST_BLOCK(BIND_INJECT_LIST, readonly);
layout(push_constant) uniform Push { VoxelLightPush pc; };

#include "lib/math.glsl"
#include "lib/voxel_attributes.glsl"
#include "lib/voxel_index.glsl"
#include "lib/lights.glsl"
#include "lib/shadow_map.glsl"
#include "lib/voxel_trace.glsl"
#include "lib/voxel_list_dispatch.glsl"


void main() {
    uint entry = listInvocation();
    if (entry >= list.header.counts.x || list.entries[entry] == VOXEL_LIST_FREE) return;
    ivec3 v = listVoxel(list.entries[entry]);
    uint slot = entry;
    vec3 albedo = voxelAlbedo(slot);
    vec3 pos, neg;
    voxelNormalWeights(slot, pos, neg);
    vec3 n = voxelNormal(slot);
    float s = grid.originSize.w;
    // Lit position: the voxel centre pushed half a voxel along its normal.
    vec3 P = grid.originSize.xyz + (vec3(v) + 0.5) * s + n * (0.5 * s);

    // Emitters lit explicitly (as LIGHT_AREA patches) keep their emission out
    // of the radiance that cones gather, or it would be counted twice.
    vec3 radiance = pc.params.z > 0.5 ? voxelEmission(slot) : vec3(0.0);
    for (uint i = 0u; i < pc.flags.x; ++i) {
        GpuLight light = lights[i];
        vec3 L;
        float dist;
        vec3 E = lightIrradiance(light, P, L, dist);
        // Eq. 5 generalized to signed weights: sum over axes of the weight of
        // the normals facing the light along that axis times the cosine there.
        // For a single normal it is exactly W_x D_x + W_y D_y + W_z D_z.
        float att = pc.flags.y != 0u ? dot(pos, max(L, 0.0)) + dot(neg, max(-L, 0.0)) : max(dot(n, L), 0.0);
        if (att <= 0.0 || all(equal(E, vec3(0.0)))) continue;
        uint mode = pc.flags.z != OCCLUSION_PER_LIGHT ? pc.flags.z : light.shadow.z;
        bool area = uint(light.position.w) == LIGHT_AREA;
        // Patches have no shadow maps; their rays stop short of the emitter's own voxels.
        if (area && mode == OCCLUSION_SHADOW_MAP) mode = OCCLUSION_RAYCAST_HARD;
        if (area) dist -= 2.0 * s / max(abs(dot(light.direction.xyz, L)), 0.2);
        float vis = 1.0;
        if (mode == OCCLUSION_SHADOW_MAP && pc.flags.w != 0u)
            vis = shadowVisibility(light, P, n, pc.params.y);
        else if (mode == OCCLUSION_RAYCAST_HARD || mode == OCCLUSION_RAYCAST_SOFT)
            vis = voxelRayVisibility(P, L, dist, mode == OCCLUSION_RAYCAST_SOFT, pc.params.x);
        radiance += albedo / PI * E * att * vis;
    }
    imageStore(outDirect, slotTexel(slot, 0u), vec4(radiance, 1.0));
    imageStore(outRadiance, v, vec4(radiance, 1.0));
}
