// Shadow-map visibility for one light. Needs `shadowViews[]` (GpuShadowView)
// and `shadowMap` (sampler2DArrayShadow) declared by the including shader.
// Point lights own six views (+X -X +Y -Y +Z -Z); the face is the dominant axis
// of the light-to-point vector.
float shadowVisibility(GpuLight light, vec3 P, vec3 N, float normalOffsetTexels) {
    uint count = light.shadow.y;
    if (count == 0u) return 1.0;
    uint view = light.shadow.x;
    vec3 fromLight = P - light.position.xyz;
    if (count == 6u) {
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
