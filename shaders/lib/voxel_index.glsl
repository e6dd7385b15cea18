// The slot index (shared/voxel_data.h). Needs `grid` (VoxelGrid) and the
// VOXEL_INDEX_BLOCK declared by the including shader.

#include "lib/voxel_window.glsl"

// The index word of grid voxel v (stored toroidally: lib/voxel_window.glsl).
uint voxelIndexOffset(ivec3 v) {
    uint n = grid.dims.x;
    uvec3 s = uvec3(storageVoxel(v));
    return s.x + n * (s.y + n * s.z);
}

uint voxelSlotAt(ivec3 v) { return indexSlot(voxelIndex[voxelIndexOffset(v)]); }

bool voxelOccupied(ivec3 v) { return voxelSlotAt(v) != 0u; }
