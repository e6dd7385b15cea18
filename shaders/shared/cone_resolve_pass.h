// The six-cone set's interleaving resolved, and the gather's rays filtered
// (render/gather.cpp, cone_resolve.comp): bindings, push constants, workgroup
// size, the turns; shared by C++ and GLSL.
#ifndef DVSGI_SHARED_CONE_RESOLVE_PASS_H
#define DVSGI_SHARED_CONE_RESOLVE_PASS_H

#include "common.h"

DVSGI_BEGIN

// gather.comp turns the six cones about the normal by (x & 1) + 2 (y & 1)
// steps of 72 / CONE_SPIN_STEPS degrees at trace pixel (x, y) (the five side
// cones repeat every 72 degrees); every 2x2 block holds each turn once.
DVSGI_CONST(uint, CONE_SPIN_STEPS, 4);
// Turn `step` as a fraction of a full turn.
DVSGI_FUNCTION float coneTurn(uint step) { return float(step) / (5.0f * float(CONE_SPIN_STEPS)); }
DVSGI_FUNCTION float coneSpinTurn(int x, int y) { return coneTurn(uint((x & 1) + 2 * (y & 1))); }

DVSGI_CONST(uint, BIND_RESOLVE_FRAME, 0);
DVSGI_CONST(uint, BIND_RESOLVE_NORMAL, 1);
DVSGI_CONST(uint, BIND_RESOLVE_DEPTH, 2);
DVSGI_CONST(uint, BIND_RESOLVE_TRACED, 3);  // the gather's diffuse term, turned per pixel (RGBA16F)
DVSGI_CONST(uint, BIND_RESOLVE_OUT, 4);     // the same resolved (RGBA16F)

struct ConeResolvePush {
    uvec4 sizes;  // x trace width, y trace height, z G-buffer width, w G-buffer height
    // x: trace pixels between the tent's taps (pass k of the rays' filter:
    // 2^k); y: the voxel edge (float bits, world units) for
    // RESOLVE_REACH_VOXELS, 0 for the turned cones (no falloff)
    uvec4 step;
};
DVSGI_CHECK_SIZE(ConeResolvePush, 32);

DVSGI_CONST(uint, RESOLVE_GROUP, 8);
// A neighbour's weight falls as 1 / (1 + (d / (RESOLVE_REACH_VOXELS voxels))^2)
// with its world distance d: the gather's light varies over a few voxels, and
// on a floor seen at a grazing angle the widest taps reach metres away.
DVSGI_CONST(float, RESOLVE_REACH_VOXELS, 4.0f);

DVSGI_END

#endif
