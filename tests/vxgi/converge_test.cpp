// Converged and feedback bounces (--bounces auto). In a closed box of albedo
// rho and emission L every wall converges to L / (1 - rho t), t the fraction
// of light one bounce carries; with rho = 0.9 ten bounces still leave a third
// of the light missing, so this checks that iterating to convergence reaches
// the infinite series. A light switched off must leave no lasting indirect
// light under feedback. A renderer whose voxel slots run out grows them and
// renders the same frame.
#include <cmath>
#include <cstdio>

#include "gpu_fixture.h"
#include "light_helpers.h"
#include "shared/voxel_data.h"
#include "vxgi/voxel_light_settings.h"

namespace dvsgi::test {
namespace {

constexpr uint32_t kN = 32;
constexpr float kHalf = 0.71875f;  // walls in the middle of voxel layers 4 and 27 of [-1, 1]^3
constexpr int kLow = 4, kHigh = 27, kInnerLo = 10, kInnerHi = 21;

render::RenderSettings boxSettings() { return unitBoxGridSettings(kN, 256); }

// Mean of one channel over the wall voxels away from edges, all six walls.
double wallMean(const Rgba16Volume& v, int channel = 0) {
    double sum = 0.0;
    int count = 0;
    forEachWallVoxel(kLow, kHigh, kInnerLo, kInnerHi, [&](glm::ivec3 p) {
        sum += v.at(p.x, p.y, p.z)[channel];
        ++count;
    });
    return sum / count;
}

class Converge : public GpuTest {};

TEST_F(Converge, ClosedFurnaceReachesTheInfiniteSeriesOfItsTransport) {
    constexpr float kRho = 0.9f, kL = 1.0f;
    scene::Scene s;
    addInwardBox(s, addMaterial(s, glm::vec3(kRho), glm::vec3(kL)), glm::vec3(0.0f), kHalf);
    addTopDownCamera(s, 0.0f, glm::radians(60.0f));
    // One bounce measures what fraction t of the light a bounce carries here
    // (L + rho t L); converging must then reach the series' limit L / (1 - rho t).
    render::RenderSettings one = boxSettings();
    one.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    one.voxelLight.bounces = 1;
    render::Renderer r1(context(), s, one);
    r1.renderFrame();
    const double t = (wallMean(readRgba16(r1.volumes()->radiance)) / kL - 1.0) / kRho;

    render::RenderSettings rs = boxSettings();
    rs.voxelLight.bounceMode = vxgi::BounceMode::Converge;
    rs.voxelLight.convergence = 0.002f;
    rs.voxelLight.maxBounces = 200;
    render::Renderer r(context(), s, rs);
    const render::FrameStats st = r.renderFrame();
    const double limit = kL / (1.0 - kRho * t), exact = kL / (1.0 - kRho);
    const double got = wallMean(readRgba16(r.volumes()->radiance));
    std::printf("  one bounce carries t = %.4f; %u bounces, last change %.2e: wall mean %.4f, limit L/(1-rho t) %.4f "
                "(%+.2f%%), exact L/(1-rho) %.4f (%+.2f%%)\n",
                t, st.bounces, st.bounceChange, got, limit, 100.0 * (got / limit - 1.0), exact,
                100.0 * (got / exact - 1.0));
    EXPECT_TRUE(st.converged);
    EXPECT_GT(st.bounces, 15u);  // (rho t)^15 < 0.15: far from converged before that
    EXPECT_NEAR(got / limit, 1.0, 0.017);  // measured +1.15 %: t varies a little between bounces
    // Measured: t = 0.889 (a bounce loses 11 % through coarse cells that
    // straddle a wall and the empty margin behind it), so the converged wall
    // is 49 % below L / (1 - rho); docs/quality.md. Guard against it getting worse.
    EXPECT_GT(t, 0.85);
}

TEST_F(Converge, SwitchedOffLightLeavesNoIndirectLightUnderFeedback) {
    constexpr float kRho = 0.5f;
    scene::Scene s;
    addInwardBox(s, addMaterial(s, glm::vec3(kRho)), glm::vec3(0.0f), kHalf);
    addTopDownCamera(s, 0.0f, glm::radians(60.0f));
    scene::Light light;
    light.name = "lamp";
    light.type = scene::LightType::Point;
    light.intensity = 1.0f;
    addLight(s, light, glm::vec3(0.0f, 0.5f, 0.0f), glm::vec3(0, -1, 0));
    render::RenderSettings rs = boxSettings();
    rs.voxelLight.bounceMode = vxgi::BounceMode::Feedback;
    render::Renderer r(context(), s, rs);
    // Feedback: frame k holds k - 1 bounces; 20 frames are converged for rho = 0.5.
    for (int f = 0; f < 20; ++f) r.renderFrame();
    const double lit = wallMean(readRgba16(r.volumes()->radiance));
    const double indirect = lit - wallMean(readDirect(*r.volumes()));
    ASSERT_GT(indirect, 0.05 * lit);
    r.scene().lights[0].intensity = 0.0f;
    r.sceneChanged();
    // Each frame keeps what one bounce returns of the last: about rho times it
    // in a closed box, so 1 % is reached after ln(0.01) / ln(rho) = 6.6 frames.
    constexpr int kFrames = 10;
    int frames = 0;
    double left = indirect;
    while (frames < kFrames && left >= 0.01 * indirect) {
        r.renderFrame();
        ++frames;
        left = wallMean(readRgba16(r.volumes()->radiance));
    }
    std::printf("  indirect %.5f with the light on; below 1 %% after %d frame(s) off (%.2e left)\n", indirect, frames,
                left);
    EXPECT_LT(left, 0.01 * indirect) << "after " << kFrames << " frames";
}

TEST_F(Converge, RunningOutOfVoxelSlotsGrowsThemAndRendersTheSameFrame) {
    scene::Scene s;
    // Walls 29 voxels wide: about 5000 occupied voxels, more than one row of slots.
    addInwardBox(s, addMaterial(s, glm::vec3(0.5f), glm::vec3(1.0f)), glm::vec3(0.0f), 0.9f);
    addTopDownCamera(s, 0.0f, glm::radians(60.0f));
    render::RenderSettings rs = boxSettings();
    rs.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    rs.voxelLight.bounces = 2;
    render::Renderer ref(context(), s, rs);
    ref.renderFrame();
    rs.voxelSlots = shader::VOXEL_SLOT_ROW;
    render::Renderer grown(context(), s, rs);
    grown.renderFrame();
    const uint32_t slots = grown.volumes()->slots;
    std::printf("  %u slots at first, %u after growing (default %u)\n", shader::VOXEL_SLOT_ROW, slots,
                ref.volumes()->slots);
    EXPECT_GT(slots, shader::VOXEL_SLOT_ROW);
    grown.renderFrame();  // a later frame (dynamic path) needs no more
    EXPECT_EQ(grown.volumes()->slots, slots);
    const Rgba16Volume a = readRgba16(ref.volumes()->radiance), b = readRgba16(grown.volumes()->radiance);
    EXPECT_NEAR(wallMean(b), wallMean(a), 1e-4 * wallMean(a));
    const image::ImageRGBA32F ia = ref.readOutput(), ib = grown.readOutput();
    ASSERT_EQ(ia.rgba.size(), ib.rgba.size());
    for (size_t i = 0; i < ia.rgba.size(); ++i) ASSERT_NEAR(ib.rgba[i], ia.rgba[i], 1e-4f * (1.0f + ia.rgba[i])) << i;
}

}  // namespace
}  // namespace dvsgi::test
