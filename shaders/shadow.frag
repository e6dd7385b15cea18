#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_data.h"
#include "shared/geometry_pass.h"
#include "shared/shadow_pass.h"

// Writes the caster's depth gradient next to its depth: the lookup
// (lib/shadow_map.glsl) extends the caster's plane to the receiver. The ALPHA_TESTED
// variant also discards where cut-out (MASK) and stochastic (BLEND) surfaces
// have no surface, so they cast the shadows of the parts that exist.
#ifdef DVSGI_ALPHA_TESTED
layout(set = 0, binding = BIND_GEOM_MATERIALS, std430) readonly buffer Materials { GpuMaterial materials[]; };
layout(set = SET_TEXTURES, binding = BIND_TEXTURES) uniform texture2D textures[MAX_TEXTURES];
layout(set = SET_TEXTURES, binding = BIND_TEXTURE_SAMPLER) uniform sampler textureSampler;

#include "lib/material.glsl"

layout(location = 0) in vec2 inUV;
layout(location = 1) flat in uint inMaterial;
#endif

layout(location = 0) out vec2 outGradient;

void main() {
    // Depth per texel along x and y. A triangle is a plane, and a plane's
    // depth is affine in the map's texels (perspective views too), so the
    // quad's differences are exact. Clamped to what RG16F holds: a triangle
    // that steep is seen edge-on, and its plane's sign is all that matters.
    // Taken before any discard: a quad's derivatives are undefined once a
    // neighbour has been discarded.
    vec2 gradient = vec2(dFdx(gl_FragCoord.z), dFdy(gl_FragCoord.z));
    outGradient = clamp(gradient, vec2(-SHADOW_GRADIENT_MAX), vec2(SHADOW_GRADIENT_MAX));
#ifdef DVSGI_ALPHA_TESTED
    GpuMaterial m = materials[inMaterial];
    if (m.flags.x != ALPHA_OPAQUE && !materialCovers(m, materialBaseColor(m, inUV).a, gl_FragCoord.xy)) discard;
#endif
}
