// Two-sided voxels (shared/voxel_data.h, TWO_SIDED_MIN_WEIGHT): which side
// code a voxel gets, and the per-slot side light, packed four RGB9E5 values
// to a texel: x, y the +axis and -axis sides' direct light (+ emission),
// z, w the light each side reflected in the last bounce.
#ifndef DVSGI_VOXEL_SIDES_GLSL
#define DVSGI_VOXEL_SIDES_GLSL

// The side code of normal weights pos / neg (SIDE_*): the axis on which both
// signed weights reach the threshold, SIDE_SEVERAL if more than one does.
uint sideCode(vec3 pos, vec3 neg) {
    vec3 m = min(pos, neg);
    bvec3 both = greaterThanEqual(m, vec3(TWO_SIDED_MIN_WEIGHT));
    int count = int(both.x) + int(both.y) + int(both.z);
    if (count == 0) return SIDE_ONE;
    if (count > 1) return SIDE_SEVERAL;
    return both.x ? 1u : (both.y ? 2u : 3u);
}

// A slot's direct light keeps its side code in alpha, as 1 + code, so that
// one-sided voxels keep alpha 1.
float sideCodeAlpha(uint code) { return 1.0 + float(code); }
uint sideCodeOf(vec4 direct) { return uint(direct.a + 0.5) - 1u; }

// twoSidedAxis, twoSidedOpacity, marksTwoSided and sideCodeOfOpacity live in
// shared/voxel_data.h, which the tests' CPU ray march shares.

// Shared-exponent RGB (9-bit mantissas, 5-bit exponent, bias 15), as
// VK_FORMAT_E5B9G9R9_UFLOAT_PACK32 stores it; negative inputs become 0.
uint packRgb9e5(vec3 rgb) {
    const float maxValue = 65408.0;  // (511 / 512) * 2^16
    vec3 c = clamp(rgb, vec3(0.0), vec3(maxValue));
    float m = max(c.r, max(c.g, c.b));
    int e = max(-16, int(floor(log2(max(m, 1e-30))))) + 16;  // biased shared exponent
    float scale = exp2(float(e - 24));
    if (floor(m / scale + 0.5) >= 512.0) {
        e += 1;
        scale *= 2.0;
    }
    uvec3 q = uvec3(floor(c / scale + 0.5));
    return q.r | (q.g << 9) | (q.b << 18) | (uint(e) << 27);
}

vec3 unpackRgb9e5(uint v) {
    uvec3 q = uvec3(v, v >> 9, v >> 18) & 511u;
    return vec3(q) * exp2(float(int(v >> 27) - 24));
}

// The share of a one-sided voxel's light (mean normal n) that a ray travelling
// along unit t sees (VOXEL_BACK_FADE_*): all of it face on or edge on, none
// from behind, where what lies beyond a surface is the solid it bounds or its
// own other face (then a voxel of its own, or this one two-sided).
float seenFromFront(vec3 n, vec3 t) { return voxelBackFade(dot(n, t)); }

// Side 0 (+axis) or 1 (-axis) of a slot's side-light texel `t`: its direct
// plus reflected light.
vec3 sideLight(uvec4 t, int side) {
    return side == 0 ? unpackRgb9e5(t.x) + unpackRgb9e5(t.z) : unpackRgb9e5(t.y) + unpackRgb9e5(t.w);
}
#endif
