// Between world space and a depth buffer's pixels, for the progressive
// voxelization passes (Vulkan clip space, depth 0..1).

// Clip and NDC coordinates of world point c; false when c lies behind the
// view, beside it, or outside its depth range.
bool projectInView(mat4 viewProj, vec3 c, out vec4 clip, out vec3 ndc) {
    clip = viewProj * vec4(c, 1.0);
    ndc = vec3(0.0);
    if (clip.w <= 0.0) return false;
    ndc = clip.xyz / clip.w;
    return all(lessThanEqual(abs(ndc.xy), vec2(1.0))) && ndc.z >= 0.0 && ndc.z <= 1.0;
}

// The pixel of a `size` image that NDC xy falls in.
ivec2 ndcPixel(vec2 ndc, ivec2 size) { return clamp(ivec2((ndc * 0.5 + 0.5) * vec2(size)), ivec2(0), size - 1); }

// The world point at NDC xy and depth through the inverse view-projection.
vec3 unprojectNdc(mat4 invViewProj, vec2 ndc, float depth) {
    vec4 p = invViewProj * vec4(ndc, depth, 1.0);
    return p.xyz / p.w;
}
