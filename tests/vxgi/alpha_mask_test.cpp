// Voxelization respects alpha-masked materials: where the base colour's alpha
// is under the cutoff the surface does not exist, so it leaves no voxels.
#include <cstring>

#include "gpu/transfer.h"
#include "gpu_fixture.h"
#include "shared/voxel_data.h"
#include "vox_helper.h"
#include "vxgi/volumes.h"
#include "vxgi/voxel_storage_io.h"

namespace dvsgi::test {
namespace {

namespace sh = dvsgi::shader;

class AlphaMask : public GpuTest, public ::testing::WithParamInterface<vxgi::VoxelizerKind> {};

TEST_P(AlphaMask, CutOutHalfLeavesNoVoxels) {
    scene::Scene s;
    // 8x1 texture: opaque on the left half (u < 0.5), transparent on the right.
    scene::Texture t;
    t.name = "half";
    t.width = 8;
    t.height = 1;
    for (uint32_t x = 0; x < 8; ++x) t.rgba8.insert(t.rgba8.end(), {255, 255, 255, uint8_t(x < 4 ? 255 : 0)});
    s.textures.push_back(t);
    const int m = addMaterial(s, glm::vec3(0.8f));
    s.materials[size_t(m)].baseColorTexture = 0;
    s.materials[size_t(m)].alphaMode = scene::AlphaMode::Mask;
    addQuad(s, m, glm::vec3(0), 1.0f);  // u = x / 2 + 0.5 across the quad
    addTopDownCamera(s, 2.0f, glm::radians(60.0f));
    render::RenderSettings rs;
    rs.width = rs.height = 16;
    rs.voxels = 32;
    rs.voxelizer = GetParam();
    rs.hasVoxelBox = true;
    rs.voxelBoxMin = glm::vec3(-1.0f);
    rs.voxelBoxMax = glm::vec3(1.0f);
    rs.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    rs.voxelLight.bounces = 0;
    render::Renderer r(context(), s, rs);
    r.renderFrame();
    const vxgi::VoxelVolumes& v = *r.volumes();
    const vxgi::DenseAttributes a = vxgi::readAttributes(context(), v);
    const size_t n = 32, n3 = n * n * n;
    const std::vector<float> count(a.data.begin() + n3 * sh::CH_COUNT, a.data.begin() + n3 * (sh::CH_COUNT + 1));
    // Columns away from the cut at x = 16 (the texture blends across it).
    int left = 0, right = 0;
    for (size_t i = 0; i < n3; ++i) {
        if (count[i] <= 0.0f) continue;
        const size_t x = i % n;
        if (x < 14) ++left;
        if (x > 18) ++right;
    }
    std::printf("occupied voxels: opaque side %d, cut-out side %d\n", left, right);
    EXPECT_GT(left, 300);
    EXPECT_EQ(right, 0);
}

INSTANTIATE_TEST_SUITE_P(Voxelizers, AlphaMask, ::testing::ValuesIn(kVoxelizers), voxelizerTestName);

}  // namespace
}  // namespace dvsgi::test
