// Material sampling shared by every pass that rasterizes the scene. Needs
// `materials[]`, `textures[]` and `textureSampler` declared by the including shader.

vec4 sampleTexture(int index, vec2 uv) {
    return texture(sampler2D(textures[index], textureSampler), uv);
}

vec4 materialBaseColor(GpuMaterial m, vec2 uv) {
    vec4 c = m.baseColor;
    if (m.textures.x != NO_TEXTURE) c *= sampleTexture(m.textures.x, uv);  // sRGB views decode
    return c;
}

// Interleaved gradient noise: a fixed per-pixel threshold for stochastic
// (BLEND) coverage, as CONVENTIONS.md treats alpha blending.
float coverageThreshold(vec2 fragCoord) {
    return fract(52.9829189 * fract(dot(fragCoord, vec2(0.06711056, 0.00583715))));
}

bool materialCovers(GpuMaterial m, float alpha, vec2 fragCoord) {
    if (m.flags.x == ALPHA_MASK) return alpha >= m.params.z;
    if (m.flags.x == ALPHA_BLEND) return alpha > coverageThreshold(fragCoord);
    return true;
}
