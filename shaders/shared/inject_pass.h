// Voxel direct light (vxgi/inject.cpp, inject.comp): bindings, push
// constants (the workgroup is VOXEL_LIST_GROUP entries of the list); shared by C++ and GLSL.
#ifndef DVSGI_SHARED_INJECT_PASS_H
#define DVSGI_SHARED_INJECT_PASS_H

#include "common.h"
#include "voxel_data.h"

DVSGI_BEGIN

struct VoxelLightPush {
    uvec4 flags;   // x light count, y 1 = normal-weighted attenuation (eq. 5), 0 = Lambert N.L (eq. 2),
                   // z occlusion override (OCCLUSION_*), w shadows rendered (1/0)
    vec4 params;   // x soft-shadow kappa, y shadow-map normal offset (texels), z 1 = add emission to the
                   // radiance (0 when emitters are area lights), w 1 = keep the side light's reflected part
                   // (a feedback frame's bounce blends with it)
    uvec4 keep;    // x 1 = leave the static voxels' radiance as the last bounce wrote it (a feedback
                   // frame's rays read the light of the frame before, as its cones read the filtered
                   // volumes); y 1 = --edge-voxels faces (with Lambert, flags.y = 0): edge voxels lit
                   // per axis face, their faces' light kept in BIND_INJECT_SIDES; zw unused
};
DVSGI_CHECK_SIZE(VoxelLightPush, 48);

DVSGI_CONST(uint, BIND_INJECT_GRID, 0);
DVSGI_CONST(uint, BIND_INJECT_ACCUM, 1);
DVSGI_CONST(uint, BIND_INJECT_LIGHTS, 2);
DVSGI_CONST(uint, BIND_INJECT_SHADOW_VIEWS, 3);
DVSGI_CONST(uint, BIND_INJECT_SHADOW_MAP, 4);
DVSGI_CONST(uint, BIND_INJECT_DIRECT, 5);  // per-slot direct light + emission (kept for the bounces)
DVSGI_CONST(uint, BIND_INJECT_LIST, 6);  // occupied-voxel list: one invocation per entry (= slot)
DVSGI_CONST(uint, BIND_INJECT_INDEX, 7);  // slot index volume: occupancy for voxel shadow rays
DVSGI_CONST(uint, BIND_INJECT_OUT_RADIANCE, 8);  // radiance volume (N^3): direct light + emission, a = 1 (1 - side code * TWO_SIDED_OPACITY_STEP: two-sided)
DVSGI_CONST(uint, BIND_INJECT_SIDES, 9);  // per-slot side light of two-sided voxels (lib/voxel_sides.glsl)
DVSGI_CONST(uint, BIND_INJECT_RAY_OCCUPANCY, 10);  // RAY_OCCUPANCY: the rays' occupancy bits (lib/voxel_occupancy.glsl)
DVSGI_CONST(uint, BIND_INJECT_SHADOW_GRADIENT, 11);  // the map's casters' depth gradients (shadow.frag)
DVSGI_CONST(uint, BIND_INJECT_EXTENTS, 12);  // per-slot extents (voxel_data.h): where shadows are looked up

DVSGI_END

#endif
