// Depth-aware upsampling of the cone-traced terms (render/gather.cpp,
// upsample.comp); shared by C++ and GLSL.
#ifndef DVSGI_SHARED_UPSAMPLE_PASS_H
#define DVSGI_SHARED_UPSAMPLE_PASS_H

#include "common.h"

DVSGI_BEGIN

// Depth-aware upsampling of the traced terms.
DVSGI_CONST(uint, BIND_UP_FRAME, 0);
DVSGI_CONST(uint, BIND_UP_NORMAL, 1);
DVSGI_CONST(uint, BIND_UP_DEPTH, 2);
DVSGI_CONST(uint, BIND_UP_LOW_DIFFUSE, 3);
DVSGI_CONST(uint, BIND_UP_LOW_SPECULAR, 4);
DVSGI_CONST(uint, BIND_UP_OUT_DIFFUSE, 5);
DVSGI_CONST(uint, BIND_UP_OUT_SPECULAR, 6);

struct UpsamplePush {
    uvec4 sizes;  // x low width, y low height, z full width, w full height
};
DVSGI_CHECK_SIZE(UpsamplePush, 16);

DVSGI_CONST(uint, UPSAMPLE_GROUP, 8);

DVSGI_END

#endif
