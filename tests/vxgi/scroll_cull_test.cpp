// After a clipmap scroll the compute voxelizer leaves out triangle groups that
// cannot reach the exposed slabs (vxgi::groupReachesWrittenVoxels). Checked on
// the host against the rule the shader applies to each triangle; the clipmap
// tests (ClipmapScroll.*) check that a scrolled level still equals one
// voxelized afresh, voxel for voxel.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace dvsgi::vxgi
