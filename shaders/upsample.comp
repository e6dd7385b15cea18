#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_data.h"
#include "shared/upsample_pass.h"

// Depth- and normal-aware upsampling of the cone-traced terms from the trace
// resolution to the internal resolution (the speed path of Wicked Engine's
// VXGI): each full-resolution pixel blends its four nearest trace pixels with
// bilinear weights times a depth and a normal similarity, so indirect light
// does not bleed across silhouettes.
layout(local_size_x = UPSAMPLE_GROUP, local_size_y = UPSAMPLE_GROUP) in;

layout(set = 0, binding = BIND_UP_FRAME) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = BIND_UP_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = BIND_UP_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = BIND_UP_LOW_DIFFUSE, rgba16f) uniform readonly image2D lowDiffuse;
layout(set = 0, binding = BIND_UP_LOW_SPECULAR, rgba16f) uniform readonly image2D lowSpecular;
layout(set = 0, binding = BIND_UP_OUT_DIFFUSE, rgba16f) uniform writeonly image2D outDiffuse;
layout(set = 0, binding = BIND_UP_OUT_SPECULAR, rgba16f) uniform writeonly image2D outSpecular;
layout(push_constant) uniform Push { UpsamplePush pc; };

#include "lib/trace_pixels.glsl"

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(px), pc.sizes.zw))) return;
    vec3 P = surfacePoint(px);
    vec3 n = texelFetch(gNormal, px, 0).xyz;
    vec2 q = (vec2(px) + 0.5) * vec2(pc.sizes.xy) / vec2(pc.sizes.zw) - 0.5;
    ivec2 q0 = ivec2(floor(q));
    vec2 f = q - vec2(q0);
    vec4 diff = vec4(0.0), spec = vec4(0.0);
    float wsum = 0.0;
    vec4 nearestDiff = vec4(0.0), nearestSpec = vec4(0.0);
    float best = -1.0;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            ivec2 l = clamp(q0 + ivec2(i, j), ivec2(0), ivec2(pc.sizes.xy) - 1);
            ivec2 g = gbufferPixel(l);
            float bil = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
            float dz = planeOffset(surfacePoint(g), P, n);
            float similarity = surfaceSimilarity(dz, n, texelFetch(gNormal, g, 0).xyz);
            float w = bil * similarity;
            vec4 d = imageLoad(lowDiffuse, l), s = imageLoad(lowSpecular, l);
            diff += w * d;
            spec += w * s;
            wsum += w;
            if (similarity > best) {
                best = similarity;
                nearestDiff = d;
                nearestSpec = s;
            }
        }
    // No similar neighbour (thin features): take the most similar one.
    if (wsum > 1e-4) {
        diff /= wsum;
        spec /= wsum;
    } else {
        diff = nearestDiff;
        spec = nearestSpec;
    }
    imageStore(outDiffuse, px, diff);
    imageStore(outSpecular, px, spec);
}
