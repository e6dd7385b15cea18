// Emissive surfaces lit as area-light patches (render/emitters.h): the direct
// term under a square emitter against the irradiance integrated on the CPU,
// and an emitter that faces away lighting nothing.
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
// half-size kHalf, at height kHeight facing down: E = integral L cos cos / r^2.
double irradianceUnderSquare(double x, double z) {
    const int n = 400;
    const double cell = 2.0 * kHalf / n;
    double e = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double dx = -kHalf + (i + 0.5) * cell - x, dz = -kHalf + (j + 0.5) * cell - z;
            const double r2 = dx * dx + dz * dz + kHeight * kHeight;
            e += kLe * (kHeight * kHeight) / (r2 * r2) * cell * cell;  // cos_e = cos_r = h / r
        }
    return e;
}

scene::Scene emitterOverFloor(bool facingDown) {
    scene::Scene s;
    addQuad(s, addMaterial(s, glm::vec3(kRho)), glm::vec3(0.0f), 2.0f);  // floor, normal +Y
    const glm::quat down = glm::angleAxis(kPi, glm::vec3(1, 0, 0));
    addQuad(s, addMaterial(s, glm::vec3(0.0f), glm::vec3(kLe)), glm::vec3(0.0f, kHeight, 0.0f), kHalf,
            facingDown ? down : glm::quat(1, 0, 0, 0));
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

}  // namespace
}  // namespace dvsgi::test
