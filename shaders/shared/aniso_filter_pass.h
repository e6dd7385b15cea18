// Anisotropic filtering (vxgi/aniso_filter.cpp, aniso_filter.comp); shared
// by C++ and GLSL.
#ifndef DVSGI_SHARED_ANISO_FILTER_PASS_H
#define DVSGI_SHARED_ANISO_FILTER_PASS_H

#include "common.h"

DVSGI_BEGIN

// Anisotropic filtering: radiance (N^3) -> six directional volumes ((N/2)^3 + mips).
// Directions, in volume order: -X +X -Y +Y -Z +Z (the direction light travels).
DVSGI_CONST(uint, BIND_ANISO_SOURCE, 0);      // base: radiance; upper levels: unused
DVSGI_CONST(uint, BIND_ANISO_SOURCE_DIRS, 1); // upper levels: six volumes at level l (array of 6)
DVSGI_CONST(uint, BIND_ANISO_TARGET_DIRS, 2); // six volumes at the level written (array of 6)

struct AnisoPush {
    uvec4 sizes;  // x target size (voxels per edge), y 1 = base level (read radiance)
};
DVSGI_CHECK_SIZE(AnisoPush, 16);

DVSGI_CONST(uint, ANISO_GROUP, 4);  // 4^3 target voxels per workgroup

DVSGI_END

#endif
