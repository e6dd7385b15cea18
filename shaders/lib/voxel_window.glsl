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

#endif
