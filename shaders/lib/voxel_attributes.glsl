// Averages of the accumulated voxel attributes. Needs `grid` (VoxelGrid) and
// `accum` (r32f image3D) declared by the including shader.

float voxelChannel(ivec3 v, uint channel) {
    return imageLoad(accum, v + ivec3(0, 0, int(channel * grid.dims.x))).r;
}

float voxelCount(ivec3 v) { return voxelChannel(v, CH_COUNT); }

vec3 voxelAlbedo(ivec3 v) {
    float n = max(voxelCount(v), 1e-20);
    return vec3(voxelChannel(v, CH_ALBEDO_R), voxelChannel(v, CH_ALBEDO_G), voxelChannel(v, CH_ALBEDO_B)) / n;
}

vec3 voxelEmission(ivec3 v) {
    float n = max(voxelCount(v), 1e-20);
    return vec3(voxelChannel(v, CH_EMISSION_R), voxelChannel(v, CH_EMISSION_G), voxelChannel(v, CH_EMISSION_B)) / n;
}

// Per-axis normal weights: pos.a = mean of n_a^2 over fragments with n_a > 0.
void voxelNormalWeights(ivec3 v, out vec3 pos, out vec3 neg) {
    float n = max(voxelCount(v), 1e-20);
    pos = vec3(voxelChannel(v, CH_NORMAL_POS_X), voxelChannel(v, CH_NORMAL_POS_Y), voxelChannel(v, CH_NORMAL_POS_Z)) / n;
    neg = vec3(voxelChannel(v, CH_NORMAL_NEG_X), voxelChannel(v, CH_NORMAL_NEG_Y), voxelChannel(v, CH_NORMAL_NEG_Z)) / n;
}

// A representative unit normal: sqrt of the weights keeps a single surface's
// normal exact; opposite faces cancel along their axis.
vec3 voxelNormal(ivec3 v) {
    vec3 pos, neg;
    voxelNormalWeights(v, pos, neg);
    vec3 n = sqrt(pos) - sqrt(neg);
    float len = length(n);
    return len > 1e-6 ? n / len : vec3(0.0);
}
