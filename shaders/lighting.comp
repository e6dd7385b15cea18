#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_data.h"
#include "shared/bindings.h"

// Deferred direct lighting: for every pixel, the sum over lights of
// BRDF * cos * irradiance * shadow visibility, plus emitted radiance.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = BIND_LIGHT_FRAME) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = BIND_LIGHT_GBUF_BASE) uniform sampler2D gBase;
layout(set = 0, binding = BIND_LIGHT_GBUF_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = BIND_LIGHT_GBUF_EMISSION) uniform sampler2D gEmission;
layout(set = 0, binding = BIND_LIGHT_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = BIND_LIGHT_LIGHTS, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = BIND_LIGHT_SHADOW_VIEWS, std430) readonly buffer Views { GpuShadowView shadowViews[]; };
layout(set = 0, binding = BIND_LIGHT_SHADOW_MAP) uniform sampler2DArrayShadow shadowMap;
layout(set = 0, binding = BIND_LIGHT_OUT_DIRECT, rgba32f) uniform writeonly image2D outDirect;

#include "lib/lights.glsl"
#include "lib/brdf.glsl"
#include "lib/shadow_map.glsl"

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(px), frame.sizes.xy))) return;
    vec4 emission = texelFetch(gEmission, px, 0);
    if (emission.a == 0.0) {  // background: no environment light
        imageStore(outDirect, px, vec4(0.0));
        return;
    }
    float depth = texelFetch(gDepth, px, 0).r;
    vec2 ndc = (vec2(px) + 0.5) / vec2(frame.sizes.xy) * 2.0 - 1.0;
    vec4 world = frame.invViewProj * vec4(ndc, depth, 1.0);
    vec3 P = world.xyz / world.w;
    vec4 base = texelFetch(gBase, px, 0);
    vec4 nr = texelFetch(gNormal, px, 0);
    vec3 N = normalize(nr.xyz);
    vec3 V = normalize(frame.cameraPos.xyz - P);

    vec3 radiance = emission.rgb;
    for (uint i = 0u; i < frame.sizes.z; ++i) {
        vec3 L;
        float dist;
        vec3 E = lightIrradiance(lights[i], P, L, dist);
        if (dot(N, L) <= 0.0 || all(equal(E, vec3(0.0)))) continue;
        float vis = frame.shadowParams.y > 0.5 ? shadowVisibility(lights[i], P, N, frame.shadowParams.x) : 1.0;
        radiance += surfaceBrdfCos(base.rgb, base.a, nr.w, N, L, V) * E * vis;
    }
    imageStore(outDirect, px, vec4(radiance, 1.0));
}
