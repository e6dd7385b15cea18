// Static voxels are written once; dynamic ones are cleared and re-voxelized
// every frame without disturbing the static ones.
#include <cstring>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "vox_helper.h"

namespace dvsgi::test {
namespace {

namespace sh = dvsgi::shader;

class VoxelDynamic : public GpuTest, public ::testing::WithParamInterface<vxgi::VoxelizerKind> {};

const vxgi::GridSpec kGrid = exactGrid(glm::vec3(0.0f), 1.0f, 32);
const glm::vec3 kBoxHalf(1.5f, 1.5f, 1.25f);

bool bitEqual(float a, float b) { return std::memcmp(&a, &b, sizeof(float)) == 0; }

// Static part: a floor in layer y = 2 and a pillar standing on it.
void addStatic(scene::Scene& s) {
    addRect(s, addMaterial(s, glm::vec3(0.8f, 0.7f, 0.6f)), {4, 2.5f, 4}, {28, 2.5f, 28}, 1, 1.0f);
    addBox(s, addMaterial(s, glm::vec3(0.1f, 0.9f, 0.2f)), glm::vec3(1.25f, 4.0f, 1.25f),
           glm::vec3(20.5f, 6.5f, 12.5f), false);
}

TEST_P(VoxelDynamic, MovingDynamicBoxLeavesStaticVoxelsAlone) {
    scene::Scene staticOnly;
    addStatic(staticOnly);
    scene::Scene full = staticOnly;
    const int boxMat = addMaterial(full, glm::vec3(0.3f, 0.2f, 0.9f), glm::vec3(5.0f, 0.0f, 0.0f));
    const int box = addBox(full, boxMat, kBoxHalf, glm::vec3(8.3f, 3.6f, 8.7f), true);

    // The box alone, voxelized as static into its own grid, frame by frame.
    scene::Scene alone;
    alone.materials = full.materials;
    const int aloneBox = addBox(alone, boxMat, kBoxHalf, full.nodes[size_t(box)].translation, false);
    VoxelRig aloneRig(alone, kGrid, GetParam());

    const VoxelReadback staticRef = voxelizeScene(staticOnly, kGrid, GetParam());
    const VoxelSet staticOcc = staticRef.occupancy();
    ASSERT_GT(staticOcc.count(), 0u);

    VoxelRig rig(full, kGrid, GetParam());
    rig.fullVoxelize();

    // Touching the floor, in the open, through the floor and the pillar, high
    // up, and back to the start.
    const glm::vec3 positions[] = {{8.3f, 3.6f, 8.7f}, {14.1f, 6.2f, 11.4f}, {21.75f, 3.0f, 13.5f},
                                   {15.0f, 20.0f, 15.0f}, {8.3f, 3.6f, 8.7f}};
    VoxelSet previous(kGrid.n);
    for (size_t f = 0; f < std::size(positions); ++f) {
        SCOPED_TRACE("frame " + std::to_string(f));
        full.nodes[size_t(box)].translation = positions[f];
        if (f > 0) {
            rig.updateTransforms(full);
            rig.dynamicFrame();
        }
        const VoxelReadback got = rig.read();
        const VoxelSet occ = got.occupancy();

        alone.nodes[size_t(aloneBox)].translation = positions[f];
        aloneRig.updateTransforms(alone);
        aloneRig.fullVoxelize();
        const VoxelReadback boxRef = aloneRig.read();
        const VoxelSet boxOcc = boxRef.occupancy();
        ASSERT_GT(boxOcc.count(), 0u);

        size_t shared = 0, dynamicOnly = 0, stale = 0, mismatches = 0;
        const int n = int(kGrid.n);
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const bool st = staticOcc.get(x, y, z), dy = boxOcc.get(x, y, z);
                    ASSERT_EQ(occ.get(x, y, z), st || dy) << x << " " << y << " " << z;
                    const VoxelReadback* expected = st ? &staticRef : (dy ? &boxRef : nullptr);
                    shared += st && dy;
                    dynamicOnly += dy && !st;
                    stale += previous.get(x, y, z) && !st && !dy;
                    // Static voxels keep exactly their static sums; dynamic
                    // ones hold what the box alone writes; the rest is zero
                    // in every channel (nothing left of earlier frames).
                    for (uint32_t c = 0; c < sh::VOXEL_CHANNELS; ++c) {
                        const float want = expected ? expected->at(x, y, z, c) : 0.0f;
                        if (!bitEqual(got.at(x, y, z, c), want) && ++mismatches <= 8)
                            ADD_FAILURE() << "voxel (" << x << ", " << y << ", " << z << ") channel " << c << ": "
                                          << got.at(x, y, z, c) << ", expected " << want
                                          << (st ? " (static)" : dy ? " (dynamic)" : " (empty)");
                    }
                }
        EXPECT_EQ(mismatches, 0u);
        if (f == 0 || f == 2) {
            EXPECT_GT(shared, 0u) << "the box should reach into static voxels here";
        }
        std::printf("frame %zu: %zu dynamic voxels, %zu shared with static ones (left static), %zu voxels of the "
                    "previous position emptied\n",
                    f, dynamicOnly, shared, stale);
        previous = boxOcc;
    }
}

TEST_P(VoxelDynamic, MovingStaticNodeNeedsFullRevoxelization) {
    scene::Scene s;
    addStatic(s);
    const int mover = addBox(s, addMaterial(s, glm::vec3(0.9f, 0.9f, 0.1f)), glm::vec3(2.0f, 1.0f, 1.5f),
                             glm::vec3(7.5f, 5.25f, 9.0f), false);
    addBox(s, addMaterial(s, glm::vec3(0.3f, 0.2f, 0.9f)), kBoxHalf, glm::vec3(14.1f, 6.2f, 11.4f), true);

    VoxelRig rig(s, kGrid, GetParam());
    rig.fullVoxelize();
    const VoxelSet before = rig.read().occupancy();

    s.nodes[size_t(mover)].translation = glm::vec3(24.3f, 9.6f, 22.2f);
    rig.updateTransforms(s);
    rig.fullVoxelize();
    const VoxelReadback got = rig.read();
    const VoxelReadback fresh = voxelizeScene(s, kGrid, GetParam());
    const VoxelSet occ = got.occupancy(), want = fresh.occupancy();

    size_t left = 0;
    const int n = int(kGrid.n);
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                ASSERT_EQ(occ.get(x, y, z), want.get(x, y, z)) << x << " " << y << " " << z;
                left += before.get(x, y, z) && !want.get(x, y, z);
                for (uint32_t c = 0; c < sh::VOXEL_CHANNELS; ++c) {
                    // Summation order of float atomics may differ between runs.
                    const float a = got.at(x, y, z, c), b = fresh.at(x, y, z, c);
                    ASSERT_NEAR(a, b, 1e-5f * std::max(1.0f, std::abs(b))) << x << " " << y << " " << z << " " << c;
                }
            }
    EXPECT_GT(left, 0u) << "the old placement should have had voxels of its own";
    std::printf("%zu voxels of the old placement emptied\n", left);
}

INSTANTIATE_TEST_SUITE_P(Voxelizers, VoxelDynamic, ::testing::ValuesIn(kVoxelizers), voxelizerTestName);

}  // namespace
}  // namespace dvsgi::test
