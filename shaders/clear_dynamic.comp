#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/voxel_data.h"
#include "shared/voxelize_pass.h"

// Zeroes every voxel that static geometry did not write, so dynamic geometry
// can be voxelized afresh without touching static voxels.
layout(local_size_x = CLEAR_GROUP, local_size_y = CLEAR_GROUP, local_size_z = CLEAR_GROUP) in;

layout(set = 0, binding = BIND_CLEAR_GRID) uniform Grid { VoxelGrid grid; };
layout(set = 0, binding = BIND_CLEAR_ACCUM, r32f) uniform writeonly image3D accum;
layout(set = 0, binding = BIND_CLEAR_FLAGS, r8ui) uniform readonly uimage3D flags;

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    int N = int(grid.dims.x);
    if (any(greaterThanEqual(v, ivec3(N)))) return;
    if (imageLoad(flags, v).r == VOXEL_FLAG_STATIC) return;
    for (int c = 0; c < int(VOXEL_CHANNELS); ++c) imageStore(accum, v + ivec3(0, 0, c * N), vec4(0.0));
}
