#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_data.h"
#include "shared/temporal_indirect_pass.h"

// Temporal accumulation of the indirect diffuse term (issue #11 item 3). Each
// pixel's surface point is projected into last frame's camera; the four
// history texels around it are blended bilinearly, each only where last frame
// saw the same surface there: its point on this pixel's tangent plane within
// a tolerance relative to the view depth, and its normal close. A tap's own
// depth is not compared with the point's: on a floor seen at a grazing angle
// the next texel's depth differs by more than any useful tolerance, and
// rejecting it there dropped the history of whole strips of floor, whose raw
// gather then set the walk's flicker. With any such texel the output is
// mix(history, current, alpha), one alpha for the whole frame
// (render::temporalBlendWeight: alphaMin once the voxel light has settled;
// while it still climbs frame by frame, the running mean of the frames since
// the history restarted, until 1/alphaMin of them, an exponential average after);
// with none (disocclusion, off screen, the first frame, a reset) the current
// value stays as the gather wrote it and the pixel's count restarts at 1.
// A pixel that has just come into view blends at the frame's alpha from its
// first value on: weighting its own few frames as a running mean moved it by
// half, a third, ... of the change between gathers each frame, and such pixels
// set the walk's flicker (docs/benchmarks.md). The accumulated value goes
// back into the indirect diffuse image (its alpha, the AO, untouched) and
// into the history for the next frame, with this frame's normal and view
// depth.
layout(local_size_x = TEMPORAL_GROUP, local_size_y = TEMPORAL_GROUP) in;

layout(set = 0, binding = BIND_TI_FRAME) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = BIND_TI_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = BIND_TI_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = BIND_TI_DIFFUSE, rgba16f) uniform image2D diffuse;
layout(set = 0, binding = BIND_TI_HISTORY_IN, rgba32f) uniform readonly image2D historyIn;
layout(set = 0, binding = BIND_TI_SURFACE_IN, rgba16f) uniform readonly image2D surfaceIn;
layout(set = 0, binding = BIND_TI_HISTORY_OUT, rgba32f) uniform writeonly image2D historyOut;
layout(set = 0, binding = BIND_TI_SURFACE_OUT, rgba16f) uniform writeonly image2D surfaceOut;
layout(push_constant) uniform Push { TemporalIndirectPush pc; };

bool finite(vec4 v) { return !any(isnan(v)) && !any(isinf(v)); }

// The world point last frame's camera saw at pixel t, `viewDepth` along its
// axis: on the ray through the pixel's centre, where clip w (the view depth,
// affine in the point) takes that value.
vec3 pointSeenBefore(mat4 invPrev, ivec2 t, ivec2 size, float viewDepth) {
    vec2 ndc = (vec2(t) + 0.5) / vec2(size) * 2.0 - 1.0;
    vec4 nearH = invPrev * vec4(ndc, 0.0, 1.0), farH = invPrev * vec4(ndc, 1.0, 1.0);
    vec3 a = nearH.xyz / nearH.w, b = farH.xyz / farH.w;
    vec4 wRow = vec4(pc.prevViewProj[0][3], pc.prevViewProj[1][3], pc.prevViewProj[2][3], pc.prevViewProj[3][3]);
    float wa = dot(wRow, vec4(a, 1.0)), wb = dot(wRow, vec4(b, 1.0));
    return mix(a, b, (viewDepth - wa) / (wb - wa));
}

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(pc.flags.xy);
    if (any(greaterThanEqual(px, size))) return;
    float depth = texelFetch(gDepth, px, 0).r;
    if (depth >= 1.0) {  // no geometry: nothing to keep (the gather wrote zero)
        imageStore(historyOut, px, vec4(0.0));
        imageStore(surfaceOut, px, vec4(0.0));
        return;
    }
    vec2 ndc = (vec2(px) + 0.5) / vec2(size) * 2.0 - 1.0;
    vec4 w = frame.invViewProj * vec4(ndc, depth, 1.0);
    vec4 P = vec4(w.xyz / w.w, 1.0);
    vec3 N = normalize(texelFetch(gNormal, px, 0).xyz);
    imageStore(surfaceOut, px, vec4(N, (frame.viewProj * P).w));
    vec4 current = imageLoad(diffuse, px);

    vec3 history = vec3(0.0);
    float samples = 0.0;
    vec4 clip = pc.prevViewProj * P;
    if (pc.flags.z != 0u && clip.w > 0.0) {
        // Last frame's pixel coordinates (pixel centres at +0.5).
        vec2 q = (clip.xy / clip.w * 0.5 + 0.5) * vec2(size);
        if (all(greaterThanEqual(q, vec2(0.0))) && all(lessThan(q, vec2(size)))) {
            vec2 b = q - 0.5;
            ivec2 b0 = ivec2(floor(b));
            vec2 f = b - vec2(b0);
            f = mix(f, round(f), lessThan(abs(f - round(f)), vec2(TEMPORAL_SNAP)));
            mat4 invPrev = inverse(pc.prevViewProj);
            vec3 sum = vec3(0.0);
            float count = 0.0, weight = 0.0;
            for (int j = 0; j < 2; ++j)
                for (int i = 0; i < 2; ++i) {
                    ivec2 t = b0 + ivec2(i, j);
                    float bw = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
                    if (bw <= 0.0 || any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, size))) continue;
                    vec4 s = imageLoad(surfaceIn, t);
                    if (s.w <= 0.0 || dot(s.xyz, N) < pc.params.z) continue;
                    // Written so that a NaN distance (a stored depth beyond half's range) rejects the texel.
                    float off = abs(dot(pointSeenBefore(invPrev, t, size, s.w) - P.xyz, N));
                    if (!(off <= pc.params.y * clip.w)) continue;
                    vec4 h = imageLoad(historyIn, t);
                    if (h.a < 1.0 || !finite(h)) continue;
                    sum += bw * h.rgb;
                    count += bw * h.a;
                    weight += bw;
                }
            if (weight > 1e-4) {
                history = sum / weight;
                samples = count / weight;
            }
        }
    }
    if (samples <= 0.0) {
        imageStore(historyOut, px, vec4(current.rgb, 1.0));
        return;
    }
    float alpha = pc.params.x;
    // history + alpha (current - history), not mix(): equal inputs give that
    // value exactly, which lavapipe's round-toward-zero RGBA16F store keeps.
    vec3 result = history + alpha * (current.rgb - history);
    imageStore(historyOut, px, vec4(result, min(samples + 1.0, pc.params.w)));
    imageStore(diffuse, px, vec4(result, current.a));
}
