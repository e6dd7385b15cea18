#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"

// Bookkeeping of the occupied-voxel list (see shared/voxel_list_pass.h). The
// FINISH and DROP modes run as a single invocation; SCAN runs over N^3.
layout(local_size_x = VOXEL_LIST_GROUP) in;

layout(set = 0, binding = BIND_LIST_GRID) uniform Grid { VoxelGrid grid; };
VOXEL_LIST_BLOCK(BIND_LIST_BUFFER, coherent);
layout(set = 0, binding = BIND_LIST_ACCUM, r32f) uniform readonly image3D accum;
layout(push_constant) uniform Push { VoxelListPush pc; };

#include "lib/voxel_list.glsl"
#include "lib/voxel_list_append.glsl"
#include "lib/voxel_list_dispatch.glsl"
#include "lib/voxel_attributes.glsl"

uvec4 dispatchOver(uint entries) {
    uint groups = (entries + VOXEL_LIST_GROUP - 1u) / VOXEL_LIST_GROUP;
    uint x = min(groups, VOXEL_LIST_ROW);
    return uvec4(x, x == 0u ? 0u : (groups + x - 1u) / x, 1u, 0u);
}

void main() {
    uint mode = pc.mode.x;
    if (mode == LIST_SCAN) {
        uint N = grid.dims.x;
        uint i = listInvocation();
        if (i >= N * N * N) return;
        ivec3 v = ivec3(i % N, (i / N) % N, i / (N * N));
        if (voxelCount(v) > 0.0) appendVoxel(v);
        return;
    }
    if (listInvocation() != 0u) return;
    if (mode == LIST_DROP_DYNAMIC) {
        list.header.counts.x = list.header.counts.y;
        list.header.dynamicGroups = uvec4(0u, 0u, 1u, 0u);
        return;
    }
    uint count = min(list.header.counts.x, list.header.counts.z);
    list.header.counts.x = count;
    if (mode == LIST_FINISH_STATIC) list.header.counts.y = count;
    uint statics = min(list.header.counts.y, count);
    list.header.allGroups = dispatchOver(count);
    list.header.dynamicGroups = dispatchOver(count - statics);
}
