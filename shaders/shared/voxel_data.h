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

struct VoxelGrid {
    vec4 originSize;  // xyz world position of the grid's minimum corner, w voxel edge (m)
    uvec4 dims;       // x N (voxels per edge), y channels, z mip count of the directional volumes
};
DVSGI_CHECK_SIZE(VoxelGrid, 32);

// Occlusion of a light at voxels (GpuLight.shadow.z, or a global override).
DVSGI_CONST(uint, OCCLUSION_SHADOW_MAP, 0);
DVSGI_CONST(uint, OCCLUSION_RAYCAST_HARD, 1);
DVSGI_CONST(uint, OCCLUSION_RAYCAST_SOFT, 2);
DVSGI_CONST(uint, OCCLUSION_NONE, 3);
DVSGI_CONST(uint, OCCLUSION_PER_LIGHT, 4);  // no override

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

// Diffuse aperture sets (ConeParams.surface.w).
DVSGI_CONST(uint, CONE_SET_6, 6);    // the paper's six 60-degree cones
DVSGI_CONST(uint, CONE_SET_16, 16);  // sixteen cones over the hemisphere

// Bindings of lib/cone_trace.glsl, the same in every pass that traces cones.
DVSGI_CONST(uint, BIND_CONE_GRID, 0);
DVSGI_CONST(uint, BIND_CONE_RADIANCE, 1);     // sampled, trilinear
DVSGI_CONST(uint, BIND_CONE_DIRECTIONAL, 2);  // sampled, trilinear + mips (array of 6)

DVSGI_END

#endif
