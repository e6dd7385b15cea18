// Temporal accumulation of the per-pixel indirect diffuse term
// (render/temporal_indirect.cpp, temporal_indirect.comp); shared by C++ and GLSL.
#ifndef DVSGI_SHARED_TEMPORAL_INDIRECT_PASS_H
#define DVSGI_SHARED_TEMPORAL_INDIRECT_PASS_H

#include "common.h"

DVSGI_BEGIN

DVSGI_CONST(uint, BIND_TI_FRAME, 0);        // FrameConstants of this frame's camera
DVSGI_CONST(uint, BIND_TI_NORMAL, 1);       // G-buffer world normal (sampled)
DVSGI_CONST(uint, BIND_TI_DEPTH, 2);        // G-buffer depth (sampled)
DVSGI_CONST(uint, BIND_TI_DIFFUSE, 3);      // RGBA16F indirect diffuse: this frame's in, accumulated rgb out (a kept)
// The history's a counts the frames a pixel has accumulated since it last
// restarted: >= 1 marks history present (0: none, NaN: unusable). The blend
// weight does not depend on it (one weight per frame, the push's params.x).
DVSGI_CONST(uint, BIND_TI_HISTORY_IN, 4);   // RGBA32F last frame's accumulated rgb, a = the pixel's frames
DVSGI_CONST(uint, BIND_TI_SURFACE_IN, 5);   // RGBA16F last frame's normal xyz, w = view depth (0: no surface)
DVSGI_CONST(uint, BIND_TI_HISTORY_OUT, 6);  // this frame's, for the next
DVSGI_CONST(uint, BIND_TI_SURFACE_OUT, 7);

struct TemporalIndirectPush {
    mat4 prevViewProj;  // last frame's camera (same clip space as FrameConstants.viewProj)
    vec4 params;        // x this frame's blend weight (render::temporalBlendWeight), y tangent-plane
                        // tolerance (of the view depth), z minimum cosine between normals, w largest
                        // sample count kept
    uvec4 flags;        // x width, y height (internal), z 1 = the history is valid (0: reset), w unused
};
DVSGI_CHECK_SIZE(TemporalIndirectPush, 96);

// A history texel is rejected where the point last frame saw there lies off
// this pixel's tangent plane by more than 2 % of the view depth, or its normal
// is more than about 25 degrees off (the test the flicker figure applies to the
// taps it interpolates, render/temporal_change.h).
DVSGI_CONST(float, TEMPORAL_DEPTH_TOLERANCE, 0.02);
DVSGI_CONST(float, TEMPORAL_NORMAL_COSINE, 0.9);
DVSGI_CONST(float, TEMPORAL_MAX_SAMPLES, 255.0);
// A still camera reprojects each pixel onto itself up to float rounding:
// bilinear fractions this close to a whole pixel are snapped to it, so the
// history is not blurred a little more every frame.
DVSGI_CONST(float, TEMPORAL_SNAP, 1e-3);

DVSGI_CONST(uint, TEMPORAL_GROUP, 8);

DVSGI_END

#endif
