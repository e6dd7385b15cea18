#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_data.h"
#include "shared/geometry_pass.h"

layout(set = 0, binding = BIND_GEOM_MATERIALS, std430) readonly buffer Materials { GpuMaterial materials[]; };
layout(set = SET_TEXTURES, binding = BIND_TEXTURES) uniform texture2D textures[MAX_TEXTURES];
layout(set = SET_TEXTURES, binding = BIND_TEXTURE_SAMPLER) uniform sampler textureSampler;

#include "lib/material.glsl"

layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec2 inUV;
layout(location = 2) flat in uint inMaterial;

layout(location = 0) out vec4 outBase;      // rgb base colour (linear), a metallic
layout(location = 1) out vec4 outNormal;    // xyz world normal facing the viewer, a roughness
layout(location = 2) out vec4 outEmission;  // rgb emitted radiance, a = 1 where geometry is

void main() {
    GpuMaterial m = materials[inMaterial];
    vec4 base = materialBaseColor(m, inUV);
#ifdef DVSGI_ALPHA_TESTED
    // Only cut-out and stochastic materials use this variant: a shader that can
    // discard keeps the depth test late, so opaque draws use the other one.
    if (!materialCovers(m, base.a, gl_FragCoord.xy)) discard;
#endif

    float metallic = m.params.x, roughness = m.params.y;
#ifndef DVSGI_BASE_COLOR_ONLY
    // Materials whose only texture, if any, is the base colour are drawn with
    // the BASE_COLOR_ONLY variant, which leaves these samples out: llvmpipe runs
    // both sides of every branch, so they were taken, and thrown away, for
    // every fragment (Sponza: the pass took twice as long).
    if (m.textures.z != NO_TEXTURE) {
        vec4 mr = sampleTexture(m.textures.z, inUV);
        roughness *= mr.g;
        metallic *= mr.b;
    }
#endif
    // Back faces reflect like front faces (CONVENTIONS.md), so shade them with
    // the flipped normal; only emission is one-sided.
    vec3 N = normalize(inNormal);
    if (!gl_FrontFacing) N = -N;

    vec3 emission = vec3(0.0);
    if (gl_FrontFacing || m.flags.y != 0u) {
        emission = m.emission.rgb;
#ifndef DVSGI_BASE_COLOR_ONLY
        if (m.textures.y != NO_TEXTURE) emission *= sampleTexture(m.textures.y, inUV).rgb;
#endif
    }
    outBase = vec4(base.rgb, metallic);
    outNormal = vec4(N, roughness);
    outEmission = vec4(emission, 1.0);
}
