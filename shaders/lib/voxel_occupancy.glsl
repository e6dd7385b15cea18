// The rays' occupancy bits (BIND_*_RAY_OCCUPANCY): one bit per cell of
// 2^(level + 1) voxels that holds an occupied voxel, set from this frame's
// voxel list by bounce.comp's RAY_NORMALS dispatch, so that a ray crosses an
// empty cell in one step. Needs `grid`, the buffer `rayOccupancy` and
// shared/bounce_pass.h.
#ifndef DVSGI_VOXEL_OCCUPANCY_GLSL
#define DVSGI_VOXEL_OCCUPANCY_GLSL

// The bit of the cell of occupancy level `level` that holds voxel v.
uint rayOccupancyBit(ivec3 v, uint level) {
    uvec3 c = uvec3(v) >> (level + 1u);
    uint m = rayOccupancySide(grid.dims.x, level);
    return c.x + m * (c.y + m * c.z);
}

// Whether the cell of 2^(level + 1) voxels holding voxel v holds no occupied
// voxel (BIND_BOUNCE_RAY_OCCUPANCY, set from this frame's voxels; the
// directional volumes' mips, read before, could still show last frame's).
// `offset`: rayOccupancyOffset of the level.
bool cellEmpty(ivec3 v, uint level, uint offset) {
    uint bit = rayOccupancyBit(v, level);
    return (rayOccupancy[offset + bit / 32u] & (1u << (bit % 32u))) == 0u;
}

// The ray parameter where a ray from p along d (1/d = inv) leaves the box
// [lo, lo + size).
float exitDistance(vec3 p, vec3 inv, vec3 lo, float size) {
    vec3 far = lo + step(vec3(0.0), inv) * size;
    vec3 t = (far - p) * inv;
    return min(t.x, min(t.y, t.z));
}

// Each coarse level's rayOccupancyOffset (level 0's is 0), as voxelRayStep takes them.
uvec4 rayOccupancyOffsets() {
    return uvec4(0u, rayOccupancyOffset(grid.dims.x, 1u), rayOccupancyOffset(grid.dims.x, 2u),
                 rayOccupancyOffset(grid.dims.x, 3u));
}

// The edge of the largest empty cell (16, 8, 4 or 2 voxels) that holds voxel
// v, or 0 where even the 2-voxel cell holds a voxel. `offsets`: rayOccupancyOffsets().
float emptyCellSize(ivec3 v, uvec4 offsets) {
    if (cellEmpty(v, 3u, offsets.w)) return 16.0;
    if (cellEmpty(v, 2u, offsets.z)) return 8.0;
    if (cellEmpty(v, 1u, offsets.y)) return 4.0;
    return cellEmpty(v, 0u, 0u) ? 2.0 : 0.0;
}

#endif
