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

// Mean of the fragments' normals (CH_FIRST_*).
vec3 voxelFirstMoment(uint slot) {
    float n = max(voxelCount(slot), 1e-20);
    return vec3(voxelChannel(slot, CH_FIRST_X), voxelChannel(slot, CH_FIRST_Y), voxelChannel(slot, CH_FIRST_Z)) / n;
}

// How much of the voxel is one plane (1) rather than faces along the axes (0).
// One plane of normal n has pos - neg squared per axis and sqrt(pos) -
// sqrt(neg) = n: its mean normal is as long as that (lp = 1). Faces along
// the axes in shares w_a have a mean normal of length |pos - neg| (la). The
// mean normal's length lm is read as a blend of the two.
float voxelPlaneShare(uint slot, vec3 pos, vec3 neg) {
    float lp = length(sqrt(pos) - sqrt(neg)), la = length(pos - neg), lm = length(voxelFirstMoment(slot));
    return lp - la > 1e-3 ? clamp((lm - la) / (lp - la), 0.0, 1.0) : 1.0;
}

// A one-sided voxel (the side code SIDE_ONE of lib/voxel_sides.glsl) made of
// faces along several axes, an edge or a corner: with --edge-voxels faces lit
// per axis face, and rays see the faces that turn toward them. From its
// normal weights and plane share where the caller has them.
bool showsFaces(vec3 pos, vec3 neg, float planeShare) {
    return !any(greaterThanEqual(min(pos, neg), vec3(TWO_SIDED_MIN_WEIGHT))) && planeShare < FACES_BELOW_PLANE_SHARE;
}
bool voxelShowsFaces(uint slot) {
    vec3 pos, neg;
    voxelNormalWeights(slot, pos, neg);
    return showsFaces(pos, neg, voxelPlaneShare(slot, pos, neg));
}
