// After a clipmap scroll the compute voxelizer leaves out triangle groups that
// cannot reach the exposed slabs (vxgi::groupReachesWrittenVoxels). Checked on
// hand-picked boxes, and on random groups of random triangles under random
// transforms and scrolls against the test voxelize.comp applies to each
// triangle (loadTriangle: its closed voxel box, then rangeKeptByScroll); the
// clipmap tests (ClipmapScroll.*) check that a scrolled level still equals one
// voxelized afresh, voxel for voxel.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "shared/voxelize_compute_pass.h"

#include "vxgi/volumes.h"
#include "vxgi/voxelize_compute.h"

namespace dvsgi::vxgi {
namespace {

// A 32^3 grid of 0.1 m voxels at the origin.
GridSpec grid32() {
    GridSpec g;
    g.origin = glm::vec3(0.0f);
    g.voxelSize = 0.1f;
    g.n = 32;
    return g;
}

// Voxels [lo, hi] (whole voxels) as world bounds.
bool reaches(glm::vec3 lo, glm::vec3 hi, glm::ivec4 keep) {
    return groupReachesWrittenVoxels(lo * 0.1f, (hi + 1.0f) * 0.1f, grid32(), keep);
}

TEST(ScrollCull, WithoutAScrollEveryGroupOnTheGridIsVoxelized) {
    const glm::ivec4 none(0);
    EXPECT_TRUE(reaches(glm::vec3(10), glm::vec3(12), none));
    EXPECT_TRUE(reaches(glm::vec3(-5), glm::vec3(0), none));    // touches the grid's corner
    EXPECT_FALSE(reaches(glm::vec3(40), glm::vec3(50), none));  // beyond it, past the margin
    EXPECT_FALSE(reaches(glm::vec3(-20), glm::vec3(-6), none));
}

TEST(ScrollCull, AfterAScrollOnlyGroupsNearTheExposedSlabsAre) {
    // The window moved +4 voxels along x: the old window's voxels are kept in
    // [-4, 28) of the new grid, so x in [28, 32) is the exposed slab.
    const glm::ivec4 keep(-4, 0, 0, 1);
    EXPECT_FALSE(reaches(glm::vec3(2, 5, 5), glm::vec3(20, 9, 9), keep));  // well inside the kept box
    EXPECT_TRUE(reaches(glm::vec3(27, 5, 5), glm::vec3(29, 9, 9), keep));  // crosses into the slab
    EXPECT_TRUE(reaches(glm::vec3(30, 5, 5), glm::vec3(31, 9, 9), keep));  // inside the slab
    // Two voxels of margin: a group ending just before the slab is still voxelized.
    EXPECT_TRUE(reaches(glm::vec3(20, 5, 5), glm::vec3(26, 9, 9), keep));
    EXPECT_FALSE(reaches(glm::vec3(20, 5, 5), glm::vec3(24, 9, 9), keep));
    // A move along all three axes exposes three slabs.
    const glm::ivec4 diagonal(2, -3, 5, 1);  // kept: x [2, 34), y [-3, 29), z [5, 37)
    EXPECT_TRUE(reaches(glm::vec3(0, 10, 10), glm::vec3(0, 12, 12), diagonal));   // x below 2
    EXPECT_TRUE(reaches(glm::vec3(10, 30, 10), glm::vec3(12, 31, 12), diagonal)); // y from 29
    EXPECT_TRUE(reaches(glm::vec3(10, 10, 1), glm::vec3(12, 12, 2), diagonal));   // z below 5
    EXPECT_FALSE(reaches(glm::vec3(10, 10, 10), glm::vec3(20, 20, 20), diagonal));
}

// voxelize.comp's loadTriangle: whether static voxelization may write any
// voxel of the triangle (world corners w) on `g` after a scroll that kept `keep`.
bool shaderMayWrite(const glm::vec3 w[3], const GridSpec& g, glm::ivec4 keep) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (int k = 0; k < 3; ++k) {
        const glm::vec3 p = (w[k] - g.origin) / g.voxelSize;
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const int n = int(g.n);
    const glm::ivec3 a = glm::max(glm::ivec3(glm::ceil(lo - shader::VOXC_BOX_GROWTH)) - 1, glm::ivec3(0));
    const glm::ivec3 b = glm::min(glm::ivec3(glm::floor(hi + shader::VOXC_BOX_GROWTH)), glm::ivec3(n - 1));
    if (glm::any(glm::greaterThan(a, b))) return false;
    const glm::ivec3 k(keep);
    return !(keep.w != 0 && glm::all(glm::greaterThanEqual(a, k)) && glm::all(glm::lessThan(b, k + n)));
}

TEST(ScrollCull, NoGroupIsLeftOutThatTheShaderWouldVoxelize) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const GridSpec g = grid32();  // 3.2 m
    int groups = 0, culled = 0, checked = 0;
    for (int trial = 0; trial < 400; ++trial) {
        // A group of 64 triangles within about 0.4 m of a centre, placed by a
        // random rotation, scale and translation around the grid.
        const glm::vec3 axis = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0.0f, 0.0f, 1e-3f));
        const glm::mat4 world = glm::translate(glm::mat4(1.0f), glm::vec3(1.6f) + 2.2f * glm::vec3(u(rng), u(rng), u(rng))) *
                                glm::rotate(glm::mat4(1.0f), 3.2f * u(rng), axis) *
                                glm::scale(glm::mat4(1.0f), glm::vec3(1.0f + 0.8f * u(rng)));
        const glm::vec3 centre = 0.5f * glm::vec3(u(rng), u(rng), u(rng));
        scene::Bounds local;
        std::vector<glm::vec3> worldCorners;
        for (int t = 0; t < int(shader::VOXC_GROUP); ++t)
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 p = centre + 0.2f * glm::vec3(u(rng), u(rng), u(rng));
                local.min = glm::min(local.min, p);
                local.max = glm::max(local.max, p);
                worldCorners.push_back(glm::vec3(world * glm::vec4(p, 1.0f)));
            }
        const glm::ivec4 keep = trial % 4 == 0 ? glm::ivec4(0)
                                               : glm::ivec4(int(6.0f * u(rng)), int(6.0f * u(rng)), int(6.0f * u(rng)), 1);
        glm::vec3 lo, hi;
        chunkWorldBounds(local, world, lo, hi);
        const bool kept = groupReachesWrittenVoxels(lo, hi, g, keep);
        ++groups;
        culled += !kept;
        for (size_t t = 0; t < worldCorners.size(); t += 3) {
            ++checked;
            if (shaderMayWrite(&worldCorners[t], g, keep)) {
                ASSERT_TRUE(kept) << "trial " << trial << ": a triangle the shader voxelizes was left out";
            }
        }
    }
    std::printf("groups %d, left out %d; triangles checked %d\n", groups, culled, checked);
    EXPECT_GT(culled, groups / 10);  // the test leaves some out, or it checks nothing
    EXPECT_LT(culled, groups);
}

TEST(ScrollCull, FarOrUnsetBoundsDoNotOverflow) {
    EXPECT_FALSE(groupReachesWrittenVoxels(glm::vec3(1e30f), glm::vec3(-1e30f), grid32(), glm::ivec4(0)));
    EXPECT_FALSE(groupReachesWrittenVoxels(glm::vec3(1e20f), glm::vec3(2e20f), grid32(), glm::ivec4(0)));
    EXPECT_TRUE(groupReachesWrittenVoxels(glm::vec3(-1e20f), glm::vec3(1e20f), grid32(), glm::ivec4(2, 0, 0, 1)));
}

}  // namespace
}  // namespace dvsgi::vxgi
