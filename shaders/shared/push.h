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
    uvec4 sizes;  // x output width, y output height, z supersample factor
};
DVSGI_CHECK_SIZE(CompositePush, 16);

DVSGI_END

#endif
