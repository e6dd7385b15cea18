// The copy kernel `dvsgi bench` measures the device's memory bandwidth with
// (bench/bandwidth_copy.cpp, bandwidth_copy.comp); shared by C++ and GLSL.
#ifndef DVSGI_SHARED_BANDWIDTH_COPY_PASS_H
#define DVSGI_SHARED_BANDWIDTH_COPY_PASS_H

#include "common.h"

DVSGI_BEGIN

DVSGI_CONST(uint, BIND_COPY_SRC, 0);  // uvec4[], read
DVSGI_CONST(uint, BIND_COPY_DST, 1);  // uvec4[], written

struct CopyPush {
    uvec4 sizes;  // x uvec4 elements to copy, yzw unused
};
DVSGI_CHECK_SIZE(CopyPush, 16);

DVSGI_CONST(uint, COPY_GROUP, 256);
// Workgroups per dispatch at most (maxComputeWorkGroupCount[0] is at least
// 65535); larger buffers loop over the grid.
DVSGI_CONST(uint, COPY_MAX_GROUPS, 65535);

DVSGI_END

#endif
