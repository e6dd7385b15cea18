#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_data.h"
#include "shared/geometry_pass.h"

// Depth-only; exists so cut-out (MASK) and stochastic (BLEND) surfaces cast
// the shadows of the parts that exist.
layout(set = 0, binding = BIND_GEOM_MATERIALS, std430) readonly buffer Materials { GpuMaterial materials[]; };
layout(set = SET_TEXTURES, binding = BIND_TEXTURES) uniform texture2D textures[MAX_TEXTURES];
layout(set = SET_TEXTURES, binding = BIND_TEXTURE_SAMPLER) uniform sampler textureSampler;

#include "lib/material.glsl"

layout(location = 0) in vec2 inUV;
layout(location = 1) flat in uint inMaterial;

void main() {
    GpuMaterial m = materials[inMaterial];
    if (m.flags.x == ALPHA_OPAQUE) return;
    if (!materialCovers(m, materialBaseColor(m, inUV).a, gl_FragCoord.xy)) discard;
}
