#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_data.h"
#include "shared/shadow_pass.h"
#include "shared/lighting_pass.h"
#include "shared/voxel_data.h"

// Deferred direct lighting: for every pixel, the sum over lights of
// BRDF * cos * irradiance * shadow visibility, plus emitted radiance. The
// visibility comes from the shadow maps or, with shadow cones (paper Table V),
// from a cone traced through the voxel volumes toward the light.
// The SHADOW_MAPS_ONLY variant leaves the cones out, for frames with neither
// shadow cones nor area lights: on llvmpipe the cone paths made the pass about
// 3.7x dearer (Sponza, 640x360) even where no lane took them.
#define CONE_USE_RADIANCE_VOLUME
layout(local_size_x = LIGHTING_GROUP, local_size_y = LIGHTING_GROUP) in;

layout(set = 0, binding = BIND_LIGHT_FRAME) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = BIND_LIGHT_GBUF_BASE) uniform sampler2D gBase;
layout(set = 0, binding = BIND_LIGHT_GBUF_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = BIND_LIGHT_GBUF_EMISSION) uniform sampler2D gEmission;
layout(set = 0, binding = BIND_LIGHT_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = BIND_LIGHT_LIGHTS, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = BIND_LIGHT_SHADOW_VIEWS, std430) readonly buffer Views { GpuShadowView shadowViews[]; };
layout(set = 0, binding = BIND_LIGHT_SHADOW_MAP) uniform sampler2DArray shadowMap;
layout(set = 0, binding = BIND_LIGHT_SHADOW_GRADIENT) uniform sampler2DArray shadowGradient;
layout(set = 0, binding = BIND_LIGHT_OUT_DIRECT, rgba32f) uniform writeonly image2D outDirect;
#ifdef DVSGI_SHADOW_MAPS_ONLY
// The cone-free variant declares no voxel volume (the layout keeps the bindings).
#elif defined(DVSGI_CLIPMAP)
// Clipmap levels (lib/cone_trace.glsl): a pixel's cones start at the finest
// level that holds its surface.
int coneFirst = 0;
#define CONE_FIRST_LEVEL coneFirst
layout(set = 0, binding = BIND_LIGHT_VOXEL_GRID) uniform Levels { ConeLevels clip; };
layout(set = 0, binding = BIND_LIGHT_VOXEL_RADIANCE) uniform sampler3D radianceAtlas;
layout(set = 0, binding = BIND_LIGHT_VOXEL_DIRECTIONAL) uniform sampler3D directionalAtlas;
#else
layout(set = 0, binding = BIND_LIGHT_VOXEL_GRID) uniform Grid { VoxelGrid grid; };
layout(set = 0, binding = BIND_LIGHT_VOXEL_RADIANCE) uniform sampler3D radianceVolume;
layout(set = 0, binding = BIND_LIGHT_VOXEL_DIRECTIONAL) uniform sampler3D directional;
#endif
#ifdef DVSGI_AREA_RAYS
// Area lights' visibility by a ray to each patch through this frame's voxels
// (lib/voxel_rays.glsl), as the per-pixel gather's rays walk them.
#include "shared/bounce_pass.h"
#include "shared/voxel_list_pass.h"
layout(set = 0, binding = BIND_LIGHT_RAY_SIDES, rgba32ui) uniform readonly uimage3D sides;
layout(set = 0, binding = BIND_LIGHT_RAY_NORMALS, r32ui) uniform readonly uimage3D rayNormals;
VOXEL_EXTENTS_BLOCK(BIND_LIGHT_RAY_EXTENTS, readonly);
layout(set = 0, binding = BIND_LIGHT_RAY_OCCUPANCY, std430) readonly buffer RayOccupancy { uint rayOccupancy[]; };
VOXEL_INDEX_BLOCK(BIND_LIGHT_RAY_INDEX, readonly);
#define RAY_RADIANCE(c) texelFetch(radianceVolume, c, 0)
#endif
layout(set = 0, binding = BIND_LIGHT_OUT_SHADOW, r16f) uniform writeonly image2D outShadow;

layout(push_constant) uniform Push { LightingPush pc; };

#include "lib/lights.glsl"
#include "lib/brdf.glsl"
#include "lib/shadow_map.glsl"
#ifndef DVSGI_SHADOW_MAPS_ONLY
#include "lib/cone_trace.glsl"
#ifdef DVSGI_AREA_RAYS
#include "lib/voxel_sides.glsl"
#include "lib/voxel_index.glsl"
#include "lib/voxel_rays.glsl"
#endif

float coneVisibility(vec3 P, vec3 N, vec3 L, float dist) {
    ConeParams p = pc.cone;
    p.trace.z = min(dist, p.trace.z);
    float originHeight = pc.cone.surface.z * traceGrid(CONE_FIRST_LEVEL).originSize.w;
    vec3 origin = P + N * originHeight;
    return 1.0 - traceCone(origin, N, originHeight, L, pc.shadow.y, p, true).a;
}

#ifdef DVSGI_AREA_RAYS
// Whether a ray from P reaches the patch's centre: with --emitter-patches
// patches the shadow is soft in steps of one patch. A cone at least as wide as
// the shadow cones, whose samples blend a voxel's neighbours in, left the
// direct light on cornell-emissive's surfaces 3 % short at 64^3
// (docs/quality.md, "Area lights seen by rays"). The ray stops
// two voxels short of the emitter's plane, so the emitter's own voxel layer
// (and a ceiling beside it in the same layer) does not shadow it, as the
// voxels' own rays to a patch stop (inject.comp).
// The pixel's rays' start and sheet, found once (rayStartOffset).
PixelRays pixelRays;
// `offset`: where the ray starts off the surface, in voxels (rayStartOffset).
float areaVisibility(vec3 P, vec3 N, vec3 L, float dist, float radius, vec3 emitterNormal, float offset) {
    float s = grid.originSize.w;
    vec3 p = (P - grid.originSize.xyz) / s;
    vec3 toEmitter = L * (dist / s) - N * offset;  // from the ray's origin, in voxels
    float reach = length(toEmitter);
    vec3 d = toEmitter / reach;
    reach -= 2.0 / max(abs(dot(emitterNormal, d)), 0.2);
    return reach <= 0.0 || pixelRayClear(p, N, d, pixelRays, reach) ? 1.0 : 0.0;
}
// The pixel's rays start as its gather's do (lib/voxel_rays.glsl, pixelRaysAt):
// before a surface that faces back within the offset, and they meet a sheet
// nearer than that.
float rayStartOffset(vec3 P, vec3 N) {
    float s = grid.originSize.w;
    pixelRays = pixelRaysAt((P - grid.originSize.xyz) / s, N, pc.shadow.z, int(grid.dims.x));
    return pixelRays.start;
}
#else
float rayStartOffset(vec3 P, vec3 N) { return 0.0; }
float areaVisibility(vec3 P, vec3 N, vec3 L, float dist, float radius, vec3 emitterNormal, float offset) {
    ConeParams p = pc.cone;
    float s = traceGrid(CONE_FIRST_LEVEL).originSize.w;
    float tanHalf = max(radius / dist, pc.shadow.y);
    // Stop where the last sample's footprint (a cell, or the cone's diameter
    // there, on each side) still misses the emitter's own voxel layer, which a
    // cone arriving obliquely crosses for longer.
    float footprint = 2.0 * max(s, 2.0 * dist * tanHalf) + s;
    float cosE = max(abs(dot(emitterNormal, L)), 0.2);
    // The cone starts off the surface, so it aims at the emitter from there
    // and its length is measured from there.
    float originHeight = pc.cone.surface.z * s;
    vec3 origin = P + N * originHeight;
    vec3 toEmitter = P + L * dist - origin;
    float reach = length(toEmitter);
    p.trace.z = min(reach - footprint / cosE, p.trace.z);
    if (p.trace.z <= 0.0) return 1.0;
    // Visibility only, for up to --emitter-patches cones per pixel: whole
    // levels (rounded) at half the cost of blending two.
    return 1.0 - traceCone(origin, N, originHeight, toEmitter / reach, tanHalf, p, false).a;
}
#endif
#endif

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(px), frame.sizes.xy))) return;
    vec4 emission = texelFetch(gEmission, px, 0);
    if (emission.a == 0.0) {  // background: no environment light
        imageStore(outDirect, px, vec4(0.0));
        imageStore(outShadow, px, vec4(1.0));
        return;
    }
    float depth = texelFetch(gDepth, px, 0).r;
    vec2 ndc = (vec2(px) + 0.5) / vec2(frame.sizes.xy) * 2.0 - 1.0;
    vec4 world = frame.invViewProj * vec4(ndc, depth, 1.0);
    vec3 P = world.xyz / world.w;
    vec4 base = texelFetch(gBase, px, 0);
    vec4 nr = texelFetch(gNormal, px, 0);
    vec3 N = normalize(nr.xyz);
    vec3 V = normalize(frame.cameraPos.xyz - P);
#if defined(DVSGI_CLIPMAP) && !defined(DVSGI_SHADOW_MAPS_ONLY)
    // No blend with the next level here: visibility cones are narrow, and a
    // level's border moves a shadow's edge by less than its voxel.
    float blend;
    coneFirst = clipSurfaceLevel(P, blend);
#endif

    vec3 radiance = emission.rgb;
    float visSum = 0.0, visCount = 0.0;
    float rayStart = -1.0;  // computed at the first patch that needs it
    for (uint i = 0u; i < frame.sizes.z; ++i) {
        vec3 L;
        float dist;
        vec3 E = lightIrradiance(lights[i], P, L, dist);
        if (dot(N, L) <= 0.0 || all(equal(E, vec3(0.0)))) continue;
        float vis = 1.0;
#ifndef DVSGI_SHADOW_MAPS_ONLY
        if (uint(lights[i].position.w) == LIGHT_AREA) {
            // No shadow map for a patch: a ray through the voxels (AREA_RAYS)
            // or a cone as wide as the patch looks from here, stopping short
            // of the emitter's own voxels.
            if (rayStart < 0.0) rayStart = rayStartOffset(P, N);
            vis = areaVisibility(P, N, L, dist, sqrt(lights[i].radiant.w), lights[i].direction.xyz, rayStart);
        } else if (pc.shadow.x > 0.5)
            vis = coneVisibility(P, N, L, dist);
        else
#endif
        if (frame.shadowParams.y > 0.5)
            vis = shadowVisibility(lights[i], P, N, frame.shadowParams.x);
        radiance += surfaceBrdfCos(base.rgb, base.a, nr.w, N, L, V) * E * vis;
        visSum += vis;
        visCount += 1.0;
    }
    imageStore(outDirect, px, vec4(radiance, 1.0));
    imageStore(outShadow, px, vec4(visCount > 0.0 ? visSum / visCount : 1.0));
}
