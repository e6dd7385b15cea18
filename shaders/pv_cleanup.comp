#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"
#include "shared/pv_pass.h"

// Progressive voxelization, cleanup (shared/pv_pass.h): last frame's voxels
// either move into this frame's list with their sums or, where a depth buffer
// shows empty space in front of its surface, are freed. No atomics on the
// volumes: every voxel is one list entry, so each invocation owns its voxel,
// its old slot and the new slot it takes.
layout(local_size_x = VOXEL_LIST_GROUP) in;

layout(set = 0, binding = BIND_PV_GRID) uniform Grid { VoxelGrid grid; };
layout(set = 0, binding = BIND_PV_ACCUM, r32f) uniform writeonly image3D accum;
VOXEL_LIST_BLOCK(BIND_PV_LIST, );
VOXEL_INDEX_BLOCK(BIND_PV_INDEX, );
layout(set = 0, binding = BIND_PV_RADIANCE, rgba16f) uniform writeonly image3D radiance;
layout(set = 0, binding = BIND_PV_OLD_ACCUM, r32f) uniform readonly image3D oldAccum;
layout(set = 0, binding = BIND_PV_OLD_LIST, std430) readonly buffer OldList { VoxelListHeader header; uint entries[]; } oldList;
layout(set = 0, binding = BIND_PV_VIEWS, std430) readonly buffer Views { PvDepthView views[]; };
layout(set = 0, binding = BIND_PV_CAMERA_DEPTH) uniform sampler2D cameraDepth;
layout(set = 0, binding = BIND_PV_SHADOW_DEPTH) uniform sampler2DArray shadowDepth;
layout(push_constant) uniform Push { PvCleanupPush pc; };

#include "lib/voxel_list_dispatch.glsl"
#include "lib/voxel_index.glsl"
#include "lib/pv_project.glsl"

const uint KEEP = 0u, BAND = 1u, FREE = 2u;

// What one depth view says about the voxel of centre c: nothing (KEEP: the
// voxel lies outside the view, or some ray through it sees a surface in
// front of it), FREE (every ray through the voxel saw past it: the recorded
// surface lies behind it by more than the tolerance, or nothing was
// recorded), or BAND (a ray's recorded surface lies within the tolerance of
// the voxel's depth). The chapter tests the centre's ray only, which frees a
// voxel whose centre lies just outside a silhouette it holds; here nine rays
// spread over the voxel's projected footprint must all see past it.
uint classify(PvDepthView view, vec3 c) {
    vec4 clip;
    vec3 ndc;
    if (!projectInView(view.viewProj, c, clip, ndc)) return KEEP;
    float b = pc.weights.z;
    // The footprint's half-extent in NDC: the largest shift of the centre's
    // projection along the grid axes, by the tolerance.
    float r = 0.0;
    for (int a = 0; a < 3; ++a) {
        vec4 e = clip + b * view.viewProj[a];
        if (e.w <= 0.0) return KEEP;
        vec2 d = abs(e.xy / e.w - ndc.xy);
        r = max(r, max(d.x, d.y));
    }
    bool camera = view.params.x < 0.0;
    ivec2 size = camera ? ivec2(pc.sizes.yz) : ivec2(pc.sizes.w);
    float tolerance = b + view.params.y + view.params.z * clip.w;
    uint freed = 0u;
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            vec2 q = ndc.xy + r * vec2(i, j);
            if (any(greaterThan(abs(q), vec2(1.0)))) continue;  // partly outside: cannot be proven empty
            ivec2 pixel = ndcPixel(q, size);
            float recorded = camera ? texelFetch(cameraDepth, pixel, 0).r
                                    : texelFetch(shadowDepth, ivec3(pixel, int(view.params.x)), 0).r;
            // Cleared depth: nothing along this ray inside the view's range.
            if (recorded >= 1.0) {
                ++freed;
                continue;
            }
            // Distance along the ray from the voxel centre's depth to the surface.
            float gap = distance(unprojectNdc(view.invViewProj, q, recorded), unprojectNdc(view.invViewProj, q, ndc.z));
            if (gap <= tolerance) return BAND;
            if (recorded > ndc.z) ++freed;
        }
    return freed == 9u ? FREE : KEEP;
}

void main() {
    uint i = listInvocation();
    if (i >= oldList.header.counts.x) return;
    uint entry = oldList.entries[i];
    ivec3 v = listVoxel(entry);
    vec3 c = grid.originSize.xyz + (vec3(v) + 0.5) * grid.originSize.w;
    // The camera's G-buffer is exact and refills what it sees, so its band
    // wins over a shadow map's (a texel holds the depth at its centre only).
    uint verdict = KEEP;
    for (uint k = 0u; k < pc.sizes.x; ++k) {
        uint s = classify(views[k], c);
        if (s == BAND && views[k].params.x < 0.0) {
            verdict = BAND;
            break;
        }
        if (s == FREE) verdict = FREE;
    }
    if (verdict == FREE) {
        voxelIndex[voxelIndexOffset(v)] = 0u;
        imageStore(radiance, v, vec4(0.0));
        return;
    }
    uint slot = atomicAdd(list.header.counts.x, 1u);  // the new list holds at most the old one's entries
    list.entries[slot] = entry;
    voxelIndex[voxelIndexOffset(v)] = (slot + 1u) | VOXEL_INDEX_STATIC;
    float count = imageLoad(oldAccum, slotTexel(i, CH_COUNT)).r;
    float keep = verdict == BAND ? pc.weights.x : pc.weights.y;
    float scale = count > keep ? keep / count : 1.0;
    for (uint ch = 0u; ch < VOXEL_CHANNELS; ++ch)
        imageStore(accum, slotTexel(slot, ch), vec4(imageLoad(oldAccum, slotTexel(i, ch)).r * scale));
}
