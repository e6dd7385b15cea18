// Deferred direct lighting (render/lighting.cpp, lighting.comp): bindings,
// push constants and workgroup size; shared by C++ and GLSL.
#ifndef DVSGI_SHARED_LIGHTING_PASS_H
#define DVSGI_SHARED_LIGHTING_PASS_H

#include "common.h"
#include "voxel_data.h"

DVSGI_BEGIN

// Deferred direct lighting.
DVSGI_CONST(uint, BIND_LIGHT_FRAME, 0);
DVSGI_CONST(uint, BIND_LIGHT_GBUF_BASE, 1);
DVSGI_CONST(uint, BIND_LIGHT_GBUF_NORMAL, 2);
DVSGI_CONST(uint, BIND_LIGHT_GBUF_EMISSION, 3);
DVSGI_CONST(uint, BIND_LIGHT_DEPTH, 4);
DVSGI_CONST(uint, BIND_LIGHT_LIGHTS, 5);
DVSGI_CONST(uint, BIND_LIGHT_SHADOW_VIEWS, 6);
DVSGI_CONST(uint, BIND_LIGHT_SHADOW_MAP, 7);
DVSGI_CONST(uint, BIND_LIGHT_OUT_DIRECT, 8);
DVSGI_CONST(uint, BIND_LIGHT_VOXEL_GRID, 9);         // shadow cones trace the voxel volumes
DVSGI_CONST(uint, BIND_LIGHT_VOXEL_RADIANCE, 10);
DVSGI_CONST(uint, BIND_LIGHT_VOXEL_DIRECTIONAL, 11);  // the six volumes' atlas
DVSGI_CONST(uint, BIND_LIGHT_OUT_SHADOW, 12);         // mean light visibility
// The AREA_RAYS variant's rays (lib/voxel_rays.glsl), as the gather's rays bind them.
DVSGI_CONST(uint, BIND_LIGHT_RAY_SIDES, 13);
DVSGI_CONST(uint, BIND_LIGHT_RAY_INDEX, 14);
DVSGI_CONST(uint, BIND_LIGHT_RAY_NORMALS, 15);
DVSGI_CONST(uint, BIND_LIGHT_RAY_OCCUPANCY, 16);
DVSGI_CONST(uint, BIND_LIGHT_RAY_EXTENTS, 17);
DVSGI_CONST(uint, BIND_LIGHT_SHADOW_GRADIENT, 18);  // the map's casters' depth gradients (shadow.frag)

// Shadow cones and area-light visibility march like the gather's cones.
struct LightingPush {
    ConeParams cone;  // the shared cone settings (vxgi::gpuCone); trace.z = the longest cone (m)
    vec4 shadow;      // x 1 = shadow cones instead of maps, y tan(half aperture), z area rays' offset (voxels)
};
DVSGI_CHECK_SIZE(LightingPush, 48);

DVSGI_CONST(uint, LIGHTING_GROUP, 8);  // 8 x 8 pixels per workgroup

DVSGI_END

#endif
