#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"
#include "shared/clipmap_pass.h"

// A clipmap level moved its window by whole voxels. Its index and list are
// toroidal (storage voxel = world voxel mod N), so every voxel that stays in
// the window keeps its slot; a storage cell whose world voxel changed held a
// voxel that left the window: free it (its slot's sums, extents, direct light,
// index word) and mark its list entry. Static voxelization then fills the exposed
// slabs. One invocation per static list entry (dynamic ones were cleared).
layout(local_size_x = VOXEL_LIST_GROUP) in;

layout(set = 0, binding = BIND_SCROLL_ACCUM, r32f) uniform writeonly image3D accum;
layout(set = 0, binding = BIND_SCROLL_DIRECT, rgba16f) uniform writeonly image3D direct;
layout(set = 0, binding = BIND_SCROLL_INDEX, std430) buffer VoxelIndex { uint voxelIndex[]; };
VOXEL_LIST_BLOCK(BIND_SCROLL_LIST, );
VOXEL_EXTENTS_BLOCK(BIND_SCROLL_EXTENTS, writeonly);
layout(push_constant) uniform Push { ClipScrollPush pc; };

#include "lib/voxel_list_dispatch.glsl"

// The world voxel a window with minimum corner m keeps in storage cell s.
ivec3 worldVoxel(ivec3 s, ivec3 m, int n) {
    ivec3 r = (s - m) % n;  // in (-n, n): GLSL's % keeps the dividend's sign
    return m + r + n * ivec3(lessThan(r, ivec3(0)));
}

void main() {
    uint i = listInvocation();
    if (i >= list.header.counts.y) return;
    uint entry = list.entries[i];
    if (entry == VOXEL_LIST_FREE) return;
    int n = pc.oldMin.w;
    ivec3 s = unpackVoxel(entry);
    if (worldVoxel(s, pc.oldMin.xyz, n) == worldVoxel(s, pc.newMin.xyz, n)) return;
    for (uint c = 0u; c < VOXEL_CHANNELS; ++c) imageStore(accum, slotTexel(i, c), vec4(0.0));
    voxelExtents[i] = 0u;
    imageStore(direct, slotTexel(i, 0u), vec4(0.0));
    voxelIndex[uint(s.x) + uint(n) * (uint(s.y) + uint(n) * uint(s.z))] = 0u;
    list.entries[i] = VOXEL_LIST_FREE;
    atomicAdd(list.header.allGroups.w, 1u);
}
