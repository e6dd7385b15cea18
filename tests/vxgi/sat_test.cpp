// The CPU reference itself, on cases whose answer is known by construction.
#include <cmath>

#include <gtest/gtest.h>

#include "sat.h"

namespace dvsgi::test {
namespace {

const glm::dvec3 kMin(0.0), kMax(1.0);

Triangle tri(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) { return Triangle{{a, b, c}}; }

TEST(Sat, TriangleInsideBox) {
    EXPECT_TRUE(triangleBoxOverlap(tri({0.2, 0.2, 0.3}, {0.8, 0.3, 0.5}, {0.4, 0.7, 0.6}), kMin, kMax));
}

TEST(Sat, BoxInsideLargeTriangle) {
    // No vertex in the box and no box corner on the triangle's side of things:
    // only the face test can see the overlap.
    EXPECT_TRUE(triangleBoxOverlap(tri({-10, -10, 0.5}, {10, -10, 0.5}, {0, 10, 0.5}), kMin, kMax));
    EXPECT_TRUE(triangleBoxOverlap(tri({-10, -10, -9}, {10, -10, 11}, {0, 10, 0.5}), kMin, kMax));
}

TEST(Sat, CrossingACorner) {
    // Cuts off the (1,1,1) corner: plane x + y + z = 2.9.
    EXPECT_TRUE(triangleBoxOverlap(tri({2.9, 0, 0}, {0, 2.9, 0}, {0, 0, 2.9}), kMin, kMax));
    // Through the corner point exactly.
    EXPECT_TRUE(triangleBoxOverlap(tri({3, 0, 0}, {0, 3, 0}, {0, 0, 3}), kMin, kMax));
    // Just beyond the corner.
    EXPECT_FALSE(triangleBoxOverlap(tri({3.001, 0, 0}, {0, 3.001, 0}, {0, 0, 3.001}), kMin, kMax));
}

TEST(Sat, TouchingAFace) {
    // A vertex on the face x = 1, the rest outside.
    EXPECT_TRUE(triangleBoxOverlap(tri({1, 0.5, 0.5}, {2, 0.2, 0.5}, {2, 0.8, 0.9}), kMin, kMax));
    // An edge lying on the face.
    EXPECT_TRUE(triangleBoxOverlap(tri({1, 0.2, 0.2}, {1, 0.8, 0.7}, {3, 0.5, 0.5}), kMin, kMax));
    // Touching only the box's edge (x = 1, y = 1) with a vertex.
    EXPECT_TRUE(triangleBoxOverlap(tri({1, 1, 0.5}, {2, 1.5, 0.5}, {1.5, 2, 0.7}), kMin, kMax));
}

TEST(Sat, JustMissing) {
    EXPECT_FALSE(triangleBoxOverlap(tri({1.001, 0.5, 0.5}, {2, 0.2, 0.5}, {2, 0.8, 0.9}), kMin, kMax));
    // An edge passing 1e-3 beyond the box's edge x = y = 1 while the triangle
    // leans away from it: only the cross product of the two edges separates.
    const double d = 1e-3 * std::sqrt(2.0);
    EXPECT_FALSE(triangleBoxOverlap(tri({2 + d, 0, 0.5}, {0, 2 + d, 0.5}, {3, 3, 5}), kMin, kMax));
    EXPECT_TRUE(triangleBoxOverlap(tri({2, 0, 0.5}, {0, 2, 0.5}, {3, 3, 5}), kMin, kMax));
    // A plane that clears the (1,1,1) corner while its vertices' bounding box
    // overlaps the box: only the normal separates.
    EXPECT_FALSE(triangleBoxOverlap(tri({3.003, 0, 0}, {0, 3.003, 0}, {0, 0, 3.003}), kMin, kMax));
}

TEST(Sat, ParallelToAFace) {
    // In the plane z = 1 (the box's top face) and crossing it: overlap.
    EXPECT_TRUE(triangleBoxOverlap(tri({-1, -1, 1}, {3, -1, 1}, {-1, 3, 1}), kMin, kMax));
    EXPECT_TRUE(triangleBoxOverlap(tri({0.2, 0.2, 0}, {0.8, 0.2, 0}, {0.2, 0.8, 0}), kMin, kMax));
    // 1e-3 above it: no overlap.
    EXPECT_FALSE(triangleBoxOverlap(tri({-1, -1, 1.001}, {3, -1, 1.001}, {-1, 3, 1.001}), kMin, kMax));
    EXPECT_FALSE(triangleBoxOverlap(tri({0.2, 0.2, -0.001}, {0.8, 0.2, -0.001}, {0.2, 0.8, -0.001}), kMin, kMax));
}

TEST(Sat, NonUnitBoxes) {
    const glm::dvec3 lo(4, 5, 6), hi(6, 6, 9);
    EXPECT_TRUE(triangleBoxOverlap(tri({5, 5.5, 0}, {5, 5.5, 20}, {5.1, 5.6, 10}), lo, hi));
    EXPECT_FALSE(triangleBoxOverlap(tri({5, 6.001, 0}, {5, 6.001, 20}, {5.1, 7, 10}), lo, hi));
}

TEST(Sat, ReferenceVoxelizer) {
    // A triangle in the plane z = 10 marks the layers on both sides of it.
    VoxelSet s = referenceVoxelize({tri({2.5, 2.5, 10}, {3.5, 2.5, 10}, {2.5, 3.5, 10})}, 16);
    EXPECT_EQ(s.count(), 2u * 4u);  // columns (2..3) x (2..3): the hypotenuse touches (3,3) at a point
    EXPECT_TRUE(s.get(2, 2, 9) && s.get(2, 2, 10) && s.get(3, 3, 9) && s.get(3, 3, 10));
    // A vertex on a lattice point touches all eight voxels around it.
    VoxelSet c = referenceVoxelize({tri({5, 5, 5}, {5.3, 5.1, 5.2}, {5.1, 5.4, 5.05})}, 16);
    EXPECT_EQ(c.count(), 8u);
    // Clipped by the grid.
    VoxelSet o = referenceVoxelize({tri({-5, 0.5, 0.5}, {20, 0.5, 0.5}, {-5, 0.6, 0.5})}, 16);
    EXPECT_EQ(o.count(), 16u);
}

TEST(Sat, CompareCoverage) {
    VoxelSet ref(8), gpu(8);
    ref.set(3, 3, 3);
    gpu.set(3, 3, 3);
    gpu.set(4, 4, 4);  // extra, near
    gpu.set(6, 6, 6);  // extra, far
    ref.set(1, 1, 1);  // miss
    const CoverageReport r = compareCoverage(ref, gpu);
    EXPECT_EQ(r.misses, 1u);
    EXPECT_EQ(r.extras, 2u);
    EXPECT_EQ(r.farExtras, 1u);
}

}  // namespace
}  // namespace dvsgi::test
