// Shadow maps (render/shadows.cpp, shadow.frag, lib/shadow_map.glsl): what the
// maps hold besides depth, and their bias; shared by C++ and GLSL.
#ifndef DVSGI_SHARED_SHADOW_PASS_H
#define DVSGI_SHARED_SHADOW_PASS_H

#include "common.h"

DVSGI_BEGIN

// Beside each texel's depth, its caster's depth gradient (depth per texel along
// the map's x and y; RG16F). The lookup compares a receiver with the caster's
// plane extended to the receiver's own place in the map instead of with the
// texel's depth plus a slope-scaled bias: a surface does not shadow itself
// however steeply the light grazes it, and a grazed caster meeting its
// receiver in a corner does not let light through the corner
// (docs/quality.md, "Shadow maps: the caster's plane").
DVSGI_CONST(float, SHADOW_GRADIENT_MAX, 60000.0);  // below RG16F's largest, 65504
// How far, in texels along the light, a receiver must lie behind a caster's
// plane and the caster in front of the receiver's, for the caster to shadow it:
// surfaces that meet or touch are on each other's planes, where rounding alone
// would decide.
DVSGI_CONST(float, SHADOW_PLANE_MARGIN, 0.05);
// Constant depth bias the maps are drawn with, in units of the depth format's
// resolution (no slope-scaled bias: the caster's plane takes its place).
DVSGI_CONST(float, SHADOW_CONSTANT_BIAS, 1.0);

DVSGI_END

#endif
