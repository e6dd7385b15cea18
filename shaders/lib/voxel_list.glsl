// The occupied-voxel list's entries: packed voxel coordinates.

uint packVoxel(ivec3 v) {
    return uint(v.x) | (uint(v.y) << VOXEL_LIST_COORD_BITS) | (uint(v.z) << (2u * VOXEL_LIST_COORD_BITS));
}

ivec3 unpackVoxel(uint e) {
    uint mask = (1u << VOXEL_LIST_COORD_BITS) - 1u;
    return ivec3(e & mask, (e >> VOXEL_LIST_COORD_BITS) & mask, e >> (2u * VOXEL_LIST_COORD_BITS));
}
