// A clipmap level's scroll (vxgi/clipmap.h, clipmap_scroll.comp): frees the
// static voxels whose storage cell now stands for a voxel of the newly
// exposed slabs. Shared by C++ and GLSL.
#ifndef DVSGI_SHARED_CLIPMAP_PASS_H
#define DVSGI_SHARED_CLIPMAP_PASS_H

#include "common.h"

DVSGI_BEGIN

struct ClipScrollPush {
    ivec4 oldMin;  // xyz the window's minimum corner before the scroll, in whole voxels of the level; w N
    ivec4 newMin;  // and after it
};
DVSGI_CHECK_SIZE(ClipScrollPush, 32);

DVSGI_CONST(uint, BIND_SCROLL_ACCUM, 0);   // per-slot attributes (zeroed for freed slots)
DVSGI_CONST(uint, BIND_SCROLL_DIRECT, 1);  // per-slot direct light (zeroed)
DVSGI_CONST(uint, BIND_SCROLL_INDEX, 2);   // the slot index (freed voxels set to 0)
DVSGI_CONST(uint, BIND_SCROLL_LIST, 3);    // the list (freed entries set to VOXEL_LIST_FREE)
DVSGI_CONST(uint, BIND_SCROLL_EXTENTS, 4);  // per-slot extents (zeroed)

DVSGI_END

#endif
