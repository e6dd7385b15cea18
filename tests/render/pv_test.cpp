// Progressive screen-space voxelization (--voxelizer pv): the cleanup against
// a CPU model of its rule, the injection against the geometric voxelizer, and
// stale voxels freed once the camera sees the space they held.
#include <cmath>
#include <cstdio>
#include <map>

#include <glm/gtc/matrix_transform.hpp>

#include "gpu/context.h"
#include "gpu/transfer.h"
#include "gpu_fixture.h"
#include "shared/pv_pass.h"
#include "shared/voxel_data.h"
#include "vxgi/pv_voxelize.h"
#include "vxgi/volumes.h"
#include "vxgi/voxel_storage_io.h"

namespace dvsgi::test {
namespace {

namespace sh = dvsgi::shader;

constexpr uint32_t kN = 32;  // the grid spans [-1, 1]^3: voxels of 1/16 m, layer 16 starts at y = 0
float layerCentre(int i) { return -1.0f + (float(i) + 0.5f) / 16.0f; }

scene::PlacedCamera topDownCamera(float height) {
    scene::PlacedCamera c;
    c.camera.yfov = glm::radians(60.0f);
    c.camera.znear = 0.01f;
    c.camera.zfar = 100.0f;
    c.world = glm::translate(glm::mat4(1.0f), glm::vec3(0, height, 0)) *
              glm::mat4_cast(glm::angleAxis(-glm::half_pi<float>(), glm::vec3(1, 0, 0)));
    return c;
}

// The cleanup rule of pv_cleanup.comp for one view, on the host.
enum class Verdict { Keep, Band, Free };
struct Classified {
    Verdict verdict;
    bool ambiguous;  // within rounding of a pixel edge or of the tolerance
};
template <class DepthAt>
Classified classify(const glm::mat4& viewProj, glm::ivec2 size, DepthAt depthAt, glm::vec3 c, float tolerance) {
    const glm::vec4 clip = viewProj * glm::vec4(c, 1.0f);
    if (clip.w <= 0.0f) return {Verdict::Keep, false};
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    if (std::abs(ndc.x) > 1.0f || std::abs(ndc.y) > 1.0f || ndc.z < 0.0f || ndc.z > 1.0f) return {Verdict::Keep, false};
    const glm::vec2 at = (glm::vec2(ndc) * 0.5f + 0.5f) * glm::vec2(size);
    const bool nearEdge = std::abs(at.x - std::round(at.x)) < 1e-3f || std::abs(at.y - std::round(at.y)) < 1e-3f;
    const glm::ivec2 pixel = glm::clamp(glm::ivec2(at), glm::ivec2(0), size - 1);
    const float recorded = depthAt(pixel);
    if (recorded >= 1.0f) return {Verdict::Free, nearEdge};
    const glm::vec4 p = glm::inverse(viewProj) * glm::vec4(glm::vec2(ndc), recorded, 1.0f);
    const float gap = glm::distance(glm::vec3(p) / p.w, c);
    const bool nearTolerance = std::abs(gap - tolerance) < 1e-4f;
    if (gap <= tolerance) return {Verdict::Band, nearEdge || nearTolerance};
    return {recorded > ndc.z ? Verdict::Free : Verdict::Keep, nearEdge || nearTolerance};
}

class PvCleanup : public GpuTest {};

// A synthetic camera depth buffer over a grid full of voxel columns: a floor at
// y = 0 on the left third of the image, nothing in the middle, a shelf at
// y = 0.5 on the right. Each voxel must be freed, kept or kept with its sums
// reduced to one fragment's worth (the band) exactly as the rule says.
TEST_F(PvCleanup, FreesKeepsAndUpdatesVoxelsAsTheRuleSays) {
    gpu::Context& ctx = context();
    const vxgi::GridSpec grid = vxgi::gridForBox(glm::vec3(-1.0f), glm::vec3(1.0f), kN);
    vxgi::VoxelVolumes volumes(ctx, grid);

    // Columns over the whole grid, every other column, all layers: sums of 3
    // fragments with distinct values.
    vxgi::DenseAttributes before(kN);
    for (int z = 0; z < int(kN); z += 2)
        for (int x = 0; x < int(kN); x += 2)
            for (int y = 0; y < int(kN); ++y) {
                before.at(x, y, z, sh::CH_COUNT) = 3.0f;
                before.at(x, y, z, sh::CH_ALBEDO_R) = 0.3f * float(x + 1);
                before.at(x, y, z, sh::CH_ALBEDO_G) = 0.2f * float(y + 1);
                before.at(x, y, z, sh::CH_EMISSION_B) = 0.1f * float(z + 1);
                before.at(x, y, z, sh::CH_NORMAL_POS_Y) = 3.0f;
            }
    vxgi::uploadAttributes(ctx, volumes, before);

    const glm::ivec2 size(64, 64);
    const scene::PlacedCamera camera = topDownCamera(2.0f);
    const glm::mat4 viewProj = render::projectionMatrix(camera, size.x, size.y) * render::viewMatrix(camera);
    auto planeDepth = [&](float y) {
        const glm::vec4 clip = viewProj * glm::vec4(0.0f, y, 0.0f, 1.0f);
        return clip.z / clip.w;
    };
    const float floorDepth = planeDepth(0.0f), shelfDepth = planeDepth(0.5f);
    auto depthAt = [&](glm::ivec2 p) { return p.x < 24 ? floorDepth : (p.x < 40 ? 1.0f : shelfDepth); };
    std::vector<float> depth(size_t(size.x) * size.y);
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) depth[size_t(y) * size.x + x] = depthAt({x, y});

    gpu::ImageDesc d;
    d.format = VK_FORMAT_D32_SFLOAT;
    d.extent = {uint32_t(size.x), uint32_t(size.y), 1};
    d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    d.name = "synthetic camera depth";
    gpu::Image cameraDepth(ctx, d);
    gpu::uploadImage(ctx, cameraDepth, depth.data(), depth.size() * sizeof(float), gpu::use::DepthRead);
    d.extent = {4, 4, 1};
    d.layers = 2;
    d.name = "unused shadow maps";
    gpu::Image shadowMaps(ctx, d);
    std::vector<float> far(32, 1.0f);
    gpu::uploadImage(ctx, shadowMaps, far.data(), far.size() * sizeof(float), gpu::use::ShaderRead);
    const sh::PvDepthView view{viewProj, glm::inverse(viewProj), glm::vec4(sh::PV_CAMERA_LAYER, 0, 0, 0)};
    gpu::Buffer views = gpu::createBuffer(ctx, &view, sizeof(view), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "views");
    gpu::SamplerDesc sd;
    sd.filter = VK_FILTER_NEAREST;
    sd.mipmap = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sd.address = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    gpu::Sampler point(ctx, sd);

    gpu::Tracker tracker = volumeTracker(volumes);
    tracker.assume(cameraDepth, gpu::use::DepthRead);
    tracker.assume(shadowMaps, gpu::use::ShaderRead);
    vxgi::PvVoxelizer pv(ctx);
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        pv.cleanup(cmd, tracker, volumes, {cameraDepth, shadowMaps, views, 1, point.handle()}, nullptr);
    });
    const vxgi::DenseAttributes after = vxgi::readAttributes(ctx, volumes);

    const float tolerance = 0.5f * std::sqrt(3.0f) * grid.voxelSize;
    std::map<Verdict, int> seen;
    int ambiguous = 0;
    for (int z = 0; z < int(kN); z += 2)
        for (int x = 0; x < int(kN); x += 2)
            for (int y = 0; y < int(kN); ++y) {
                const glm::vec3 c(layerCentre(x), layerCentre(y), layerCentre(z));
                const Classified k = classify(viewProj, size, depthAt, c, tolerance);
                if (k.ambiguous) {
                    ++ambiguous;
                    continue;
                }
                ++seen[k.verdict];
                const float count = after.at(x, y, z, sh::CH_COUNT);
                if (k.verdict == Verdict::Free) {
                    ASSERT_EQ(count, 0.0f) << "voxel (" << x << ", " << y << ", " << z << ") should be freed";
                    continue;
                }
                // Band: scaled to one fragment; kept: unchanged.
                const float scale = k.verdict == Verdict::Band ? 1.0f / 3.0f : 1.0f;
                for (uint32_t ch = 0; ch < sh::VOXEL_CHANNELS; ++ch)
                    ASSERT_NEAR(after.at(x, y, z, ch), before.at(x, y, z, ch) * scale, 1e-5f)
                        << "channel " << ch << " of voxel (" << x << ", " << y << ", " << z << ")";
            }
    std::printf("  kept %d, in the band %d, freed %d, skipped as ambiguous %d\n", seen[Verdict::Keep],
                seen[Verdict::Band], seen[Verdict::Free], ambiguous);
    EXPECT_GT(seen[Verdict::Keep], 100);
    EXPECT_GT(seen[Verdict::Band], 20);
    EXPECT_GT(seen[Verdict::Free], 100);
    EXPECT_LT(ambiguous, 10);
    // Nothing appeared where nothing was.
    for (int z = 0; z < int(kN); ++z)
        for (int x = 0; x < int(kN); ++x)
            for (int y = 0; y < int(kN); ++y)
                if (x % 2 || z % 2) ASSERT_EQ(after.at(x, y, z, sh::CH_COUNT), 0.0f);
}

render::RenderSettings pvSettings(vxgi::VoxelizerKind kind) {
    render::RenderSettings rs;
    rs.width = rs.height = 128;
    rs.voxels = kN;
    rs.hasVoxelBox = true;
    rs.voxelBoxMin = glm::vec3(-1.0f);
    rs.voxelBoxMax = glm::vec3(1.0f);
    rs.voxelizer = kind;
    rs.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    rs.voxelLight.bounces = 0;
    rs.temporal.enabled = false;
    return rs;
}

std::vector<float> channel(const vxgi::DenseAttributes& a, uint32_t ch) {
    const size_t n3 = size_t(a.n) * a.n * a.n;
    return std::vector<float>(a.data.begin() + n3 * ch, a.data.begin() + n3 * (ch + 1));
}

class PvVoxelize : public GpuTest {};

// A square seen whole by the camera (edges and plane on voxel centres, about
// three pixels per voxel): progressive voxelization finds exactly the voxels
// the exact geometric voxelizer marks, with the same material and normal.
TEST_F(PvVoxelize, PlaneSeenByTheCameraEqualsItsGeometricVoxelization) {
    scene::Scene s;
    const glm::vec3 albedo(0.6f, 0.3f, 0.2f);
    addQuad(s, addMaterial(s, albedo), glm::vec3(0.0f, layerCentre(16), 0.0f), 6.5f / 16.0f);
    addTopDownCamera(s, 2.0f, glm::radians(60.0f));
    render::Renderer pv(context(), s, pvSettings(vxgi::VoxelizerKind::Pv));
    pv.renderFrame();
    render::Renderer exact(context(), s, pvSettings(vxgi::VoxelizerKind::Compute));
    exact.renderFrame();
    const vxgi::DenseAttributes a = vxgi::readAttributes(context(), *pv.volumes());
    const vxgi::DenseAttributes b = vxgi::readAttributes(context(), *exact.volumes());
    const std::vector<float> countA = channel(a, sh::CH_COUNT), countB = channel(b, sh::CH_COUNT);
    size_t occupied = 0, missed = 0, extra = 0;
    for (size_t i = 0; i < countA.size(); ++i) {
        occupied += countB[i] > 0.0f;
        missed += countB[i] > 0.0f && countA[i] == 0.0f;
        extra += countA[i] > 0.0f && countB[i] == 0.0f;
    }
    std::printf("  geometric voxels %zu, missed by pv %zu, extra in pv %zu\n", occupied, missed, extra);
    EXPECT_EQ(occupied, 14u * 14u);
    EXPECT_EQ(missed, 0u);
    EXPECT_EQ(extra, 0u);
    for (size_t i = 0; i < countA.size(); ++i) {
        if (countA[i] == 0.0f) continue;
        for (uint32_t ch : {sh::CH_ALBEDO_R, sh::CH_ALBEDO_G, sh::CH_ALBEDO_B, sh::CH_NORMAL_POS_Y})
            ASSERT_NEAR(a.data[ch * countA.size() + i] / countA[i], b.data[ch * countB.size() + i] / countB[i], 1e-3f)
                << "channel " << ch << " at index " << i;
    }
}

// A block above a floor moves: once the camera sees the floor where the block
// was, the block's old voxels are gone and the floor under it is found; the
// floor under the block's new place, seen before, is kept.
TEST_F(PvVoxelize, MovedObjectLeavesNoStaleVoxelsOnceTheSpaceItLeftIsSeen) {
    scene::Scene s;
    const int white = addMaterial(s, glm::vec3(0.8f));
    addQuad(s, white, glm::vec3(0.0f, layerCentre(16), 0.0f), 14.5f / 16.0f);
    const int block = addQuad(s, white, glm::vec3(-0.5f, layerCentre(21), 0.0f), 2.5f / 16.0f);
    addTopDownCamera(s, 2.0f, glm::radians(60.0f));
    render::Renderer r(context(), s, pvSettings(vxgi::VoxelizerKind::Pv));
    r.renderFrame();
    auto layerVoxels = [&](int layer, bool left) {
        const std::vector<float> c = channel(vxgi::readAttributes(context(), *r.volumes()), sh::CH_COUNT);
        int found = 0;
        for (int z = 0; z < int(kN); ++z)
            for (int x = left ? 0 : 16; x < (left ? 16 : int(kN)); ++x)
                found += c[(size_t(z) * kN + layer) * kN + x] > 0.0f;
        return found;
    };
    const int blockVoxels = layerVoxels(21, true);
    EXPECT_EQ(blockVoxels, 6 * 6);
    const int floorLeft = layerVoxels(16, true);  // the block hides part of it

    r.scene().nodes[size_t(block)].translation.x = 0.5f;
    r.sceneChanged();
    r.renderFrame();
    std::printf("  block voxels %d; left floor voxels %d before the move, %d after\n", blockVoxels, floorLeft,
                layerVoxels(16, true));
    EXPECT_EQ(layerVoxels(21, true), 0) << "stale block voxels where the block was";
    EXPECT_EQ(layerVoxels(21, false), blockVoxels);
    EXPECT_EQ(layerVoxels(16, true), 30 * 15) << "the floor where the block was should be found";
    EXPECT_EQ(layerVoxels(16, false), 30 * 15) << "the floor under the block's new place, seen before, is kept";
    for (int layer = 0; layer < int(kN); ++layer)
        if (layer != 16 && layer != 21) EXPECT_EQ(layerVoxels(layer, true) + layerVoxels(layer, false), 0);
}

}  // namespace
}  // namespace dvsgi::test
