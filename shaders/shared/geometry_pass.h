// G-buffer and shadow-map rasterization (render/gbuffer.cpp, render/shadows.cpp):
// their bindings and per-draw push constants; shared by C++ and GLSL.
#ifndef DVSGI_SHARED_GEOMETRY_PASS_H
#define DVSGI_SHARED_GEOMETRY_PASS_H

#include "common.h"

DVSGI_BEGIN

// Scene geometry passes (G-buffer, shadow maps).
DVSGI_CONST(uint, BIND_GEOM_FRAME, 0);
DVSGI_CONST(uint, BIND_GEOM_DRAWS, 1);
DVSGI_CONST(uint, BIND_GEOM_MATERIALS, 2);
DVSGI_CONST(uint, BIND_GEOM_SHADOW_VIEWS, 3);
DVSGI_CONST(uint, SET_TEXTURES, 1);
DVSGI_CONST(uint, BIND_TEXTURES, 0);
DVSGI_CONST(uint, BIND_TEXTURE_SAMPLER, 1);

struct DrawPush {
    uvec4 ids;  // x draw index, y shadow view index
};
DVSGI_CHECK_SIZE(DrawPush, 16);

DVSGI_END

#endif
