// Trace pixels and the G-buffer pixels they stand for (gather.comp writes
// them, upsample.comp and cone_resolve.comp weigh them by the surface there).
// Needs `frame` (FrameConstants), `gDepth`, and pc.sizes = (trace width,
// height, G-buffer width, height).
#ifndef DVSGI_LIB_TRACE_PIXELS_GLSL
#define DVSGI_LIB_TRACE_PIXELS_GLSL

// Distance from the camera to G-buffer pixel g's surface.
float linearDepth(ivec2 g) {
    vec2 ndc = (vec2(g) + 0.5) / vec2(frame.sizes.xy) * 2.0 - 1.0;
    vec4 w = frame.invViewProj * vec4(ndc, texelFetch(gDepth, g, 0).r, 1.0);
    return length(w.xyz / w.w - frame.cameraPos.xyz);
}

// The G-buffer pixel a trace pixel stands for (same mapping as gather.comp).
ivec2 gbufferPixel(ivec2 low) {
    return min(ivec2((vec2(low) + 0.5) * vec2(pc.sizes.zw) / vec2(pc.sizes.xy)), ivec2(pc.sizes.zw) - 1);
}

// How much a neighbour's light may stand for a pixel's: 1 on the same plane,
// falling with the relative depth difference dz and the normals' angle.
float surfaceSimilarity(float dz, vec3 n, vec3 neighbourN) {
    return pow(max(dot(neighbourN, n), 0.0), 8.0) / (1.0 + 100.0 * dz);
}

#endif
