// Voxel debug view (render/voxel_view.cpp, voxel_view.comp); shared by C++
// and GLSL.
#ifndef DVSGI_SHARED_VOXEL_VIEW_PASS_H
#define DVSGI_SHARED_VOXEL_VIEW_PASS_H

#include "common.h"

DVSGI_BEGIN

// Voxel debug view (VoxelViewPush.mode.x).
DVSGI_CONST(uint, VIEW_ALBEDO, 0);
DVSGI_CONST(uint, VIEW_NORMAL, 1);
DVSGI_CONST(uint, VIEW_EMISSION, 2);
DVSGI_CONST(uint, VIEW_RADIANCE, 3);
DVSGI_CONST(uint, VIEW_DIRECTIONAL, 4);
// Where a voxel's slot lies in the list: after the first counts.y entries
// (found this frame: progressive voxels new this frame, or dynamic voxels) or
// among them (kept: from earlier frames, or static).
DVSGI_CONST(uint, VIEW_AGE, 5);

struct VoxelViewPush {
    uvec4 mode;       // x VIEW_*, y mip level (directional), z output width, w output height
    uvec4 direction;  // x which directional volume (VIEW_DIRECTIONAL), order -X +X -Y +Y -Z +Z
};
DVSGI_CHECK_SIZE(VoxelViewPush, 32);

DVSGI_CONST(uint, BIND_VIEW_GRID, 0);
DVSGI_CONST(uint, BIND_VIEW_FRAME, 1);
DVSGI_CONST(uint, BIND_VIEW_ACCUM, 2);
DVSGI_CONST(uint, BIND_VIEW_RADIANCE, 3);
DVSGI_CONST(uint, BIND_VIEW_DIRECTIONAL, 4);  // the directional volumes' atlas at the chosen mip
DVSGI_CONST(uint, BIND_VIEW_OUT, 5);
DVSGI_CONST(uint, BIND_VIEW_INDEX, 6);
DVSGI_CONST(uint, BIND_VIEW_LIST, 7);  // the occupied-voxel list (VIEW_AGE reads its header)
// VIEW_RADIANCE of a two-sided voxel shows the side facing the camera: its side
// code (in the voxel direct light's alpha) and its sides' light (lib/voxel_sides.glsl).
DVSGI_CONST(uint, BIND_VIEW_DIRECT, 8);
DVSGI_CONST(uint, BIND_VIEW_SIDES, 9);

DVSGI_CONST(uint, VIEW_GROUP, 8);

DVSGI_END

#endif
