#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"

// Bookkeeping of the occupied-voxel list (see shared/voxel_list_pass.h): a
// single invocation.
layout(local_size_x = VOXEL_LIST_GROUP) in;

layout(set = 0, binding = BIND_LIST_GRID) uniform Grid { VoxelGrid grid; };
VOXEL_LIST_BLOCK(BIND_LIST_BUFFER, coherent);
layout(push_constant) uniform Push { VoxelListPush pc; };

#include "lib/voxel_list_dispatch.glsl"

void main() {
    uint mode = pc.mode.x;
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
    list.header.allGroups.xyz = voxelListDispatch(count).xyz;  // w counts freed entries
    list.header.dynamicGroups = voxelListDispatch(count - statics);
}
