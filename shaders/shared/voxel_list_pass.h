// The occupied-voxel list (vxgi/voxel_list.cpp, voxel_list.comp): one packed
// coordinate per occupied voxel, static voxels first, then the dynamic ones
// of the current frame. Entry i is also slot i of the per-slot storage
// (shared/voxel_data.h). The voxelizers claim a slot when a voxel's first
// fragment lands; the per-voxel passes (direct light, bounce, dynamic clear)
// run over the list with indirect dispatches instead of over the N^3 grid.
// Shared by C++ and GLSL.
#ifndef DVSGI_SHARED_VOXEL_LIST_PASS_H
#define DVSGI_SHARED_VOXEL_LIST_PASS_H

#include "common.h"

DVSGI_BEGIN

// The list buffer starts with this header; entries (uint, x | y << 10 | z << 20) follow.
struct VoxelListHeader {
    uvec4 counts;         // x entries appended, y of them static (the first y), z capacity (slots), w claims dropped
    uvec4 allGroups;      // vkCmdDispatchIndirect arguments (xyz) over every entry; w static entries freed by scrolls
    uvec4 dynamicGroups;  // over the dynamic entries [y, x)
};
DVSGI_CHECK_SIZE(VoxelListHeader, 48);

// Invocations per workgroup of every pass that runs over the list. Indirect
// dispatches are (min(groups, VOXEL_LIST_ROW), rows, 1), since one dimension
// may hold only 65535 groups; the flat group index is y * ROW + x.
DVSGI_CONST(uint, VOXEL_LIST_GROUP, 64);
DVSGI_CONST(uint, VOXEL_LIST_ROW, 4096);
DVSGI_CONST(uint, VOXEL_LIST_COORD_BITS, 10);  // N <= 1024

// A list entry: the voxel's coordinates packed into one word.
DVSGI_FUNCTION uint packVoxel(ivec3 v) {
    return uint(v.x) | (uint(v.y) << VOXEL_LIST_COORD_BITS) | (uint(v.z) << (2u * VOXEL_LIST_COORD_BITS));
}

DVSGI_FUNCTION ivec3 unpackVoxel(uint e) {
    uint mask = (1u << VOXEL_LIST_COORD_BITS) - 1u;
    return ivec3(int(e & mask), int((e >> VOXEL_LIST_COORD_BITS) & mask), int(e >> (2u * VOXEL_LIST_COORD_BITS)));
}

// A static entry a clipmap scroll freed (vxgi/clipmap.h): passes over the
// list skip it; its slot stays unused until the level is voxelized afresh.
DVSGI_CONST(uint, VOXEL_LIST_FREE, 0xFFFFFFFFu);

// The indirect dispatch arguments (x, y, z) over `entries` list entries, for
// voxel_list.comp and for lists the host uploads.
DVSGI_FUNCTION uvec4 voxelListDispatch(uint entries) {
    uint groups = (entries + VOXEL_LIST_GROUP - 1u) / VOXEL_LIST_GROUP;
    uint x = groups < VOXEL_LIST_ROW ? groups : VOXEL_LIST_ROW;
    return uvec4(x, x == 0u ? 0u : (groups + x - 1u) / x, 1u, 0u);
}

// voxel_list.comp modes (VoxelListPush.mode.x).
DVSGI_CONST(uint, LIST_FINISH, 0);         // clamp the count, write both dispatch arguments
DVSGI_CONST(uint, LIST_FINISH_STATIC, 1);  // as FINISH, after static voxelization: all entries are static
DVSGI_CONST(uint, LIST_DROP_DYNAMIC, 2);   // count = static count (after the dynamic voxels were cleared)

struct VoxelListPush {
    uvec4 mode;  // x LIST_*
};
DVSGI_CHECK_SIZE(VoxelListPush, 16);

DVSGI_CONST(uint, BIND_LIST_GRID, 0);
DVSGI_CONST(uint, BIND_LIST_BUFFER, 1);

DVSGI_END

#ifndef __cplusplus
// The list as the GLSL buffer block `list` at binding B of set 0; Q is its
// access qualifier (readonly, coherent, or nothing). One declaration for
// every pass that reads or appends.
#define VOXEL_LIST_BLOCK(B, Q) \
    layout(set = 0, binding = B, std430) Q buffer List { VoxelListHeader header; uint entries[]; } list
#endif

#endif
