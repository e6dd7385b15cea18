// Shadow rays through the voxel grid's occupancy (paper section VI-C). Needs
// `grid` and lib/voxel_index.glsl; with VOXEL_TRACE_SKIPS_EMPTY also the
// rays' occupancy bits (lib/voxel_occupancy.glsl), which let a ray cross an
// empty cell in one step and meet exactly the voxels it met step by step.

// Visibility in [0, 1] from world position P toward the light along L, up to
// `dist` metres. Hard: 0 at the first occupied voxel. Soft: nu += (1 - nu) *
// kappa / t for every occupied voxel met, t = distance in voxels; returns 1 - nu.
float voxelRayVisibility(vec3 P, vec3 L, float dist, bool soft, float kappa) {
    float s = grid.originSize.w;
    int N = int(grid.dims.x);
    vec3 p = (P - grid.originSize.xyz) / s;  // voxel units
    ivec3 self = ivec3(floor(p));
    float maxT = min(dist / s, 2.0 * float(N));
    float nu = 0.0;
    ivec3 last = self;
#ifdef VOXEL_TRACE_SKIPS_EMPTY
    uvec4 offsets = rayOccupancyOffsets();
    vec3 inv = 1.0 / mix(L, vec3(1e-7), lessThan(abs(L), vec3(1e-7)));
#endif
    // Half-voxel steps visit every voxel the ray crosses closely enough for a
    // coarse occlusion test; each voxel counts once.
    for (float t = 1.0; t < maxT; t += 0.5) {
        ivec3 v = ivec3(floor(p + L * t));
        if (any(lessThan(v, ivec3(0))) || any(greaterThanEqual(v, ivec3(N)))) break;
#ifdef VOXEL_TRACE_SKIPS_EMPTY
        // No step inside an empty cell can meet a voxel: on to the last step
        // before the cell's exit (a thousandth of a voxel early, so that float
        // error never skips the step at the exit), which the loop advances.
        float size = emptyCellSize(v, offsets);
        if (size > 0.0) {
            float exit = exitDistance(p, inv, floor(vec3(v) / size) * size, size);
            t = max(t, 0.5 + 0.5 * ceil(2.0 * (exit - 1.0) - 1e-3));
            continue;
        }
#endif
        if (v == last || v == self) continue;
        last = v;
        if (!voxelOccupied(v)) continue;
        if (!soft) return 0.0;
        nu += (1.0 - nu) * min(kappa / t, 1.0);
        if (nu > 0.999) return 0.0;
    }
    return 1.0 - nu;
}
