// Grid voxel <-> storage voxel (shared/voxel_data.h, VoxelGrid.wrap). The
// index and the list are stored toroidally so a clipmap level that scrolls
// keeps its voxels where they are; a fitted grid has wrap 0 and the two are
// the same. Needs `grid` (VoxelGrid).
#ifndef DVSGI_LIB_VOXEL_WINDOW_GLSL
#define DVSGI_LIB_VOXEL_WINDOW_GLSL

ivec3 storageVoxel(ivec3 v) { return (v + grid.wrap.xyz) % int(grid.dims.x); }
ivec3 gridVoxel(ivec3 s) {
    int n = int(grid.dims.x);
    return (s - grid.wrap.xyz + n) % n;
}
// A list entry (storage coordinates) as a grid voxel.
ivec3 listVoxel(uint entry) { return gridVoxel(unpackVoxel(entry)); }
// The closed voxel range [a, b] lies wholly in the kept box: a triangle
// whose range it is adds nothing to static voxelization after a scroll, so the
// voxelizers skip it before any per-voxel work.
bool rangeKeptByScroll(ivec3 a, ivec3 b) {
    return grid.keep.w != 0 && all(greaterThanEqual(a, grid.keep.xyz)) &&
           all(lessThan(b, grid.keep.xyz + int(grid.dims.x)));
}
// Static voxelization after a scroll writes only voxels outside the kept box.
bool keptByScroll(ivec3 v) { return rangeKeptByScroll(v, v); }
// Static voxelization after a scroll: narrows the closed range [a, b] to the
// bounding box of its voxels outside the kept box. Where two axes of the range
// lie inside the kept box, only the third's exposed side remains (the slab a
// move along it exposed); otherwise voxels outside lie at every coordinate of
// the range and it stays whole. Call after rangeKeptByScroll said no.
void clipRangeToExposed(inout ivec3 a, inout ivec3 b) {
    if (grid.keep.w == 0) return;
    ivec3 k0 = grid.keep.xyz, k1 = grid.keep.xyz + int(grid.dims.x) - 1;
    bvec3 inside = bvec3(a.x >= k0.x && b.x <= k1.x, a.y >= k0.y && b.y <= k1.y, a.z >= k0.z && b.z <= k1.z);
    for (int i = 0; i < 3; ++i) {
        if (inside[i] || !inside[(i + 1) % 3] || !inside[(i + 2) % 3]) continue;
        // The kept box starts above 0 (exposed below it) or ends below N - 1.
        if (k0[i] > 0) b[i] = min(b[i], k0[i] - 1);
        else a[i] = max(a[i], k1[i] + 1);
    }
}

#endif
