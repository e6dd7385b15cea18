// dvsgi view: the renderer's output tone-mapped for the window
// (app/view_swapchain.cpp, view_present.comp); shared by C++ and GLSL.
#ifndef DVSGI_SHARED_PRESENT_PASS_H
#define DVSGI_SHARED_PRESENT_PASS_H

#include "common.h"

DVSGI_BEGIN

// dvsgi view: the renderer's output tone-mapped into the image blitted to the window.
DVSGI_CONST(uint, BIND_PRESENT_RADIANCE, 0);
DVSGI_CONST(uint, BIND_PRESENT_DISPLAY, 1);

struct PresentPush {
    vec4 params;  // x output width, y output height, z 2^EV (exposure scale)
};
DVSGI_CHECK_SIZE(PresentPush, 16);

DVSGI_CONST(uint, PRESENT_GROUP, 8);

DVSGI_END

#endif
