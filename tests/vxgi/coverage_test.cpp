// Conservative coverage of single triangles, for both voxelizers: every voxel
// whose closed box the triangle touches must be marked (zero misses). The
// geometry path may over-mark only next to such voxels (the pixel-column depth
// span and the dilation reach at most one voxel further); the compute path's
// exact test marks nothing else (zero extras).
#include <algorithm>
#include <cstdlib>

#include <gtest/gtest.h>

#include "coverage.h"
#include "gpu_fixture.h"

namespace dvsgi::test {
namespace {

class VoxelCoverage : public GpuTest, public ::testing::WithParamInterface<vxgi::VoxelizerKind> {};

// DVSGI_VXGI_STRESS=k runs k times as many random triangles (other seeds too).
int stress() {
    const char* e = std::getenv("DVSGI_VXGI_STRESS");
    return e ? std::max(1, std::atoi(e)) : 1;
}

using dvec3 = glm::dvec3;

// Moves a triangle so its bounding box sits at a random place inside
// [2, pitch - 2]^3; returns the smallest pitch (of those allowed) it fits.
uint32_t placeInCell(LocalTriangle& t, Rng& rng, const std::vector<uint32_t>& pitches) {
    dvec3 lo = glm::min(t[0], glm::min(t[1], t[2])), hi = glm::max(t[0], glm::max(t[1], t[2]));
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    uint32_t pitch = pitches.back();
    for (uint32_t p : pitches)
        if (extent <= double(p) - 4.0) {
            pitch = p;
            break;
        }
    dvec3 offset;
    for (int a = 0; a < 3; ++a) offset[a] = 2.0 - lo[a] + rng.range(0.0, double(pitch) - 4.0 - (hi[a] - lo[a]));
    for (dvec3& v : t) v += offset;
    return pitch;
}

// Triangles sorted into pitch classes, then packed.
struct Batch {
    std::vector<uint32_t> pitches;
    std::vector<std::vector<LocalTriangle>> byPitch;
    explicit Batch(std::vector<uint32_t> p) : pitches(std::move(p)), byPitch(pitches.size()) {}
    void add(LocalTriangle t, Rng& rng) {
        const uint32_t p = placeInCell(t, rng, pitches);
        byPitch[size_t(std::find(pitches.begin(), pitches.end(), p) - pitches.begin())].push_back(t);
    }
    Packing pack(uint32_t n) const {
        Packing packing;
        for (size_t i = 0; i < pitches.size(); ++i) packing.add(byPitch[i], pitches[i], n);
        return packing;
    }
};

LocalTriangle randomTriangle(Rng& rng, double minSize, double maxSize) {
    const double size = minSize * std::pow(maxSize / minSize, rng.uniform());  // log-uniform
    LocalTriangle t;
    for (dvec3& v : t) v = rng.unitVector() * (0.5 * size * rng.range(0.3, 1.0));
    return t;
}

TEST_P(VoxelCoverage, RandomTriangles32) {
    Rng rng(1234 + uint64_t(stress() - 1));
    Batch batch({8, 16, 32});
    for (int i = 0; i < 200 * stress(); ++i) batch.add(randomTriangle(rng, 0.05, 20.0), rng);
    const Packing p = batch.pack(32);
    expectCoverage(runCoverage(p.tris, p.grids, "random, N=32", GetParam()), GetParam());
}

TEST_P(VoxelCoverage, RandomTriangles64) {
    Rng rng(777 + uint64_t(stress() - 1));
    Batch batch({16, 32});
    for (int i = 0; i < 48 * stress(); ++i) batch.add(randomTriangle(rng, 0.05, 20.0), rng);
    const Packing p = batch.pack(64);
    expectCoverage(runCoverage(p.tris, p.grids, "random, N=64", GetParam()), GetParam());
}

// Needles (two long edges, a 0.01-voxel-wide apex) and slivers (one edge of
// 1e-3 voxel), in random orientations and along the axes.
TEST_P(VoxelCoverage, SliversAndNeedles) {
    Rng rng(42 + uint64_t(stress() - 1));
    Batch batch({8, 16, 32});
    for (int i = 0; i < 60 * stress(); ++i) {
        const double length = rng.range(0.5, 20.0);
        dvec3 d = rng.unitVector(), u = rng.unitVector();
        if (i % 3 == 2) {  // axis-aligned: long edge along an axis, in an axis plane
            d = dvec3(0.0);
            d[(i / 3) % 3] = 1.0;
            u = dvec3(0.0);
            u[((i / 3) + 1) % 3] = 1.0;
        }
        u = glm::normalize(u - d * glm::dot(u, d));
        const dvec3 a = -d * (0.5 * length), b = d * (0.5 * length);
        LocalTriangle t;
        if (i % 2 == 0)
            t = {a, b, rng.range(-0.4, 0.4) * length * d + u * 0.01};  // needle: apex 0.01 off the long edge
        else
            t = {a, b, b + u * 1e-3};  // sliver: one edge of 1e-3
        batch.add(t, rng);
    }
    // Axis-aligned needles on voxel faces (cell offsets are integers, so local
    // integer coordinates stay on the lattice).
    std::vector<LocalTriangle> onFaces = {
        {dvec3(2, 5, 7), dvec3(14, 5, 7), dvec3(8, 5.01, 7)},
        {dvec3(2, 5.5, 7), dvec3(14, 5.5, 7), dvec3(8, 5.51, 7)},
        {dvec3(5, 2, 7), dvec3(5, 14, 7), dvec3(5, 8, 7.01)},
        {dvec3(5, 7, 2), dvec3(5, 7, 14), dvec3(5.001, 7, 14)},
        {dvec3(3, 3, 3), dvec3(13, 13, 13), dvec3(13, 13, 13.01)},
    };
    Packing p = batch.pack(32);
    p.add(onFaces, 16, 32);
    expectCoverage(runCoverage(p.tris, p.grids, "slivers and needles, N=32", GetParam()), GetParam());
}

std::vector<LocalTriangle> latticeTriangles(Rng& rng) {
    std::vector<LocalTriangle> out;
    for (int axis = 0; axis < 3; ++axis) {
        auto inPlane = [&](double plane, double u0, double v0, double u1, double v1, double u2, double v2) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            LocalTriangle t;
            const double uv[3][2] = {{u0, v0}, {u1, v1}, {u2, v2}};
            for (int k = 0; k < 3; ++k) {
                t[size_t(k)][axis] = plane;
                t[size_t(k)][u] = uv[k][0];
                t[size_t(k)][v] = uv[k][1];
            }
            out.push_back(t);
        };
        // On a voxel face, random shapes.
        for (int i = 0; i < 4; ++i)
            inPlane(8.0, rng.range(2, 14), rng.range(2, 14), rng.range(2, 14), rng.range(2, 14), rng.range(2, 14),
                    rng.range(2, 14));
        // On a voxel face with edges on voxel edges.
        inPlane(8.0, 3, 3, 12, 3, 3, 12);
        inPlane(8.0, 12, 12, 3, 12, 12, 3);
        inPlane(8.0, 3, 3, 12, 4, 5, 12);
        // Exactly half of one voxel face, and a triangle inside one face.
        inPlane(8.0, 5, 5, 6, 5, 5, 6);
        inPlane(8.0, 5.2, 5.2, 5.8, 5.2, 5.2, 5.8);
        // Mid-layer, with legs on voxel faces of the other axes.
        inPlane(8.5, 3, 3, 12, 3, 3, 12);
        inPlane(8.5, 4, 4, 11, 4, 4, 11.5);
    }
    // Planes through voxel edges: x = y holds the z-aligned voxel edges.
    out.push_back({dvec3(3, 3, 3), dvec3(12, 12, 3), dvec3(3, 3, 12)});
    out.push_back({dvec3(3, 3, 3), dvec3(12, 12, 5), dvec3(6, 6, 12)});
    out.push_back({dvec3(3, 12, 4), dvec3(12, 3, 4), dvec3(7, 8, 12)});
    // One edge on a voxel edge, the plane tilted.
    out.push_back({dvec3(3, 4, 4), dvec3(12, 4, 4), dvec3(7, 9.3, 11.1)});
    out.push_back({dvec3(4, 3, 4), dvec3(4, 12, 4), dvec3(11.2, 6, 9.7)});
    // Vertices on lattice points, general plane.
    out.push_back({dvec3(3, 3, 3), dvec3(12, 5, 4), dvec3(4, 11, 12)});
    out.push_back({dvec3(3, 3, 3), dvec3(5, 4, 3), dvec3(3, 5, 4)});
    // A vertex on a lattice point: touches all eight voxels around it.
    out.push_back({dvec3(5, 5, 5), dvec3(5.3, 5.1, 5.2), dvec3(5.1, 5.4, 5.05)});
    out.push_back({dvec3(5, 5, 5), dvec3(4.7, 5.1, 4.8), dvec3(4.9, 4.6, 5.05)});
    // 45-degree planes: the dominant axis is a tie.
    out.push_back({dvec3(3, 3, 3), dvec3(12, 3, 12), dvec3(3, 12, 3)});
    out.push_back({dvec3(3, 3, 3), dvec3(12, 12, 12), dvec3(3, 12, 3)});
    return out;
}

TEST_P(VoxelCoverage, LatticeAligned32) {
    Rng rng(5);
    Packing p;
    p.add(latticeTriangles(rng), 16, 32);
    expectCoverage(runCoverage(p.tris, p.grids, "lattice-aligned, N=32", GetParam()), GetParam());
}

TEST_P(VoxelCoverage, LatticeAligned64) {
    Rng rng(6);
    Packing p;
    p.add(latticeTriangles(rng), 16, 64);
    expectCoverage(runCoverage(p.tris, p.grids, "lattice-aligned, N=64", GetParam()), GetParam());
}

TEST_P(VoxelCoverage, PartlyOutsideTheGrid) {
    Rng rng(9);
    // One triangle across each corner of a 32^3 grid: two vertices up to 12
    // voxels inside, one outside beyond the corner; the octants keep them apart.
    std::vector<WorldTriangle> corners;
    for (int c = 0; c < 8; ++c) {
        const dvec3 corner(32.0 * (c & 1), 32.0 * ((c >> 1) & 1), 32.0 * ((c >> 2) & 1));
        const dvec3 inward(c & 1 ? -1 : 1, (c >> 1) & 1 ? -1 : 1, (c >> 2) & 1 ? -1 : 1);
        WorldTriangle t;
        for (int k = 0; k < 3; ++k) {
            const dvec3 d(rng.range(1, 12), rng.range(1, 12), rng.range(1, 12));
            t[size_t(k)] = glm::vec3(corner + (k < 2 ? inward : -inward) * d);
        }
        corners.push_back(t);
    }
    // Across single faces (x = 0, y = 32, z = 32), away from the corners.
    corners.push_back({glm::vec3(-6, 14, 14), glm::vec3(5, 16, 15.5f), glm::vec3(-3, 18.5f, 17)});
    corners.push_back({glm::vec3(14, 37, 15), glm::vec3(17.5f, 27.25f, 14), glm::vec3(16, 35, 18.5f)});
    corners.push_back({glm::vec3(15, 15, 40), glm::vec3(18, 16, 27), glm::vec3(16, 18.5f, 29)});
    const vxgi::GridSpec grid = exactGrid(glm::vec3(0.0f), 1.0f, 32);
    expectCoverage(runCoverage(corners, {grid}, "partly outside, N=32", GetParam()), GetParam());

    // Larger than the grid: all vertices outside, the interior crossing it.
    const std::vector<WorldTriangle> huge = {
        {glm::vec3(-40, -30, 5.3f), glm::vec3(90, -20, 20.7f), glm::vec3(10, 80, 30.1f)},
    };
    expectCoverage(runCoverage(huge, {grid}, "larger than the grid, N=32", GetParam()), GetParam());
}

INSTANTIATE_TEST_SUITE_P(Voxelizers, VoxelCoverage, ::testing::ValuesIn(kVoxelizers), voxelizerTestName);

}  // namespace
}  // namespace dvsgi::test
