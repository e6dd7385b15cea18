// Per-pixel voxel cone tracing (paper section VIII-X) and the final
// composition: shared by C++ and GLSL.
#ifndef DVSGI_SHARED_GATHER_DATA_H
#define DVSGI_SHARED_GATHER_DATA_H

#include "common.h"
#include "voxel_data.h"

DVSGI_BEGIN

DVSGI_CONST(uint, CONE_SET_6, 6);    // the paper's six 60-degree cones
DVSGI_CONST(uint, CONE_SET_16, 16);  // sixteen cones over the hemisphere

struct GatherPush {
    ConeParams cone;  // step factor, min step, max distance, first sample distance
    vec4 params;      // x unused, y AO lambda (per voxel of distance), z unused,
                      // w minimum specular half-angle tangent
    uvec4 flags;      // x unused, y specular on, z trace width, w trace height
};
DVSGI_CHECK_SIZE(GatherPush, 64);

DVSGI_CONST(uint, BIND_GATHER_FRAME, 3);
DVSGI_CONST(uint, BIND_GATHER_BASE, 4);
DVSGI_CONST(uint, BIND_GATHER_NORMAL, 5);
DVSGI_CONST(uint, BIND_GATHER_DEPTH, 6);
DVSGI_CONST(uint, BIND_GATHER_OUT_DIFFUSE, 7);   // rgb indirect diffuse radiance, a ambient occlusion
DVSGI_CONST(uint, BIND_GATHER_OUT_SPECULAR, 8);  // rgb specular radiance
DVSGI_CONST(uint, BIND_GATHER_RADIANCE, 9);      // radiance volume (sampled)

// Output terms (CompositePush.sizes.w).
DVSGI_CONST(uint, TERM_FULL, 0);
DVSGI_CONST(uint, TERM_DIRECT, 1);
DVSGI_CONST(uint, TERM_INDIRECT, 2);
DVSGI_CONST(uint, TERM_SPECULAR, 3);
DVSGI_CONST(uint, TERM_AO, 4);
DVSGI_CONST(uint, TERM_SHADOW, 5);

DVSGI_END

#endif
