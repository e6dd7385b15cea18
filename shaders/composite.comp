#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/composite_pass.h"

// Final composition at output resolution: direct (with emission) + indirect
// diffuse (times the G-buffer's diffuse albedo) + specular, the indirect terms optionally times AO; or one term
// alone (--output). With supersampling each output pixel is the box average of
// its k x k internal pixels: a pixel-area average, as the references are.
layout(local_size_x = COMPOSITE_GROUP, local_size_y = COMPOSITE_GROUP) in;

layout(set = 0, binding = BIND_COMP_DIRECT, rgba32f) uniform readonly image2D direct;
layout(set = 0, binding = BIND_COMP_OUT, rgba32f) uniform writeonly image2D outImage;
layout(set = 0, binding = BIND_COMP_DIFFUSE, rgba16f) uniform readonly image2D diffuse;
layout(set = 0, binding = BIND_COMP_SPECULAR, rgba16f) uniform readonly image2D specular;
layout(set = 0, binding = BIND_COMP_SHADOW, r16f) uniform readonly image2D shadow;
layout(set = 0, binding = BIND_COMP_BASE) uniform sampler2D gBase;
layout(push_constant) uniform Push { CompositePush pc; };

vec3 term(ivec2 p) {
    uint t = pc.sizes.w;
    vec3 d = imageLoad(direct, p).rgb;
    if (t == TERM_DIRECT) return d;
    if (t == TERM_SHADOW) return vec3(imageLoad(shadow, p).r);
    if (pc.flags.y == 0u) return t == TERM_FULL ? d : (t == TERM_AO ? vec3(1.0) : vec3(0.0));
    vec4 diff = imageLoad(diffuse, p);
    vec3 spec = imageLoad(specular, p).rgb;
    if (t == TERM_AO) return vec3(diff.a);
    float ao = pc.flags.x != 0u ? diff.a : 1.0;
    if (t == TERM_IRRADIANCE) return diff.rgb * ao;
    // The cone-traced diffuse term is demodulated (gather.comp): the albedo
    // goes on here, per internal pixel, after any upsampling and accumulation.
    vec4 base = texelFetch(gBase, p, 0);
    diff.rgb *= base.rgb * (1.0 - base.a);
    if (t == TERM_INDIRECT) return diff.rgb * ao;
    if (t == TERM_SPECULAR) return spec * ao;
    return d + (diff.rgb + spec) * ao;
}

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(px), pc.sizes.xy))) return;
    int k = int(pc.sizes.z);
    vec3 sum = vec3(0.0);
    for (int y = 0; y < k; ++y)
        for (int x = 0; x < k; ++x) sum += term(px * k + ivec2(x, y));
    imageStore(outImage, px, vec4(sum / float(k * k), 1.0));
}
