// Anisotropic filtering (vxgi/aniso_filter.cpp, aniso_filter.comp); shared
// by C++ and GLSL.
#ifndef DVSGI_SHARED_ANISO_FILTER_PASS_H
#define DVSGI_SHARED_ANISO_FILTER_PASS_H

#include "common.h"

DVSGI_BEGIN

// Anisotropic filtering: radiance (N^3) -> the six directional volumes ((N/2)^3
// + mips each, side by side in one image: voxel_data.h, directionalTexel).
DVSGI_CONST(uint, BIND_ANISO_SOURCE, 0);      // base: radiance; upper levels: unused
DVSGI_CONST(uint, BIND_ANISO_SOURCE_DIRS, 1); // upper levels: the volumes' level l - 1
DVSGI_CONST(uint, BIND_ANISO_TARGET_DIRS, 2); // the volumes' level written
// The base level and the two-sided pass run over the occupied-voxel list:
DVSGI_CONST(uint, BIND_ANISO_GRID, 3);    // VoxelGrid (the list's and the index's toroidal addressing)
DVSGI_CONST(uint, BIND_ANISO_LIST, 7);    // occupied-voxel list: one invocation per entry
DVSGI_CONST(uint, BIND_ANISO_INDEX, 4);   // slot index
// The two-sided pass (aniso_filter.comp with DVSGI_TWO_SIDED) only: which voxels
// are two-sided and their light per side.
DVSGI_CONST(uint, BIND_ANISO_DIRECT, 5);  // per-slot direct light: a = 1 + side code
DVSGI_CONST(uint, BIND_ANISO_SIDES, 6);   // per-slot side light (lib/voxel_sides.glsl)
// Both passes over level 0: the voxels' attributes, for their mean normals.
DVSGI_CONST(uint, BIND_ANISO_ACCUM, 8);

struct AnisoPush {
    uvec4 sizes;  // x target size (voxels per edge); y (passes over level 0) 1: a voxel seen from behind
                  // shows no light (seenFront); zw unused
};
DVSGI_CHECK_SIZE(AnisoPush, 16);

DVSGI_CONST(uint, ANISO_GROUP, 4);  // 4^3 target voxels per workgroup

DVSGI_END

#endif
