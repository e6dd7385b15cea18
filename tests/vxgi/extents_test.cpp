// The part of each voxel its surface reaches (the extents, shared/voxel_data.h):
// the voxelizers OR, per voxel, every touching triangle's bounding box in
// eighths of the voxel per axis; checked against the CPU reference
// voxelization: bit for bit for the compute voxelizer, and for the geometry
// shader's, whose dilated columns may reach a few voxels more, as a superset
// equal in most voxels. The pv voxelizer leaves them 0 (not known).
#include <gtest/gtest.h>

#include "gpu/transfer.h"
#include "gpu_fixture.h"
#include "shared/voxelize_compute_pass.h"
#include "vox_helper.h"

namespace dvsgi::test {
namespace {

namespace sh = dvsgi::shader;

class VoxelExtents : public GpuTest, public ::testing::WithParamInterface<vxgi::VoxelizerKind> {};

const vxgi::GridSpec kGrid = exactGrid(glm::vec3(0.0f), 1.0f, 32);

// A box standing off the grid's lattice (its faces inside voxels, its
// edges and corners too), and a slanted triangle.
scene::Scene edgesScene() {
    scene::Scene s;
    const int m = addMaterial(s, glm::vec3(0.6f));
    addBox(s, m, glm::vec3(3.3f, 2.6f, 4.15f), glm::vec3(11.4f, 9.7f, 13.05f), false);
    addTriangles(s, m, {{glm::vec3(20.2f, 3.1f, 4.4f), glm::vec3(27.9f, 6.3f, 9.8f), glm::vec3(22.6f, 12.7f, 5.3f)}});
    return s;
}

TEST_P(VoxelExtents, MatchTheTrianglesBoxes) {
    const bool exact = GetParam() == vxgi::VoxelizerKind::Compute;
    const scene::Scene s = edgesScene();
    VoxelRig rig(s, kGrid, GetParam());
    rig.fullVoxelize();
    const std::vector<uint32_t> got = readExtents(rig.volumes);

    const uint32_t n = kGrid.n;
    std::vector<uint32_t> want(got.size(), 0u);
    for (const Triangle& t : voxelTriangles(s, kGrid)) {
        const VoxelSet one = referenceVoxelize({t}, n, double(sh::VOXC_BOX_GROWTH));
        // The shader's box, in float as it computes it.
        glm::vec3 lo(t.v[0]), hi(t.v[0]);
        for (int k = 1; k < 3; ++k) {
            lo = glm::min(lo, glm::vec3(t.v[k]));
            hi = glm::max(hi, glm::vec3(t.v[k]));
        }
        for (int z = 0; z < int(n); ++z)
            for (int y = 0; y < int(n); ++y)
                for (int x = 0; x < int(n); ++x) {
                    if (!one.get(x, y, z)) continue;
                    const glm::vec3 c = glm::vec3(float(x), float(y), float(z));
                    want[(size_t(z) * n + size_t(y)) * n + size_t(x)] |= sh::voxelExtentBits(lo - c, hi - c);
                }
    }
    int occupied = 0, partial = 0, differ = 0, missing = 0;
    for (size_t i = 0; i < got.size(); ++i) {
        occupied += want[i] != 0;
        partial += want[i] != 0 && want[i] != sh::VOXEL_EXTENT_ALL;
        differ += got[i] != want[i];
        if ((exact ? got[i] != want[i] : (got[i] & want[i]) != want[i]) && missing++ < 5)
            ADD_FAILURE() << "voxel " << i % n << " " << i / n % n << " " << i / (n * n) << ": extents " << std::hex
                          << got[i] << ", expected " << (exact ? "" : "at least ") << want[i];
    }
    std::printf("  %d voxels, %d reached in part, %d differ\n", occupied, partial, differ);
    EXPECT_EQ(missing, 0);
    EXPECT_GT(partial, 200) << "the box's faces and edges lie inside their voxels";
    EXPECT_LE(differ, exact ? 0 : occupied / 10) << "the dilated columns' extra voxels";
}

INSTANTIATE_TEST_SUITE_P(Voxelizers, VoxelExtents, ::testing::ValuesIn(kVoxelizers), voxelizerTestName);

// One axis's bits: the eighths a box reaches, clamped to the voxel.
TEST(VoxelExtentBits, EighthsReached) {
    EXPECT_EQ(sh::voxelExtentAxisBits(0.5f, 0.5f), 0x10u);    // a plane through the centre: the fifth eighth
    EXPECT_EQ(sh::voxelExtentAxisBits(-3.0f, 0.25f), 0x03u);  // reaching in from below to a quarter
    EXPECT_EQ(sh::voxelExtentAxisBits(0.3f, 4.0f), 0xfcu);    // from 0.3 on, past the top
    EXPECT_EQ(sh::voxelExtentAxisBits(-1.0f, 2.0f), 0xffu);   // through the whole voxel
    EXPECT_EQ(sh::voxelExtentAxisBits(1.0f, 1.0f), 0x80u);    // on the top face: the last eighth
    EXPECT_EQ(sh::voxelExtentAxisBits(0.0f, 0.0f), 0x01u);    // on the bottom face: the first
    // A plane on an eighth's border rounded either way: the eighth above it, as on the border itself.
    EXPECT_EQ(sh::voxelExtentAxisBits(0.125f - 3e-5f, 0.125f - 3e-5f), 0x02u);
    EXPECT_EQ(sh::voxelExtentAxisBits(0.125f + 3e-5f, 0.125f + 3e-5f), 0x02u);
    EXPECT_EQ(sh::voxelExtentAxisBits(0.125f - 2e-3f, 0.125f - 2e-3f), 0x01u);  // clearly below it
}

}  // namespace
}  // namespace dvsgi::test
