// Shadow-map visibility for one light. Needs `shadowViews[]` (GpuShadowView)
// and `shadowMap` (sampler2DArrayShadow) declared by the including shader.
// Point lights own six views (+X -X +Y -Y +Z -Z); the face is the dominant axis
// of the light-to-point vector. A directional light with two views has one
// around the camera first (render/shadows.h, ShadowFocus), used where the
// point and its filter taps fall inside it, and the whole scene's second.
float shadowVisibility(GpuLight light, vec3 P, vec3 N, float normalOffsetTexels) {
    uint count = light.shadow.y;
    if (count == 0u) return 1.0;
    uint view = light.shadow.x;
    vec3 fromLight = P - light.position.xyz;
    if (count == 2u) {
        GpuShadowView focus = shadowViews[view];
        vec4 clip = focus.viewProj * vec4(P + N * focus.params.x * normalOffsetTexels, 1.0);
        // Two texels of margin keep the bilinear compare inside the map.
        float inside = 1.0 - 4.0 / float(textureSize(shadowMap, 0).x);
        if (any(greaterThan(abs(clip.xy / clip.w), vec2(inside)))) view += 1u;
    } else if (count == 6u) {
        vec3 a = abs(fromLight);
        if (a.x >= a.y && a.x >= a.z) view += fromLight.x > 0.0 ? 0u : 1u;
        else if (a.y >= a.z) view += fromLight.y > 0.0 ? 2u : 3u;
        else view += fromLight.z > 0.0 ? 4u : 5u;
    }
    GpuShadowView sv = shadowViews[view];
    // Normal offset: push the lookup off the surface by a few shadow-map texels,
    // measured at the point's distance for perspective views.
    float texel = sv.params.x * (sv.params.y > 0.5 ? length(fromLight) : 1.0);
    vec4 clip = sv.viewProj * vec4(P + N * texel * normalOffsetTexels, 1.0);
    vec3 ndc = clip.xyz / clip.w;
    if (any(greaterThan(abs(ndc.xy), vec2(1.0))) || ndc.z > 1.0) return 1.0;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    return texture(shadowMap, vec4(uv, float(view), ndc.z));
}
