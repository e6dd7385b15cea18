// The average Hausdorff distance of the progressive-voxelization tables
// (bench/hausdorff.h) on cases with known answers.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "bench/hausdorff.h"

namespace dvsgi::bench {
namespace {

std::vector<glm::dvec3> planeGrid(double z) {
    std::vector<glm::dvec3> p;
    for (int j = 0; j < 20; ++j)
        for (int i = 0; i < 20; ++i) p.push_back({0.05 * i, 0.05 * j, z});
    return p;
}

TEST(Hausdorff, ShiftedCopyIsItsShiftAway) {
    const Hausdorff h = averageHausdorff(planeGrid(0.0), planeGrid(0.1));
    EXPECT_NEAR(h.surfaceToVoxels, 0.1, 1e-12);
    EXPECT_NEAR(h.voxelsToSurface, 0.1, 1e-12);
    EXPECT_NEAR(h.average(), 0.1, 1e-12);
}

TEST(Hausdorff, AStrayVoxelCountsOnlyFromItsSide) {
    std::vector<glm::dvec3> voxels = planeGrid(0.1);
    voxels.push_back({0.0, 0.0, 1.0});  // 1 m above the nearest sample, (0, 0, 0)
    const Hausdorff h = averageHausdorff(planeGrid(0.0), voxels);
    EXPECT_NEAR(h.surfaceToVoxels, 0.1, 1e-12);
    EXPECT_NEAR(h.voxelsToSurface, (400 * 0.1 + 1.0) / 401.0, 1e-12);
}

// Scattered points against a brute-force search (the k-d tree's back-tracking).
TEST(Hausdorff, MatchesBruteForceOnScatteredPoints) {
    std::vector<glm::dvec3> a, b;
    uint32_t state = 12345u;
    auto next = [&] {
        state = state * 1664525u + 1013904223u;
        return double(state >> 8) / double(1u << 24);
    };
    for (int i = 0; i < 700; ++i) a.push_back({next(), next(), 0.3 * next()});
    for (int i = 0; i < 300; ++i) b.push_back({2.0 * next() - 0.5, next(), next()});
    auto brute = [](const std::vector<glm::dvec3>& from, const std::vector<glm::dvec3>& to) {
        double sum = 0.0;
        for (const glm::dvec3& p : from) {
            double best = 1e30;
            for (const glm::dvec3& q : to) best = std::min(best, glm::distance(p, q));
            sum += best;
        }
        return sum / double(from.size());
    };
    const Hausdorff h = averageHausdorff(a, b);
    EXPECT_NEAR(h.surfaceToVoxels, brute(a, b), 1e-12);
    EXPECT_NEAR(h.voxelsToSurface, brute(b, a), 1e-12);
}

TEST(Hausdorff, NoVoxelsIsInfinitelyFar) {
    EXPECT_TRUE(std::isinf(averageHausdorff(planeGrid(0.0), {}).average()));
}

TEST(Hausdorff, SurfaceSamplesCoverTheTrianglesByArea) {
    scene::Scene s;
    scene::Primitive p;
    // Two triangles: a unit square at z = 0 (area 1) and a triangle of area 0.25 at z = 2.
    for (glm::vec3 v : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(1, 1, 0), glm::vec3(0, 1, 0),
                        glm::vec3(0, 0, 2), glm::vec3(0.5f, 0, 2), glm::vec3(0, 1, 2)}) {
        scene::Vertex vert;
        vert.position = v;
        p.vertices.push_back(vert);
    }
    p.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6};
    s.primitives.push_back(p);
    s.meshes.push_back(scene::Mesh{"m", {0}});
    scene::Node n;
    n.mesh = 0;
    s.nodes.push_back(n);
    s.roots.push_back(0);
    const std::vector<glm::dvec3> pts = surfaceSamples(s, 1250);
    ASSERT_NEAR(double(pts.size()), 1250.0, 1.0);
    size_t low = 0;
    glm::dvec2 mean(0.0);
    for (const glm::dvec3& q : pts) {
        ASSERT_TRUE(q.z == 0.0 || q.z == 2.0);
        ASSERT_GE(q.x, 0.0);
        ASSERT_LE(q.x, 1.0);
        ASSERT_GE(q.y, 0.0);
        ASSERT_LE(q.y, 1.0);
        if (q.z == 0.0) {
            ++low;
            mean += glm::dvec2(q);
        }
    }
    EXPECT_NEAR(double(low), 1000.0, 1.0);  // area 1 of 1.25
    mean /= double(low);
    EXPECT_NEAR(mean.x, 0.5, 0.01);
    EXPECT_NEAR(mean.y, 0.5, 0.01);
}

}  // namespace
}  // namespace dvsgi::bench
