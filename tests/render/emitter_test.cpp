// Emissive surfaces lit as area-light patches (render/emitters.h): the direct
// term under a square emitter against the irradiance integrated on the CPU,
// an emitter that faces away lighting nothing, and an occluder between an
// emitter and the floor shadowing it.
#include <cmath>
#include <cstdio>

#include <glm/gtc/constants.hpp>

#include "gpu_fixture.h"
#include "render/emitters.h"
#include "shared/composite_pass.h"

namespace dvsgi::test {
namespace {

constexpr float kPi = glm::pi<float>();
constexpr float kRho = 0.5f, kLe = 1.0f, kHalf = 0.5f, kHeight = 1.0f;

// Irradiance at (x, 0, z) from a one-sided square emitter of radiance kLe,
// half-size kHalf, at `height` facing down: E = integral L cos cos / r^2.
double irradianceUnderSquare(double x, double z, double height = kHeight) {
    const int n = 400;
    const double cell = 2.0 * kHalf / n;
    double e = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double dx = -kHalf + (i + 0.5) * cell - x, dz = -kHalf + (j + 0.5) * cell - z;
            const double r2 = dx * dx + dz * dz + height * height;
            e += kLe * (height * height) / (r2 * r2) * cell * cell;  // cos_e = cos_r = h / r
        }
    return e;
}

// With `occluderHeight` > 0, a black square of half-size 0.75 m at that
// height between the emitter and the floor.
scene::Scene emitterOverFloor(bool facingDown, float height = kHeight, float occluderHeight = 0.0f) {
    scene::Scene s;
    addQuad(s, addMaterial(s, glm::vec3(kRho)), glm::vec3(0.0f), 2.0f);  // floor, normal +Y
    const glm::quat down = glm::angleAxis(kPi, glm::vec3(1, 0, 0));
    addQuad(s, addMaterial(s, glm::vec3(0.0f), glm::vec3(kLe)), glm::vec3(0.0f, height, 0.0f), kHalf,
            facingDown ? down : glm::quat(1, 0, 0, 0));
    if (occluderHeight > 0.0f) addQuad(s, addMaterial(s, glm::vec3(0.0f)), glm::vec3(0.0f, occluderHeight, 0.0f), 0.75f);
    addTopDownCamera(s, 0.9f, glm::radians(60.0f));  // below the emitter, looking at the floor
    return s;
}

render::RenderSettings directOnly() {
    render::RenderSettings rs;
    rs.width = rs.height = 32;
    rs.shadowMapSize = 256;
    rs.voxels = 32;
    rs.outputTerm = shader::TERM_DIRECT;
    rs.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    rs.voxelLight.bounces = 0;
    return rs;
}

class Emitters : public GpuTest {};

TEST_F(Emitters, SquareEmitterLightsTheFloorAsTheIrradianceIntegral) {
    const scene::Scene s = emitterOverFloor(true);
    const render::RenderSettings rs = directOnly();
    render::Renderer r(context(), s, rs);
    r.renderFrame();
    EXPECT_EQ(r.emitterPatchCount(), rs.emitterPatches);
    const image::ImageRGBA32F img = r.readOutput();
    double worst = 0.0, sumGot = 0.0, sumWant = 0.0;
    for (uint32_t y = 2; y < 30; y += 3)
        for (uint32_t x = 2; x < 30; x += 3) {
            const glm::vec3 p = pixelOnPlane(s, rs, x, y, 0.0f);
            const double want = kRho / kPi * irradianceUnderSquare(p.x, p.z);
            const double got = img.at(x, y)[0];
            worst = std::max(worst, std::abs(got / want - 1.0));
            sumGot += got;
            sumWant += want;
        }
    std::printf("  floor under a square emitter: mean ratio %.4f, worst pixel %.2f%%\n", sumGot / sumWant,
                100.0 * worst);
    // Measured on lavapipe: mean -0.09 %, worst pixel 0.18 %; bounds 1.5x.
    EXPECT_NEAR(sumGot / sumWant, 1.0, 0.0014);
    EXPECT_LT(worst, 0.0027);
}

TEST_F(Emitters, EmitterFacingAwayLightsNothing) {
    const scene::Scene s = emitterOverFloor(false);
    render::Renderer r(context(), s, directOnly());
    r.renderFrame();
    const image::ImageRGBA32F img = r.readOutput();
    double maxFloor = 0.0;
    for (uint32_t y = 0; y < 32; ++y)
        for (uint32_t x = 0; x < 32; ++x) maxFloor = std::max(maxFloor, double(img.at(x, y)[0]));
    EXPECT_EQ(maxFloor, 0.0);
}

// The emitter 3 m up, the occluder halfway: every floor point within 1 m of
// the centre (all the camera sees) has the whole emitter behind it, so its
// direct light is what the patches' visibility cones let through. This also
// fails if the lighting pass runs its cone-free variant (lighting.comp,
// DVSGI_SHADOW_MAPS_ONLY) while area lights exist: that variant cannot
// shadow them. (Closer to the floor or the emitter an occluder escapes the
// cones, which start 2.5 voxels up and stop a patch's footprint short of the
// emitter: docs/quality.md, "Emitters as area lights".)
TEST_F(Emitters, OccluderHalfwayShadowsTheFloor) {
    constexpr float kHigh = 3.0f;
    const render::RenderSettings rs = directOnly();
    // The floor's light over the unoccluded integral, with and without the occluder.
    auto floorRatio = [&](float occluderHeight) {
        const scene::Scene s = emitterOverFloor(true, kHigh, occluderHeight);
        render::Renderer r(context(), s, rs);
        r.renderFrame();
        EXPECT_EQ(r.emitterPatchCount(), rs.emitterPatches);
        const image::ImageRGBA32F img = r.readOutput();
        double sumGot = 0.0, sumOpen = 0.0;
        for (uint32_t y = 2; y < 30; y += 3)
            for (uint32_t x = 2; x < 30; x += 3) {
                const glm::vec3 p = pixelOnPlane(s, rs, x, y, 0.0f);
                EXPECT_LT(std::max(std::abs(p.x), std::abs(p.z)), 1.0f);
                sumOpen += kRho / kPi * irradianceUnderSquare(p.x, p.z, kHigh);
                sumGot += img.at(x, y)[0];
            }
        return sumGot / sumOpen;
    };
    const double open = floorRatio(0.0f), shadowed = floorRatio(0.5f * kHigh);
    std::printf("  floor under the emitter: %.4f of the integral without the occluder, %.4f in its umbra\n", open,
                shadowed);
    // Measured on lavapipe: 1.0001 (bound as the test above's) and 0.0016 (the
    // cone-free variant forced: 1.0001 in the umbra; bound 1.5x).
    EXPECT_NEAR(open, 1.0, 0.0014);
    EXPECT_LT(shadowed, 0.0024);
}

}  // namespace
}  // namespace dvsgi::test
