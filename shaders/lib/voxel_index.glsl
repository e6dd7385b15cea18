// The slot index (shared/voxel_data.h). Needs `grid` (VoxelGrid) and the
// VOXEL_INDEX_BLOCK declared by the including shader.

uint voxelIndexOffset(ivec3 v) {
    uint n = grid.dims.x;
    return uint(v.x) + n * (uint(v.y) + n * uint(v.z));
}

uint voxelSlotAt(ivec3 v) { return indexSlot(voxelIndex[voxelIndexOffset(v)]); }

bool voxelOccupied(ivec3 v) { return voxelSlotAt(v) != 0u; }
