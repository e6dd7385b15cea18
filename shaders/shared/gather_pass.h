// Per-pixel voxel cone tracing (paper sections VIII-X; render/gather.cpp,
// gather.comp): bindings beside lib/cone_trace.glsl's, push constants,
// workgroup size; shared by C++ and GLSL.
#ifndef DVSGI_SHARED_GATHER_PASS_H
#define DVSGI_SHARED_GATHER_PASS_H

#include "common.h"
#include "voxel_data.h"

DVSGI_BEGIN

struct GatherPush {
    ConeParams cone;  // step factor, min step, max distance, first sample distance
    vec4 params;      // x unused, y AO lambda (per voxel of distance), z unused,
                      // w minimum specular half-angle tangent
    uvec4 flags;      // x 1: turn the six cones per pixel (coneSpinTurn, resolved by cone_resolve.comp),
                      // 2 + k: every pixel by k steps (tests), 0: not at all;
                      // y specular on, z trace width, w trace height
    // The gather by rays (DVSGI_RAYS): x rays per pixel, y their origin's
    // offset along the normal (voxels, float bits), z 1: a one-sided voxel met
    // from behind shows a ray no light (--voxel-backs-dark), w unused.
    uvec4 rays;
};
DVSGI_CHECK_SIZE(GatherPush, 80);

DVSGI_CONST(uint, BIND_GATHER_FRAME, 3);
DVSGI_CONST(uint, BIND_GATHER_BASE, 4);
DVSGI_CONST(uint, BIND_GATHER_NORMAL, 5);
DVSGI_CONST(uint, BIND_GATHER_DEPTH, 6);
DVSGI_CONST(uint, BIND_GATHER_OUT_DIFFUSE, 7);   // rgb indirect diffuse radiance, a ambient occlusion
DVSGI_CONST(uint, BIND_GATHER_OUT_SPECULAR, 8);  // rgb specular radiance
DVSGI_CONST(uint, BIND_GATHER_RADIANCE, 9);      // radiance volume (sampled)

// The gather by rays (DVSGI_RAYS) reads what the voxel bounce's rays read
// (shared/bounce_pass.h): the side light, the slot index, the packed normals
// and the occupancy bits (vxgi::RayData).
DVSGI_CONST(uint, BIND_GATHER_RAY_SIDES, 10);
DVSGI_CONST(uint, BIND_GATHER_RAY_INDEX, 11);
DVSGI_CONST(uint, BIND_GATHER_RAY_NORMALS, 12);
DVSGI_CONST(uint, BIND_GATHER_RAY_OCCUPANCY, 13);
DVSGI_CONST(uint, BIND_GATHER_RAY_EXTENTS, 14);

DVSGI_CONST(uint, GATHER_GROUP, 8);

DVSGI_END

#endif
