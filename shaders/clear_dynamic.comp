#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"
#include "shared/voxelize_pass.h"

// Zeroes the voxels that dynamic geometry wrote last frame (the list's dynamic
// entries): their attributes, and their direct light and radiance, which the
// per-voxel passes write only for listed voxels. Static voxels stay.
layout(local_size_x = VOXEL_LIST_GROUP) in;

layout(set = 0, binding = BIND_CLEAR_GRID) uniform Grid { VoxelGrid grid; };
layout(set = 0, binding = BIND_CLEAR_ACCUM, r32f) uniform writeonly image3D accum;
VOXEL_LIST_BLOCK(BIND_CLEAR_LIST, readonly);
layout(set = 0, binding = BIND_CLEAR_DIRECT, rgba16f) uniform writeonly image3D direct;
layout(set = 0, binding = BIND_CLEAR_RADIANCE, rgba16f) uniform writeonly image3D radiance;

#include "lib/voxel_list.glsl"
#include "lib/voxel_list_dispatch.glsl"

void main() {
    uint i = list.header.counts.y + listInvocation();
    if (i >= list.header.counts.x) return;
    ivec3 v = unpackVoxel(list.entries[i]);
    int N = int(grid.dims.x);
    for (int c = 0; c < int(VOXEL_CHANNELS); ++c) imageStore(accum, v + ivec3(0, 0, c * N), vec4(0.0));
    imageStore(direct, v, vec4(0.0));
    imageStore(radiance, v, vec4(0.0));
}
