#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/present_pass.h"
// dvsgi view: the window's tone mapping, the PNG preview's (image/image_io.h,
// writePng): radiance * 2^EV clamped to [0, 1], NaN -> 0, +Inf -> 1. The blit
// into the sRGB swapchain image that follows applies the sRGB curve.
layout(local_size_x = PRESENT_GROUP, local_size_y = PRESENT_GROUP) in;

layout(set = 0, binding = BIND_PRESENT_RADIANCE, rgba32f) uniform readonly image2D radiance;
layout(set = 0, binding = BIND_PRESENT_DISPLAY, rgba32f) uniform writeonly image2D display;
layout(push_constant) uniform Push { PresentPush pc; };

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(pc.params.xy)))) return;
    vec3 c = imageLoad(radiance, p).rgb * pc.params.z;
    // Select, not arithmetic: a NaN fails the comparison and becomes 0.
    c = mix(vec3(0.0), min(c, vec3(1.0)), greaterThan(c, vec3(0.0)));
    imageStore(display, p, vec4(c, 1.0));
}
