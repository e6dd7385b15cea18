// Material sampling shared by every pass that rasterizes the scene. Needs
// `materials[]`, `textures[]` and `textureSampler` declared by the including shader;
// the voxelizers define MATERIAL_EXPLICIT_LOD first.

#ifdef MATERIAL_EXPLICIT_LOD
// The voxelizers sample by hand: the caller sets how much texture area one
// unit of surface area covers (uv^2 per voxel^2; the compute voxelizer has no
// derivatives, the geometry-shader one takes them from its voxel-sized
// pixels), and the level is the one where a texel matches that unit.
// Filtered by hand with texelFetch (bilinear, nearest level, repeat as the
// scene's sampler): lavapipe (Mesa 22.3) crashes compiling textureLod or
// textureGrad on a dynamically indexed texture array in a compute shader, and
// its texture() on that array in the geometry-shader voxelizer's fragment
// shader sampled a material's texture wrong (white over a half-black one).
// It also compiles every fetch site of such an array as a switch over all
// MAX_TEXTURES slots (8 sites took 44 s to compile), so the four taps share
// one site in a loop of `materialTaps` (4, from a push constant the compiler
// cannot see, so it does not unroll them), and callers call this once.
// The texture's size comes with its material (GpuMaterial::textureSizes):
// lavapipe answered textureSize on the array with another texture's size for
// some invocations, so texels were fetched where that size put them (Sponza's
// floor voxels 6 % too bright and unrelated to its pattern).
float materialUvDensity = 0.0;
uint materialTaps = 4u;

vec4 sampleTexture(int index, ivec2 size0, vec2 uv) {
    size0 = max(size0, ivec2(1));
    int levels = int(floor(log2(float(max(size0.x, size0.y))))) + 1;  // SceneGpu builds full chains
    float lod = 0.5 * log2(max(materialUvDensity * float(size0.x) * float(size0.y), 1e-20));
    int level = int(clamp(round(lod), 0.0, float(levels - 1)));
    ivec2 size = max(size0 >> level, ivec2(1));
    vec2 st = uv * vec2(size) - 0.5;
    vec2 base = floor(st), f = st - base;
    ivec2 i0 = ivec2(base) % size, i1 = (ivec2(base) + 1) % size;
    i0 += ivec2(lessThan(i0, ivec2(0))) * size;
    i1 += ivec2(lessThan(i1, ivec2(0))) * size;
    vec4 sum = vec4(0.0);
    for (uint k = 0u; k < materialTaps; ++k) {
        bvec2 far = bvec2((k & 1u) != 0u, (k & 2u) != 0u);
        vec2 w = mix(1.0 - f, f, vec2(far));
        sum += (w.x * w.y) * texelFetch(sampler2D(textures[index], textureSampler), mix(i0, i1, far), level);
    }
    return sum;
}
#else
vec4 sampleTexture(int index, vec2 uv) {
    return texture(sampler2D(textures[index], textureSampler), uv);
}
#endif

vec4 materialBaseColor(GpuMaterial m, vec2 uv) {
    vec4 c = m.baseColor;
#ifdef MATERIAL_EXPLICIT_LOD
    if (m.textures.x != NO_TEXTURE) c *= sampleTexture(m.textures.x, m.textureSizes.xy, uv);  // sRGB views decode
#else
    if (m.textures.x != NO_TEXTURE) c *= sampleTexture(m.textures.x, uv);  // sRGB views decode
#endif
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
