// Trace pixels and the G-buffer pixels they stand for (gather.comp writes
// them, upsample.comp and cone_resolve.comp weigh them by the surface there).
// Needs `frame` (FrameConstants), `gDepth`, and pc.sizes = (trace width,
// height, G-buffer width, height).
#ifndef DVSGI_LIB_TRACE_PIXELS_GLSL
#define DVSGI_LIB_TRACE_PIXELS_GLSL

// G-buffer pixel g's surface point (world space).
vec3 surfacePoint(ivec2 g) {
    vec2 ndc = (vec2(g) + 0.5) / vec2(frame.sizes.xy) * 2.0 - 1.0;
    vec4 w = frame.invViewProj * vec4(ndc, texelFetch(gDepth, g, 0).r, 1.0);
    return w.xyz / w.w;
}

// How far surface point q stands off the plane through p (normal n),
// relative to p's distance from the camera: 0 anywhere on that plane. A
// difference of depths instead grew along a floor or ceiling seen at a
// grazing angle, so the filters averaged such a plane across the view but
// hardly up it, and its noise stayed in streaks.
float planeOffset(vec3 q, vec3 p, vec3 n) {
    return abs(dot(q - p, n)) / max(length(p - frame.cameraPos.xyz), 1e-6);
}

// The G-buffer pixel a trace pixel stands for (same mapping as gather.comp).
ivec2 gbufferPixel(ivec2 low) {
    return min(ivec2((vec2(low) + 0.5) * vec2(pc.sizes.zw) / vec2(pc.sizes.xy)), ivec2(pc.sizes.zw) - 1);
}

// How much a neighbour's light may stand for a pixel's: 1 on the same plane,
// falling with its relative distance dz off the pixel's plane (planeOffset)
// and the normals' angle.
float surfaceSimilarity(float dz, vec3 n, vec3 neighbourN) {
    return pow(max(dot(neighbourN, n), 0.0), 8.0) / (1.0 + 100.0 * dz);
}

#endif
