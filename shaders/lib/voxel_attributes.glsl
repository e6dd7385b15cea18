// Averages of the accumulated voxel attributes of one slot (shared/voxel_data.h).
// Needs `accum` (r32f image3D) declared by the including shader.

float voxelChannel(uint slot, uint channel) { return imageLoad(accum, slotTexel(slot, channel)).r; }

float voxelCount(uint slot) { return voxelChannel(slot, CH_COUNT); }

vec3 voxelAlbedo(uint slot) {
    float n = max(voxelCount(slot), 1e-20);
    return vec3(voxelChannel(slot, CH_ALBEDO_R), voxelChannel(slot, CH_ALBEDO_G), voxelChannel(slot, CH_ALBEDO_B)) / n;
}

vec3 voxelEmission(uint slot) {
    float n = max(voxelCount(slot), 1e-20);
    return vec3(voxelChannel(slot, CH_EMISSION_R), voxelChannel(slot, CH_EMISSION_G),
                voxelChannel(slot, CH_EMISSION_B)) / n;
}

// Per-axis sums of n_a^2 over the fragments with n_a > 0 (pos) and n_a < 0 (neg).
void voxelNormalSums(uint slot, out vec3 pos, out vec3 neg) {
    pos = vec3(voxelChannel(slot, CH_NORMAL_POS_X), voxelChannel(slot, CH_NORMAL_POS_Y),
               voxelChannel(slot, CH_NORMAL_POS_Z));
    neg = vec3(voxelChannel(slot, CH_NORMAL_NEG_X), voxelChannel(slot, CH_NORMAL_NEG_Y),
               voxelChannel(slot, CH_NORMAL_NEG_Z));
}

// Per-axis normal weights: pos.a = mean of n_a^2 over fragments with n_a > 0.
void voxelNormalWeights(uint slot, out vec3 pos, out vec3 neg) {
    float n = max(voxelCount(slot), 1e-20);
    voxelNormalSums(slot, pos, neg);
    pos /= n;
    neg /= n;
}

// sqrt(pos) - sqrt(neg) as a unit vector, 0 where opposite faces cancel.
vec3 normalFromWeights(vec3 pos, vec3 neg) {
    vec3 n = sqrt(pos) - sqrt(neg);
    float len = length(n);
    return len > 1e-6 ? n / len : vec3(0.0);
}

// A representative unit normal: sqrt of the weights keeps a single surface's
// normal exact; opposite faces cancel along their axis.
vec3 voxelNormal(uint slot) {
    vec3 pos, neg;
    voxelNormalWeights(slot, pos, neg);
    return normalFromWeights(pos, neg);
}

// voxelNormal from the sums alone: the fragment count scales every weight
// alike and the normalization cancels it, one read fewer.
vec3 voxelNormalDirection(uint slot) {
    vec3 pos, neg;
    voxelNormalSums(slot, pos, neg);
    return normalFromWeights(pos, neg);
}
