// vxgi::countVoxels (the occupied-voxel list's header): occupied and dynamic
// voxels after voxelization, against the attribute read-back and a static-only
// voxelization of the same scene.
#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "vox_helper.h"
#include "vxgi/voxel_counts.h"

namespace dvsgi::test {
namespace {

class VoxelCountsTest : public GpuTest {};

const vxgi::GridSpec kGrid = exactGrid(glm::vec3(0.0f), 1.0f, 32);

void addStatic(scene::Scene& s) {
    addRect(s, addMaterial(s, glm::vec3(0.8f)), {4, 2.5f, 4}, {28, 2.5f, 28}, 1, 1.0f);
}

TEST_F(VoxelCountsTest, CountsOccupiedAndDynamicVoxels) {
    scene::Scene staticOnly;
    addStatic(staticOnly);
    scene::Scene full = staticOnly;
    // A dynamic box standing on the floor: it shares the floor's layer, where
    // voxels stay static, and occupies its own voxels above it.
    const int box = addBox(full, addMaterial(full, glm::vec3(0.2f, 0.3f, 0.9f)), glm::vec3(3.0f, 3.0f, 3.0f),
                           glm::vec3(15.5f, 5.0f, 15.5f), true);

    const VoxelSet staticOcc = voxelizeScene(staticOnly, kGrid).occupancy();
    VoxelRig rig(full, kGrid);
    rig.fullVoxelize();
    for (int frame = 0; frame < 2; ++frame) {
        SCOPED_TRACE("frame " + std::to_string(frame));
        if (frame > 0) {
            full.nodes[size_t(box)].translation = glm::vec3(10.25f, 7.0f, 18.5f);
            rig.updateTransforms(full);
            rig.dynamicFrame();
        }
        const VoxelSet occ = rig.read().occupancy();
        uint64_t occupied = 0, dynamic = 0;
        const int n = int(kGrid.n);
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x)
                    if (occ.get(x, y, z)) {
                        ++occupied;
                        dynamic += !staticOcc.get(x, y, z);
                    }
        ASSERT_GT(dynamic, 0u);
        ASSERT_GT(occupied, dynamic);
        const vxgi::VoxelCounts counts = vxgi::countVoxels(context(), rig.volumes);
        std::printf("occupied %llu, dynamic %llu\n", (unsigned long long)counts.occupied,
                    (unsigned long long)counts.dynamic);
        EXPECT_EQ(counts.occupied, occupied);
        EXPECT_EQ(counts.dynamic, dynamic);
    }
}

}  // namespace
}  // namespace dvsgi::test
