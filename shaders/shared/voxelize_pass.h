// Conservative voxelization and the dynamic-voxel clear (vxgi/voxelize.cpp,
// voxelize.*, clear_dynamic.comp); shared by C++ and GLSL.
#ifndef DVSGI_SHARED_VOXELIZE_PASS_H
#define DVSGI_SHARED_VOXELIZE_PASS_H

#include "common.h"

DVSGI_BEGIN

// Voxelization modes (VoxelizePush.mode.x).
DVSGI_CONST(uint, VOXELIZE_STATIC, 0);   // claims voxels as static
DVSGI_CONST(uint, VOXELIZE_DYNAMIC, 1);  // skips voxels flagged static

struct VoxelizePush {
    uvec4 ids;   // x draw index
    uvec4 mode;  // x VOXELIZE_STATIC/DYNAMIC, y 1 = dilate in the geometry shader,
                 // z float bits of the dilation margin beyond half a pixel (two sub-pixel steps,
                 //   so grown edges survive the rasterizer's vertex snapping)
};
DVSGI_CHECK_SIZE(VoxelizePush, 32);

// Voxelization pass bindings (set 1 = texture table, as for other geometry passes).
DVSGI_CONST(uint, BIND_VOX_GRID, 0);
DVSGI_CONST(uint, BIND_VOX_DRAWS, 1);
DVSGI_CONST(uint, BIND_VOX_MATERIALS, 2);
DVSGI_CONST(uint, BIND_VOX_ACCUM, 3);
DVSGI_CONST(uint, BIND_VOX_INDEX, 4);  // slot index volume (claimed)
DVSGI_CONST(uint, BIND_VOX_LIST, 5);  // occupied-voxel list (a claimed slot appends its voxel)
DVSGI_CONST(uint, BIND_VOX_EXTENTS, 6);  // per-slot extents (voxel_data.h), OR-ed into

// Clearing listed voxels (clear_listed.comp): over the list's dynamic entries,
// or over every entry (VOXEL_LIST_GROUP per workgroup).
DVSGI_CONST(uint, CLEAR_LISTED_DYNAMIC, 0);  // entries [counts.y, counts.x): last frame's dynamic voxels
DVSGI_CONST(uint, CLEAR_LISTED_ALL, 1);      // entries [0, counts.x): every occupied voxel

struct ClearListedPush {
    uvec4 scope;  // x CLEAR_LISTED_*
};
DVSGI_CHECK_SIZE(ClearListedPush, 16);

DVSGI_CONST(uint, BIND_CLEAR_GRID, 0);
DVSGI_CONST(uint, BIND_CLEAR_ACCUM, 1);
DVSGI_CONST(uint, BIND_CLEAR_LIST, 2);
DVSGI_CONST(uint, BIND_CLEAR_DIRECT, 3);
DVSGI_CONST(uint, BIND_CLEAR_RADIANCE, 4);
DVSGI_CONST(uint, BIND_CLEAR_INDEX, 5);
DVSGI_CONST(uint, BIND_CLEAR_EXTENTS, 6);

DVSGI_END

#endif
