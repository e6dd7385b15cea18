// The voxel grid and its volumes, shared by C++ and GLSL.
//
// Voxel attributes are accumulated, not averaged in place: one R32_SFLOAT 3D
// image holds VOXEL_CHANNELS slabs of N^3 floats stacked along z (slab c spans
// z in [c*N, (c+1)*N)). Fragments add into them with float atomics, so nothing
// saturates, nothing is dropped, and HDR emission survives. Readers divide by
// the fragment count (channel CH_COUNT) to get averages.
#ifndef DVSGI_SHARED_VOXEL_DATA_H
#define DVSGI_SHARED_VOXEL_DATA_H

#include "common.h"

DVSGI_BEGIN

DVSGI_CONST(uint, CH_ALBEDO_R, 0);
DVSGI_CONST(uint, CH_ALBEDO_G, 1);
DVSGI_CONST(uint, CH_ALBEDO_B, 2);
DVSGI_CONST(uint, CH_COUNT, 3);       // fragments that landed in the voxel
DVSGI_CONST(uint, CH_EMISSION_R, 4);  // W m^-2 sr^-1, summed
DVSGI_CONST(uint, CH_EMISSION_G, 5);
DVSGI_CONST(uint, CH_EMISSION_B, 6);
// Normal weights per axis and sign: sum of n_a^2 over fragments whose normal
// has n_a > 0 (POS) or n_a < 0 (NEG). A voxel holding a thin wall's two
// opposite faces keeps both orientations instead of averaging them to zero.
DVSGI_CONST(uint, CH_NORMAL_POS_X, 7);
DVSGI_CONST(uint, CH_NORMAL_NEG_X, 8);
DVSGI_CONST(uint, CH_NORMAL_POS_Y, 9);
DVSGI_CONST(uint, CH_NORMAL_NEG_Y, 10);
DVSGI_CONST(uint, CH_NORMAL_POS_Z, 11);
DVSGI_CONST(uint, CH_NORMAL_NEG_Z, 12);
DVSGI_CONST(uint, VOXEL_CHANNELS, 13);

DVSGI_CONST(uint, VOXEL_FLAG_STATIC, 1);

// Voxelization modes (VoxelizePush.mode.x).
DVSGI_CONST(uint, VOXELIZE_STATIC, 0);   // writes and flags voxels
DVSGI_CONST(uint, VOXELIZE_DYNAMIC, 1);  // skips voxels flagged static

struct VoxelGrid {
    vec4 originSize;  // xyz world position of the grid's minimum corner, w voxel edge (m)
    uvec4 dims;       // x N (voxels per edge), y channels, z mip count of the directional volumes
};
DVSGI_CHECK_SIZE(VoxelGrid, 32);

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
DVSGI_CONST(uint, BIND_VOX_FLAGS, 4);

// Dynamic-voxel clear.
DVSGI_CONST(uint, BIND_CLEAR_GRID, 0);
DVSGI_CONST(uint, BIND_CLEAR_ACCUM, 1);
DVSGI_CONST(uint, BIND_CLEAR_FLAGS, 2);

// Occlusion of a light at voxels (GpuLight.shadow.z, or a global override).
DVSGI_CONST(uint, OCCLUSION_SHADOW_MAP, 0);
DVSGI_CONST(uint, OCCLUSION_RAYCAST_HARD, 1);
DVSGI_CONST(uint, OCCLUSION_RAYCAST_SOFT, 2);
DVSGI_CONST(uint, OCCLUSION_NONE, 3);
DVSGI_CONST(uint, OCCLUSION_PER_LIGHT, 4);  // no override

struct VoxelLightPush {
    uvec4 flags;   // x light count, y 1 = normal-weighted attenuation (eq. 5), 0 = Lambert N.L (eq. 2),
                   // z occlusion override (OCCLUSION_*), w shadows rendered (1/0)
    vec4 params;   // x soft-shadow kappa, y shadow-map normal offset (texels), z 1 = add emission to the
                   // radiance (0 when emitters are area lights)
};
DVSGI_CHECK_SIZE(VoxelLightPush, 32);

DVSGI_CONST(uint, BIND_INJECT_GRID, 0);
DVSGI_CONST(uint, BIND_INJECT_ACCUM, 1);
DVSGI_CONST(uint, BIND_INJECT_LIGHTS, 2);
DVSGI_CONST(uint, BIND_INJECT_SHADOW_VIEWS, 3);
DVSGI_CONST(uint, BIND_INJECT_SHADOW_MAP, 4);
DVSGI_CONST(uint, BIND_INJECT_RADIANCE, 5);

// Anisotropic filtering: radiance (N^3) -> six directional volumes ((N/2)^3 + mips).
// Directions, in volume order: -X +X -Y +Y -Z +Z (the direction light travels).
DVSGI_CONST(uint, BIND_ANISO_SOURCE, 0);      // base: radiance; upper levels: unused
DVSGI_CONST(uint, BIND_ANISO_SOURCE_DIRS, 1); // upper levels: six volumes at level l (array of 6)
DVSGI_CONST(uint, BIND_ANISO_TARGET_DIRS, 2); // six volumes at the level written (array of 6)

struct AnisoPush {
    uvec4 sizes;  // x target size (voxels per edge), y 1 = base level (read radiance)
};
DVSGI_CHECK_SIZE(AnisoPush, 16);

// Cone tracing through the filtered volumes (shared by the voxel bounce and
// the per-pixel gather).
struct ConeParams {
    vec4 trace;    // x step factor beta, y minimum step (voxels), z maximum distance (m), w first sample (voxels)
    vec4 surface;  // x clearance K (0 = off), y surface thickness (voxels): see traceConeAO,
                   // z origin offset along the normal (voxels), w aperture set (CONE_SET_*)
};
DVSGI_CHECK_SIZE(ConeParams, 32);

// Default cone clearance K and the thickness of a voxelized surface.
DVSGI_CONST(float, CONE_CLEARANCE_DEFAULT, 3.0);
DVSGI_CONST(float, CONE_SURFACE_VOXELS, 1.0);

struct BouncePush {
    ConeParams cone;
    uvec4 flags;  // x 1 = write the per-workgroup change statistics (BIND_BOUNCE_STATS)
};
DVSGI_CHECK_SIZE(BouncePush, 48);

// The bounce's workgroup edge, and what each workgroup writes when asked:
// the sum over its occupied voxels of |luminance change| and of the new
// luminance (two floats), so the host can tell when bounces have converged.
DVSGI_CONST(uint, BOUNCE_GROUP, 4);
DVSGI_CONST(uint, BOUNCE_STATS_FLOATS, 2);

DVSGI_CONST(uint, BIND_CONE_GRID, 0);
DVSGI_CONST(uint, BIND_CONE_RADIANCE, 1);     // sampled, trilinear
DVSGI_CONST(uint, BIND_CONE_DIRECTIONAL, 2);  // sampled, trilinear + mips (array of 6)
DVSGI_CONST(uint, BIND_BOUNCE_ACCUM, 3);
DVSGI_CONST(uint, BIND_BOUNCE_DIRECT, 4);     // direct light + emission (storage, read)
DVSGI_CONST(uint, BIND_BOUNCE_OUT, 5);        // radiance (storage, read for the change, then written)
DVSGI_CONST(uint, BIND_BOUNCE_STATS, 6);      // float[BOUNCE_STATS_FLOATS] per workgroup

// Voxel debug view (VoxelViewPush.mode.x).
DVSGI_CONST(uint, VIEW_ALBEDO, 0);
DVSGI_CONST(uint, VIEW_NORMAL, 1);
DVSGI_CONST(uint, VIEW_EMISSION, 2);
DVSGI_CONST(uint, VIEW_RADIANCE, 3);
DVSGI_CONST(uint, VIEW_DIRECTIONAL, 4);

struct VoxelViewPush {
    uvec4 mode;  // x VIEW_*, y mip level (directional), z output width, w output height
};
DVSGI_CHECK_SIZE(VoxelViewPush, 16);

DVSGI_CONST(uint, BIND_VIEW_GRID, 0);
DVSGI_CONST(uint, BIND_VIEW_FRAME, 1);
DVSGI_CONST(uint, BIND_VIEW_ACCUM, 2);
DVSGI_CONST(uint, BIND_VIEW_RADIANCE, 3);
DVSGI_CONST(uint, BIND_VIEW_DIRECTIONAL, 4);  // the chosen direction, the chosen mip
DVSGI_CONST(uint, BIND_VIEW_OUT, 5);

DVSGI_END

#endif
