#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_data.h"
#include "shared/cone_resolve_pass.h"

// The gather turns its six cones about the normal a little more in each pixel
// of a 2x2 block (coneSpinTurn), so that four neighbours together sample 24
// directions where each alone samples six. A fixed set left blotches a cone
// wide wherever a bright surface fell between two side cones (cornell-lights
// 0.104 relative RMSE, 0.094 with the turns unresolved). A 3x3 tent at trace
// resolution weighs the four turns 1/4 each, so the turns leave no pattern on
// a surface; each neighbour is also weighed by how alike its surface is, as
// the upsampler does, so light does not cross silhouettes (there the pattern
// is partly left).
// The gather's rays differ from pixel to pixel (16 each by default): one tent
// left blotches a few trace pixels wide (cornell-lights 0.050 relative RMSE
// at 512^2, most of it that noise). So the tent runs again with its taps 2,
// 4, ... pixels apart (an a-trous filter, GatherSettings::rayFilterPasses),
// each pass weighing the same surface likeness, which keeps it on a surface:
// the neighbour's distance off the pixel's plane (a depth difference kept a
// floor seen at a grazing angle from being averaged up the view, and left its
// noise in streaks) and its world distance against RESOLVE_REACH_VOXELS.
layout(local_size_x = RESOLVE_GROUP, local_size_y = RESOLVE_GROUP) in;

layout(set = 0, binding = BIND_RESOLVE_FRAME) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = BIND_RESOLVE_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = BIND_RESOLVE_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = BIND_RESOLVE_TRACED, rgba16f) uniform readonly image2D traced;
layout(set = 0, binding = BIND_RESOLVE_OUT, rgba16f) uniform writeonly image2D resolved;
layout(push_constant) uniform Push { ConeResolvePush pc; };

#include "lib/trace_pixels.glsl"

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(p), pc.sizes.xy))) return;
    ivec2 g = gbufferPixel(p);
    vec4 own = imageLoad(traced, p);
    if (texelFetch(gDepth, g, 0).r >= 1.0) {  // background: what the gather wrote
        imageStore(resolved, p, own);
        return;
    }
    vec3 P = surfacePoint(g);
    vec3 n = texelFetch(gNormal, g, 0).xyz;
    float reach = RESOLVE_REACH_VOXELS * uintBitsToFloat(pc.step.y);
    vec4 sum = vec4(0.0);
    float wsum = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = p + ivec2(dx, dy) * int(pc.step.x);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(uvec2(q), pc.sizes.xy))) continue;
            ivec2 gq = gbufferPixel(q);
            vec3 Q = surfacePoint(gq);
            float dz = planeOffset(Q, P, n);
            float d = reach > 0.0 ? length(Q - P) / reach : 0.0;
            float w = float((2 - abs(dx)) * (2 - abs(dy))) * surfaceSimilarity(dz, n, texelFetch(gNormal, gq, 0).xyz) /
                      (1.0 + d * d);
            sum += w * imageLoad(traced, q);
            wsum += w;
        }
    imageStore(resolved, p, wsum > 1e-4 ? sum / wsum : own);
}
