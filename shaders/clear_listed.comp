#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"
#include "shared/voxelize_pass.h"

// Frees listed voxels: zeroes their slots' attributes, extents and direct light, their
// radiance (the per-voxel passes write only listed voxels) and their index.
// CLEAR_LISTED_DYNAMIC frees what dynamic geometry wrote last frame (their
// slots are taken again by the next dynamic voxelization; static voxels
// stay); CLEAR_LISTED_ALL frees every occupied voxel before static geometry
// is voxelized again, which leaves the volumes as zero as a clear of the
// whole grid at a fraction of the bytes.
layout(local_size_x = VOXEL_LIST_GROUP) in;

layout(set = 0, binding = BIND_CLEAR_GRID) uniform Grid { VoxelGrid grid; };
layout(set = 0, binding = BIND_CLEAR_ACCUM, r32f) uniform writeonly image3D accum;
VOXEL_LIST_BLOCK(BIND_CLEAR_LIST, readonly);
layout(set = 0, binding = BIND_CLEAR_DIRECT, rgba16f) uniform writeonly image3D direct;
layout(set = 0, binding = BIND_CLEAR_RADIANCE, rgba16f) uniform writeonly image3D radiance;
VOXEL_INDEX_BLOCK(BIND_CLEAR_INDEX, );
VOXEL_EXTENTS_BLOCK(BIND_CLEAR_EXTENTS, writeonly);
layout(push_constant) uniform Push { ClearListedPush pc; };

#include "lib/voxel_list_dispatch.glsl"
#include "lib/voxel_index.glsl"

void main() {
    uint first = pc.scope.x == CLEAR_LISTED_ALL ? 0u : list.header.counts.y;
    uint i = first + listInvocation();
    if (i >= list.header.counts.x || list.entries[i] == VOXEL_LIST_FREE) return;
    ivec3 v = listVoxel(list.entries[i]);
    for (uint c = 0u; c < VOXEL_CHANNELS; ++c) imageStore(accum, slotTexel(i, c), vec4(0.0));
    voxelExtents[i] = 0u;
    imageStore(direct, slotTexel(i, 0u), vec4(0.0));
    imageStore(radiance, v, vec4(0.0));
    voxelIndex[voxelIndexOffset(v)] = 0u;
}
