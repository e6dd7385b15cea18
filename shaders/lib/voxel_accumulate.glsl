// Adding one fragment's material to a voxel of the attribute volume: shared by
// every voxelizer so they store exactly the same sums. Needs `grid`
// (VoxelGrid), `accum` (r32f image3D, coherent) and `flags` (r8ui uimage3D)
// declared by the including shader, the occupied-voxel list `list` and
// lib/voxel_list.glsl, and GL_EXT_shader_atomic_float.

void accumulateChannel(ivec3 voxel, uint channel, float value) {
    if (value != 0.0) imageAtomicAdd(accum, voxel + ivec3(0, 0, int(channel * grid.dims.x)), value);
}

// Static voxelization flags what it writes; dynamic voxelization leaves
// static voxels alone (they are cleared only when static geometry changes).
// The fragment that finds the voxel empty appends it to the occupied-voxel
// list (exactly one does: the count's atomic add returns what was there).
// Returns false when the voxel was skipped.
bool accumulateFragment(ivec3 voxel, uint mode, vec3 albedo, vec3 emission, vec3 n) {
    if (mode == VOXELIZE_DYNAMIC) {
        if (imageLoad(flags, voxel).r == VOXEL_FLAG_STATIC) return false;
    } else {
        imageStore(flags, voxel, uvec4(VOXEL_FLAG_STATIC));
    }
    accumulateChannel(voxel, CH_ALBEDO_R, albedo.r);
    accumulateChannel(voxel, CH_ALBEDO_G, albedo.g);
    accumulateChannel(voxel, CH_ALBEDO_B, albedo.b);
    if (imageAtomicAdd(accum, voxel + ivec3(0, 0, int(CH_COUNT * grid.dims.x)), 1.0) == 0.0) appendVoxel(voxel);
    accumulateChannel(voxel, CH_EMISSION_R, emission.r);
    accumulateChannel(voxel, CH_EMISSION_G, emission.g);
    accumulateChannel(voxel, CH_EMISSION_B, emission.b);
    vec3 n2 = n * n;
    accumulateChannel(voxel, CH_NORMAL_POS_X, n.x > 0.0 ? n2.x : 0.0);
    accumulateChannel(voxel, CH_NORMAL_NEG_X, n.x < 0.0 ? n2.x : 0.0);
    accumulateChannel(voxel, CH_NORMAL_POS_Y, n.y > 0.0 ? n2.y : 0.0);
    accumulateChannel(voxel, CH_NORMAL_NEG_Y, n.y < 0.0 ? n2.y : 0.0);
    accumulateChannel(voxel, CH_NORMAL_POS_Z, n.z > 0.0 ? n2.z : 0.0);
    accumulateChannel(voxel, CH_NORMAL_NEG_Z, n.z < 0.0 ? n2.z : 0.0);
    return true;
}
