// Runs triangle sets through the GPU voxelizer and the CPU reference and
// compares the two voxel sets grid by grid.
#pragma once

#include <string>
#include <vector>

#include "vox_helper.h"

namespace dvsgi::test {

// Voxelizes one scene holding every triangle into each grid in turn and sums
// the comparisons; each miss is reported (ADD_FAILURE) with the triangles
// that the reference says touch the voxel. Prints a one-line summary.
CoverageReport runCoverage(const std::vector<WorldTriangle>& tris, const std::vector<vxgi::GridSpec>& grids,
                           const std::string& label, vxgi::VoxelizerKind kind);
// The same for a ready-made scene (its own materials and transforms).
CoverageReport runCoverage(const scene::Scene& scene, const std::vector<vxgi::GridSpec>& grids,
                           const std::string& label, vxgi::VoxelizerKind kind);
// Zero misses; the geometry path may over-mark only next to reference voxels
// (its pixel-column depth span and dilation), the exact compute path not at all.
void expectCoverage(const CoverageReport& r, vxgi::VoxelizerKind kind);

using LocalTriangle = std::array<glm::dvec3, 3>;

// Lays triangles out one per cell of edge `pitch` voxels, cells packed into
// grids of N^3 voxels of edge 1 tiling world space with integer origins, so
// lattice-aligned local coordinates stay lattice-aligned. Each triangle's
// bounding box must lie within [2, pitch - 2] of its cell: the voxels it may
// mark, extras included, then stay inside the cell.
struct Packing {
    std::vector<WorldTriangle> tris;
    std::vector<vxgi::GridSpec> grids;
    void add(const std::vector<LocalTriangle>& local, uint32_t pitch, uint32_t n);
};

// Deterministic on every platform (unlike the standard distributions).
struct Rng {
    uint64_t state;
    explicit Rng(uint64_t seed) : state(seed * 0x9E3779B97F4A7C15ull + 1) {}
    uint32_t next() {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return uint32_t(state >> 33);
    }
    double uniform() { return double(next()) / 2147483648.0; }  // [0, 1)
    double range(double a, double b) { return a + (b - a) * uniform(); }
    glm::dvec3 unitVector();
};

}  // namespace dvsgi::test
