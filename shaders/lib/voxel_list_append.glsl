// Appending to the occupied-voxel list. Needs lib/voxel_list.glsl and a
// writable buffer block `list` { VoxelListHeader header; uint entries[]; }.

void appendVoxel(ivec3 v) {
    uint i = atomicAdd(list.header.counts.x, 1u);
    // Capacity is N^3, so this only guards memory; the count of drops is kept for the host.
    if (i < list.header.counts.z) list.entries[i] = packVoxel(v);
    else atomicAdd(list.header.counts.w, 1u);
}
