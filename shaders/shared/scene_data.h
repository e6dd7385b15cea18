// GPU-side scene records shared by the G-buffer, shadow and lighting passes.
#ifndef DVSGI_SHARED_SCENE_DATA_H
#define DVSGI_SHARED_SCENE_DATA_H

#include "common.h"

DVSGI_BEGIN

// Fixed-size texture table: lavapipe lacks runtime descriptor arrays and allows
// 128 sampled images per stage, so 96 leaves room for every pass's own bindings.
DVSGI_CONST(uint, MAX_TEXTURES, 96);
DVSGI_CONST(int, NO_TEXTURE, -1);

DVSGI_CONST(uint, ALPHA_OPAQUE, 0);
DVSGI_CONST(uint, ALPHA_MASK, 1);
DVSGI_CONST(uint, ALPHA_BLEND, 2);

DVSGI_CONST(uint, LIGHT_DIRECTIONAL, 0);
DVSGI_CONST(uint, LIGHT_POINT, 1);
DVSGI_CONST(uint, LIGHT_SPOT, 2);
// An emissive patch (render/emitters.h): position = centroid, direction.xyz =
// the side it emits toward (w = 1: both sides), radiant.rgb = radiance x area
// (W/sr at normal incidence), radiant.w = area / pi (the near-field disk r^2).
DVSGI_CONST(uint, LIGHT_AREA, 3);

struct GpuMaterial {
    vec4 baseColor;   // linear factor, a = alpha
    vec4 emission;    // rgb = emissiveFactor * strength (W m^-2 sr^-1)
    vec4 params;      // x metallic, y roughness, z alphaCutoff, w normalScale
    ivec4 textures;   // base colour, emissive, metallic-roughness, normal; NO_TEXTURE = none
    uvec4 flags;      // x alpha mode, y doubleSided
    // x, y: the base colour texture's width and height, z, w: the emissive
    // texture's (texels; 0 without one). The voxelizers read them here: lavapipe
    // answered textureSize on the dynamically indexed texture array with
    // another texture's size for some invocations (lib/material.glsl).
    ivec4 textureSizes;
};
DVSGI_CHECK_SIZE(GpuMaterial, 96);

struct GpuDraw {
    mat4 model;
    mat4 normalMatrix;  // inverse-transpose of the model's upper 3x3
    uvec4 info;         // x material, y node
};
DVSGI_CHECK_SIZE(GpuDraw, 144);

struct GpuLight {
    vec4 position;   // xyz world position (point/spot), w = type
    vec4 direction;  // xyz direction the light travels (directional/spot), w = cos(outer cone)
    vec4 radiant;    // rgb = colour * intensity (E in W/m^2 or I in W/sr), w = cos(inner cone)
    uvec4 shadow;    // x first shadow view, y view count (0 = unshadowed)
};
DVSGI_CHECK_SIZE(GpuLight, 64);

struct GpuShadowView {
    mat4 viewProj;
    vec4 params;  // x world texel size (ortho) or per metre of distance (perspective), y 1 = perspective
};
DVSGI_CHECK_SIZE(GpuShadowView, 80);

struct FrameConstants {
    mat4 viewProj;
    mat4 invViewProj;
    vec4 cameraPos;
    uvec4 sizes;         // x width, y height (internal), z light count, w shadow map size
    vec4 shadowParams;   // x normal offset in texels, y shadows on (1/0)
};
DVSGI_CHECK_SIZE(FrameConstants, 176);

DVSGI_END

#endif
