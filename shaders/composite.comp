#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/bindings.h"
#include "shared/push.h"

// Final composition at output resolution. With supersampling each output pixel
// is the box average of its k x k internal pixels: a pixel-area average, as
// the reference images are.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = BIND_COMP_DIRECT, rgba32f) uniform readonly image2D direct;
layout(set = 0, binding = BIND_COMP_OUT, rgba32f) uniform writeonly image2D outImage;
layout(push_constant) uniform Push { CompositePush pc; };

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(px), pc.sizes.xy))) return;
    int k = int(pc.sizes.z);
    vec3 sum = vec3(0.0);
    for (int y = 0; y < k; ++y)
        for (int x = 0; x < k; ++x) sum += imageLoad(direct, px * k + ivec2(x, y)).rgb;
    imageStore(outImage, px, vec4(sum / float(k * k), 1.0));
}
