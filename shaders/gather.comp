#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_data.h"
#include "shared/cone_resolve_pass.h"
#include "shared/gather_pass.h"
#include "shared/voxel_data.h"

// Deferred voxel cone tracing per pixel (paper section VIII-X): indirect
// diffuse from a cone set over the normal hemisphere, specular from one cone
// along the reflected view direction, and ambient occlusion from the diffuse
// cones. Runs at the trace resolution (--trace-scale); the G-buffer is read at
// the pixel each trace pixel stands for.
// Built with RAYS (--gather-trace rays, a fitted grid's): the indirect diffuse
// light and AO from cosine rays marched voxel by voxel through the radiance
// volume (lib/voxel_rays.glsl) instead of the cones; specular keeps its cone.
#define CONE_USE_RADIANCE_VOLUME
#define CONE_NEAR_SIDES  // near samples read every voxel for thin walls and show the side facing them
layout(local_size_x = GATHER_GROUP, local_size_y = GATHER_GROUP) in;

#ifdef DVSGI_CLIPMAP
// The level a pixel's cones start at (clipSurfaceLevel), set per pixel.
int coneFirst = 0;
#define CONE_FIRST_LEVEL coneFirst
layout(set = 0, binding = BIND_CONE_GRID) uniform Levels { ConeLevels clip; };
layout(set = 0, binding = BIND_GATHER_RADIANCE) uniform sampler3D radianceAtlas;
layout(set = 0, binding = BIND_CONE_DIRECTIONAL) uniform sampler3D directionalAtlas;
#else
layout(set = 0, binding = BIND_CONE_GRID) uniform Grid { VoxelGrid grid; };
layout(set = 0, binding = BIND_GATHER_RADIANCE) uniform sampler3D radianceVolume;
layout(set = 0, binding = BIND_CONE_DIRECTIONAL) uniform sampler3D directional;
#endif
layout(set = 0, binding = BIND_GATHER_FRAME) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = BIND_GATHER_BASE) uniform sampler2D gBase;
layout(set = 0, binding = BIND_GATHER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = BIND_GATHER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = BIND_GATHER_OUT_DIFFUSE, rgba16f) uniform writeonly image2D outDiffuse;
layout(set = 0, binding = BIND_GATHER_OUT_SPECULAR, rgba16f) uniform writeonly image2D outSpecular;
layout(push_constant) uniform Push { GatherPush pc; };
#ifdef DVSGI_RAYS
#include "shared/bounce_pass.h"
#include "shared/voxel_list_pass.h"
layout(set = 0, binding = BIND_GATHER_RAY_SIDES, rgba32ui) uniform readonly uimage3D sides;
layout(set = 0, binding = BIND_GATHER_RAY_NORMALS, r32ui) uniform readonly uimage3D rayNormals;
VOXEL_EXTENTS_BLOCK(BIND_GATHER_RAY_EXTENTS, readonly);
layout(set = 0, binding = BIND_GATHER_RAY_OCCUPANCY, std430) readonly buffer RayOccupancy { uint rayOccupancy[]; };
VOXEL_INDEX_BLOCK(BIND_GATHER_RAY_INDEX, readonly);
#define RAY_RADIANCE(c) texelFetch(radianceVolume, c, 0)
#endif

#include "lib/brdf.glsl"
#include "lib/cone_trace.glsl"
#include "lib/cone_sets.glsl"
#ifdef DVSGI_RAYS
#include "lib/voxel_sides.glsl"
#include "lib/voxel_index.glsl"
#include "lib/voxel_rays.glsl"
#endif

// Roughness -> specular cone half-angle: tan(half-angle) = roughness^2 (the
// GGX alpha), clamped below by the minimum aperture.
float specularTanHalf(float roughness) {
    return max(roughness * roughness, pc.params.w);
}

// Indirect diffuse (rgb, a = 1 - occlusion) and specular at surface point P.
// `turn`: the six cones' turn about N (coneSpinTurn).
void gatherAt(vec3 P, vec3 N, vec3 V, vec4 base, float roughness, float turn, out vec4 diffuseOut, out vec3 specular) {
    float metallic = base.a;
    // Offset along the normal so the surface does not sample its own voxels.
    float originHeight = pc.cone.surface.z * traceGrid(CONE_FIRST_LEVEL).originSize.w;
    vec3 origin = P + N * originHeight;

    float occlusion;
#ifdef DVSGI_RAYS
    // The same rays every frame: a still image does not flicker. The resolve's
    // 3x3 tent, run --gather-ray-filter times with wider taps, averages each
    // pixel's rays with its neighbours' on the same surface (gatherRaySeed
    // spreads them).
    float s = grid.originSize.w;
    uvec2 px = gl_GlobalInvocationID.xy;
    vec3 E = PI * pixelRaysCosine((P - grid.originSize.xyz) / s, N, uintBitsToFloat(pc.rays.y), pc.rays.x,
                                  gatherRaySeed(px.x, px.y, pc.rays.x), pc.params.y, pc.rays.z != 0u, occlusion);
#else
    vec3 E = uint(pc.cone.surface.w) == CONE_SET_16 ? gatherIrradiance16(origin, N, originHeight, pc.cone, pc.params.y, occlusion)
                                       : gatherIrradiance6(origin, N, originHeight, pc.cone, pc.params.y, turn, occlusion);
#endif
    // Demodulated: the albedo base.rgb (1 - metallic) multiplies it in the
    // composite, after upsampling and temporal accumulation, so those filter
    // the smooth irradiance and never blur or smear the textures.
    diffuseOut = vec4(E / PI, 1.0 - occlusion);

    specular = vec3(0.0);
    if (pc.flags.y != 0u && isGlossy(metallic, roughness)) {
        vec3 R = reflect(-V, N);
        vec4 c = traceCone(origin, N, originHeight, R, specularTanHalf(roughness), pc.cone, true);
        vec3 F0 = mix(vec3(0.04), base.rgb, metallic);
        float NoV = max(dot(N, V), 0.0);
        specular = (F0 + (1.0 - F0) * pow(1.0 - NoV, 5.0)) * c.rgb;
    }
}

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(px), pc.flags.zw))) return;
    // The G-buffer pixel this trace pixel stands for (the upsampler uses the same mapping).
    ivec2 g = min(ivec2((vec2(px) + 0.5) * vec2(frame.sizes.xy) / vec2(pc.flags.zw)), ivec2(frame.sizes.xy) - 1);
    float depth = texelFetch(gDepth, g, 0).r;
    if (depth >= 1.0) {
        imageStore(outDiffuse, px, vec4(0.0, 0.0, 0.0, 1.0));
        imageStore(outSpecular, px, vec4(0.0));
        return;
    }
    vec2 ndc = (vec2(g) + 0.5) / vec2(frame.sizes.xy) * 2.0 - 1.0;
    vec4 w = frame.invViewProj * vec4(ndc, depth, 1.0);
    vec3 P = w.xyz / w.w;
    vec4 base = texelFetch(gBase, g, 0);
    vec4 nr = texelFetch(gNormal, g, 0);
    vec3 N = normalize(nr.xyz);
    vec3 V = normalize(frame.cameraPos.xyz - P);
    float turn = pc.flags.x == 0u ? 0.0 : pc.flags.x == 1u ? coneSpinTurn(px.x, px.y) : coneTurn(pc.flags.x - 2u);
#ifdef DVSGI_CLIPMAP
    // Near the face of the level the pixel starts at, the next level's
    // gather is blended in, so the start level changes without a seam.
    float blend;
    coneFirst = clipSurfaceLevel(P, blend);
    vec4 diffuse;
    vec3 specular;
    gatherAt(P, N, V, base, nr.w, turn, diffuse, specular);
    if (blend > 0.0) {
        vec4 d1;
        vec3 s1;
        coneFirst += 1;
        gatherAt(P, N, V, base, nr.w, turn, d1, s1);
        diffuse = mix(diffuse, d1, blend);
        specular = mix(specular, s1, blend);
    }
#else
    vec4 diffuse;
    vec3 specular;
    gatherAt(P, N, V, base, nr.w, turn, diffuse, specular);
#endif
    imageStore(outDiffuse, px, diffuse);
    imageStore(outSpecular, px, vec4(specular, 1.0));
}
