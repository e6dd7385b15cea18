// The slot index (shared/voxel_data.h). Needs `grid` (VoxelGrid) and the
// VOXEL_INDEX_BLOCK declared by the including shader.

uint voxelIndexOffset(ivec3 v) {
    uint n = grid.dims.x;
    return uint(v.x) + n * (uint(v.y) + n * uint(v.z));
}

// slot + 1 of an index value, or 0 for an empty voxel (and for the transient
// and overflow values, which own no slot).
uint indexSlot(uint value) {
    uint slot = value & VOXEL_INDEX_SLOT_MASK;
    return slot == VOXEL_INDEX_FULL ? 0u : slot;
}

uint voxelSlotAt(ivec3 v) { return indexSlot(voxelIndex[voxelIndexOffset(v)]); }

bool voxelOccupied(ivec3 v) { return voxelSlotAt(v) != 0u; }
