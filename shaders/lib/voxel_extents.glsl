// The box a voxel's surface covers, from its extents (shared/voxel_data.h):
// per axis, from the lowest eighth reached to the highest. Needs the
// extents block `voxelExtents` (VOXEL_EXTENTS_BLOCK).
#ifndef DVSGI_LIB_VOXEL_EXTENTS_GLSL
#define DVSGI_LIB_VOXEL_EXTENTS_GLSL

// The box in voxel units (grid coordinates); a voxel with no bits along an
// axis (the pv voxelizer's) covers that axis whole.
void extentBox(ivec3 c, uint bits, out vec3 lo, out vec3 hi) {
    for (int k = 0; k < 3; ++k) {
        uint m = (bits >> (VOXEL_EXTENT_STEPS * uint(k))) & 0xffu;
        if (m == 0u) m = 0xffu;
        lo[k] = float(c[k]) + float(findLSB(m)) / float(VOXEL_EXTENT_STEPS);
        hi[k] = float(c[k]) + float(findMSB(m) + 1) / float(VOXEL_EXTENT_STEPS);
    }
}

#endif
