// CPU reference for conservative voxelization: an exact triangle / closed box
// overlap test by the separating-axis theorem, and the voxel set it implies.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace dvsgi::test {

struct Triangle {
    glm::dvec3 v[3];
};

// True when the triangle and the closed box [boxMin, boxMax] share a point.
// Double precision; touching (a shared face, edge or corner point) counts.
bool triangleBoxOverlap(const Triangle& t, const glm::dvec3& boxMin, const glm::dvec3& boxMax);

// Voxel sets on an N^3 grid with origin 0 and voxel edge 1.
struct VoxelSet {
    explicit VoxelSet(uint32_t n = 0) : n(n), bits(size_t(n) * n * n, 0) {}
    uint32_t n;
    std::vector<uint8_t> bits;  // x fastest, then y, then z

    size_t index(int x, int y, int z) const { return (size_t(z) * n + size_t(y)) * n + size_t(x); }
    bool inside(int x, int y, int z) const {
        return x >= 0 && y >= 0 && z >= 0 && x < int(n) && y < int(n) && z < int(n);
    }
    bool get(int x, int y, int z) const { return inside(x, y, z) && bits[index(x, y, z)] != 0; }
    void set(int x, int y, int z) { bits[index(x, y, z)] = 1; }
    size_t count() const;
};

// Adds every voxel of the grid whose closed unit box, grown by `growth` on
// every side, overlaps the triangle (coordinates in voxel units); voxels
// outside the grid are ignored. The compute voxelizer's boxes are grown by
// shader::VOXC_BOX_GROWTH (kComputeBoxGrowth).
void referenceVoxelize(const Triangle& t, VoxelSet& out, double growth = 0.0);
VoxelSet referenceVoxelize(const std::vector<Triangle>& tris, uint32_t n, double growth = 0.0);
// The same test for a box given by its centre and half-size.
bool triangleBoxOverlapCentred(const Triangle& t, const glm::dvec3& centre, const glm::dvec3& half);

struct CoverageReport {
    size_t reference = 0;  // voxels the reference marks
    size_t gpu = 0;        // voxels the GPU marks
    size_t misses = 0;     // marked by the reference, not by the GPU
    size_t extras = 0;     // marked by the GPU, not by the reference
    size_t farExtras = 0;  // extras farther than Chebyshev distance 1 from every reference voxel
    std::vector<glm::ivec3> missList, farList;  // the first few, for messages
};
CoverageReport compareCoverage(const VoxelSet& reference, const VoxelSet& gpu);

}  // namespace dvsgi::test
