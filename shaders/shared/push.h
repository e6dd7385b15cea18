// Push-constant blocks.
#ifndef DVSGI_SHARED_PUSH_H
#define DVSGI_SHARED_PUSH_H

#include "common.h"

DVSGI_BEGIN

struct DrawPush {
    uvec4 ids;  // x draw index, y shadow view index
};
DVSGI_CHECK_SIZE(DrawPush, 16);

struct CompositePush {
    uvec4 sizes;  // x output width, y output height, z supersample factor, w output term (TERM_*)
    uvec4 flags;  // x 1 = multiply the indirect terms by AO, y 1 = indirect terms present
};
DVSGI_CHECK_SIZE(CompositePush, 32);

struct UpsamplePush {
    uvec4 sizes;  // x low width, y low height, z full width, w full height
};
DVSGI_CHECK_SIZE(UpsamplePush, 16);

struct PresentPush {
    vec4 params;  // x output width, y output height, z 2^EV (exposure scale)
};
DVSGI_CHECK_SIZE(PresentPush, 16);

DVSGI_END

#endif
