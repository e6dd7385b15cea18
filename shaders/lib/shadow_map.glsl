// Shadow-map visibility for one light. Needs `shadowViews[]` (GpuShadowView),
// `shadowMap` (the depth array) and `shadowGradient` (each texel's caster's
// depth gradient, shadow.frag), both sampler2DArray, declared by the including
// shader, and shared/shadow_pass.h.
// Point lights own six views (+X -X +Y -Y +Z -Z); the face is the dominant axis
// of the light-to-point vector. A directional light with two views has one
// around the camera first (render/shadows.h, ShadowFocus), used where the
// point and its filter taps fall inside it, and the whole scene's second.

vec3 shadowNdc(GpuShadowView sv, vec3 P) {
    vec4 clip = sv.viewProj * vec4(P, 1.0);
    return clip.xyz / clip.w;
}

// The receiver's plane (through P, normal N) in the map: depth per texel
// along x and y, from two points a texel off P along the plane.
vec2 receiverGradient(GpuShadowView sv, vec3 P, vec3 N, vec3 ndc, float texel, float size) {
    vec3 t1 = normalize(cross(N, abs(N.x) < 0.6 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0))) * texel;
    vec3 t2 = cross(N, t1);
    vec3 a = shadowNdc(sv, P + t1) - ndc, b = shadowNdc(sv, P + t2) - ndc;
    a.xy *= 0.5 * size;
    b.xy *= 0.5 * size;
    vec3 n = cross(a, b);
    return abs(n.z) > 1e-30 ? -n.xy / n.z : vec2(0.0);
}

float shadowVisibility(GpuLight light, vec3 P, vec3 N, float normalOffsetTexels) {
    uint count = light.shadow.y;
    if (count == 0u) return 1.0;
    uint view = light.shadow.x;
    vec3 fromLight = P - light.position.xyz;
    float size = float(textureSize(shadowMap, 0).x);
    if (count == 2u) {
        GpuShadowView focus = shadowViews[view];
        vec4 clip = focus.viewProj * vec4(P + N * focus.params.x * normalOffsetTexels, 1.0);
        // Two texels of margin keep the 2 x 2 texels inside the focus view.
        float inside = 1.0 - 4.0 / size;
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
    vec3 Q = P + N * texel * normalOffsetTexels;
    vec3 ndc = shadowNdc(sv, Q);
    if (any(greaterThan(abs(ndc.xy), vec2(1.0))) || ndc.z > 1.0) return 1.0;
    // The 2 x 2 texels are picked here, not by the gather: hardware picks them
    // from a fixed-point coordinate, and near a texel's edge its quad and a
    // float fract() disagree by a texel, which would extend each caster's
    // plane from the wrong place. At the map's edge the quad stays inside
    // the map and the offsets run past [0, 1]; the weights do not.
    vec2 t = (ndc.xy * 0.5 + 0.5) * size - 0.5;
    vec2 corner = clamp(floor(t), vec2(0.0), vec2(size - 2.0));
    vec2 f = t - corner;
    vec3 uv = vec3((corner + 1.0) / size, float(view));
    // Each of the 2 x 2 texels around the lookup holds its caster's depth at
    // its centre and the caster's gradient. That caster shadows the receiver
    // where the receiver lies behind the caster's plane and the caster lies in
    // front of the receiver's own plane, each by the margin. A surface is its
    // own caster, and the normal offset puts the lookup in front of it; in a
    // corner, a wall the light grazes hides the receiver behind its plane; at
    // a convex edge the face beyond the edge lies behind the receiver's plane.
    // textureGather's order: (0,1) (1,1) (1,0) (0,0).
    vec4 dx = vec4(f.x, f.x - 1.0, f.x - 1.0, f.x), dy = vec4(f.y - 1.0, f.y - 1.0, f.y, f.y);
    vec4 depth = textureGather(shadowMap, uv, 0);
    vec4 plane = depth + textureGather(shadowGradient, uv, 0) * dx + textureGather(shadowGradient, uv, 1) * dy;
    vec2 g = receiverGradient(sv, Q, N, ndc, texel, size);
    vec4 receiverPlane = ndc.z - g.x * dx - g.y * dy;
    vec3 along = sv.params.y > 0.5 ? normalize(fromLight) : light.direction.xyz;
    float margin = SHADOW_PLANE_MARGIN * abs(shadowNdc(sv, Q + along * texel).z - ndc.z);
    vec4 shadowed = vec4(greaterThan(vec4(ndc.z), plane + margin)) * vec4(lessThan(depth, receiverPlane - margin));
    vec4 lit = 1.0 - shadowed;
    vec2 w = clamp(f, 0.0, 1.0);
    return mix(mix(lit.w, lit.z, w.x), mix(lit.x, lit.y, w.x), w.y);
}
