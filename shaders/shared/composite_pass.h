// Composition of the frame's terms at output size (render/composite.cpp,
// composite.comp); shared by C++ and GLSL.
#ifndef DVSGI_SHARED_COMPOSITE_PASS_H
#define DVSGI_SHARED_COMPOSITE_PASS_H

#include "common.h"

DVSGI_BEGIN

// Composition and resolve to the output size.
DVSGI_CONST(uint, BIND_COMP_DIRECT, 0);
DVSGI_CONST(uint, BIND_COMP_OUT, 1);
// Indirect diffuse irradiance / pi (not yet times the albedo) + AO, internal size.
DVSGI_CONST(uint, BIND_COMP_DIFFUSE, 2);
DVSGI_CONST(uint, BIND_COMP_SPECULAR, 3);
DVSGI_CONST(uint, BIND_COMP_SHADOW, 4);
DVSGI_CONST(uint, BIND_COMP_BASE, 5);      // G-buffer base colour + metallic: the diffuse albedo

// Output terms (CompositePush.sizes.w).
DVSGI_CONST(uint, TERM_FULL, 0);
DVSGI_CONST(uint, TERM_DIRECT, 1);
DVSGI_CONST(uint, TERM_INDIRECT, 2);
DVSGI_CONST(uint, TERM_SPECULAR, 3);
DVSGI_CONST(uint, TERM_AO, 4);
DVSGI_CONST(uint, TERM_SHADOW, 5);
DVSGI_CONST(uint, TERM_IRRADIANCE, 6);  // indirect diffuse before the albedo: E / pi (times AO when applied)

struct CompositePush {
    uvec4 sizes;  // x output width, y output height, z supersample factor, w output term (TERM_*)
    uvec4 flags;  // x 1 = multiply the indirect terms by AO, y 1 = indirect terms present
};
DVSGI_CHECK_SIZE(CompositePush, 32);

DVSGI_CONST(uint, COMPOSITE_GROUP, 8);

DVSGI_END

#endif
