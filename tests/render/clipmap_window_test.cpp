// The clipmap's window arithmetic on the host (vxgi/clipmap.h): windows
// centred on the camera and snapped, negative corners wrapped, the default
// level-0 voxel, the lattice. No GPU.
#include <cmath>
#include <cstdlib>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "vxgi/clipmap.h"

namespace dvsgi::test {
namespace {

TEST(ClipmapWindow, CentredOnTheCameraAndSnapped) {
    static_assert(vxgi::kClipSnapVoxels == 8, "the cases below assume steps of 8 voxels");
    // Voxel 0.5: the camera at x = 10.2 is in voxel 20; 20 - 16 = 4 rounds to 8.
    EXPECT_EQ(vxgi::clipWindowMin(glm::vec3(10.2f, -0.1f, -7.9f), glm::vec3(0.0f), 0.5f, 32), glm::ivec3(8, -16, -32));
    // Half a snap step either way rounds to the nearest multiple.
    EXPECT_EQ(vxgi::clipWindowMin(glm::vec3(0.9f, 0.0f, 1.1f), glm::vec3(0.0f), 0.5f, 32).x, -16);  // voxel 1: -15 -> -16
    EXPECT_EQ(vxgi::clipWindowMin(glm::vec3(2.1f, 0.0f, 0.0f), glm::vec3(0.0f), 0.5f, 32).x, -8);   // voxel 4: -12 -> -8
    for (float x = -20.0f; x < 20.0f; x += 0.37f) {
        const glm::ivec3 m = vxgi::clipWindowMin(glm::vec3(x), glm::vec3(0.0f), 0.25f, 64);
        EXPECT_EQ(m.x % vxgi::kClipSnapVoxels, 0);
        // The camera stays within a snap step of the window's centre.
        EXPECT_LE(std::abs(x / 0.25f - float(m.x + 32)), float(vxgi::kClipSnapVoxels / 2) + 1.0f) << x;
    }
}

TEST(ClipmapWindow, GridWrapsNegativeCornersIntoTheVolume) {
    const vxgi::GridSpec g = vxgi::clipLevelGrid(glm::ivec3(-36, 0, 40), glm::vec3(0.125f, 0.0f, 0.0f), 0.25f, 32);
    EXPECT_EQ(g.wrap, glm::ivec3(28, 0, 8));
    EXPECT_EQ(g.origin, glm::vec3(-8.875f, 0.0f, 10.0f));
    EXPECT_EQ(g.voxelSize, 0.25f);
    scene::Bounds b;
    b.min = glm::vec3(-10.0f, 0.0f, -2.0f);
    b.max = glm::vec3(10.0f, 3.0f, 2.0f);
    // The coarsest of 3 levels spans twice the longest side: 32 x 4 x s0 = 40 m.
    EXPECT_FLOAT_EQ(vxgi::clipBaseVoxelSize(b, 32, 3, glm::vec3(1.0f, 1.0f, 0.0f)), 40.0f / 128.0f);
    // The lattice puts the lower bounds at voxel centres: -10 = 0.125 + (k + 0.5) 0.25 for whole k.
    const glm::vec3 lattice = vxgi::clipLattice(b, 0.25f);
    for (int a = 0; a < 3; ++a) {
        const float k = (b.min[a] - lattice[a]) / 0.25f - 0.5f;
        EXPECT_NEAR(k, std::round(k), 1e-4f) << a;
        EXPECT_GE(lattice[a], 0.0f);
        EXPECT_LT(lattice[a], 0.25f);
    }
}

// A camera outside the scene, as a Cornell box's camera in front of its open
// side: the default coarsest window still holds the whole scene, wherever the
// snapping puts it; from inside, it is twice the longest side, up to the
// spare voxels' share where the camera stands near one end.
TEST(ClipmapWindow, DefaultCoarsestWindowHoldsTheSceneFromOutsideIt) {
    scene::Bounds b;
    b.min = glm::vec3(0.0f);
    b.max = glm::vec3(0.56f, 0.55f, 0.56f);
    int outside = 0;
    for (uint32_t n : {32u, 64u, 128u})
        for (uint32_t levels : {1u, 2u, 3u})
            for (float z = -2.0f; z <= 0.8f; z += 0.13f)
                for (float x = -0.4f; x <= 1.0f; x += 0.35f) {
                    const glm::vec3 eye(x, 0.27f, z);
                    const float v = vxgi::clipBaseVoxelSize(b, n, levels, eye);
                    const glm::vec3 lattice = vxgi::clipLattice(b, v);
                    EXPECT_TRUE(vxgi::clipCoarsestHolds(b, eye, lattice, v, n, levels))
                        << "N " << n << ", " << levels << " levels, eye " << x << ", " << z;
                    const bool inside = glm::all(glm::greaterThanEqual(eye, b.min)) &&
                                        glm::all(glm::lessThanEqual(eye, b.max));
                    if (inside) {
                        // At most the spare voxels' share coarser than twice the longest side.
                        const float spare = float(n) / (float(n) - 2.0f * float(vxgi::clipSpareVoxels(n)));
                        EXPECT_LE(v, 2.0f * 0.56f / (float(n) * float(1u << (levels - 1))) * spare * 1.0001f);
                    } else {
                        ++outside;
                    }
                }
    EXPECT_GT(outside, 100);
    // A given voxel too small for the camera's distance: the check says so.
    const glm::vec3 eye(0.28f, 0.27f, -0.76f);
    EXPECT_FALSE(vxgi::clipCoarsestHolds(b, eye, vxgi::clipLattice(b, 0.01f), 0.01f, 64, 1));
}

}  // namespace
}  // namespace dvsgi::test
