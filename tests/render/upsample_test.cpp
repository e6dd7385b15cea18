// Reduced-resolution cone tracing (GatherSettings::traceScale, the CLI's
// --trace-scale S <= 1): the depth- and normal-aware upsampling keeps the
// indirect light of one surface from bleeding onto another across a depth edge.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "gpu_fixture.h"
#include "shared/composite_pass.h"

namespace dvsgi::test {
namespace {

namespace sh = dvsgi::shader;

constexpr uint32_t kSize = 128;
constexpr float kPlatformY = 0.3f, kPlatformHalf = 0.3f;

// A dark floor and a bright platform above it, under an emissive ceiling: the
// indirect diffuse term (albedo/pi times the gathered irradiance) jumps by
// about 4x at the platform's edge, which is also a depth edge.
scene::Scene platformScene() {
    scene::Scene s;
    addQuad(s, addMaterial(s, glm::vec3(0.2f)), glm::vec3(0.0f), 1.0f);
    addQuad(s, addMaterial(s, glm::vec3(0.9f)), glm::vec3(0.0f, kPlatformY, 0.0f), kPlatformHalf);
    addQuad(s, addMaterial(s, glm::vec3(0.0f), glm::vec3(1.0f)), glm::vec3(0.0f, 1.0f, 0.0f), 1.0f,
            glm::angleAxis(glm::pi<float>(), glm::vec3(1, 0, 0)));
    addTopDownCamera(s, 0.9f, glm::radians(60.0f));
    return s;
}

render::RenderSettings settings(float traceScale) {
    render::RenderSettings rs;
    rs.width = rs.height = kSize;
    rs.shadowMapSize = 256;
    rs.voxels = 64;
    rs.outputTerm = sh::TERM_INDIRECT;
    rs.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    rs.voxelLight.bounces = 0;
    rs.emitterLights = false;  // the ceiling's radiance is what the cones gather
    rs.gather.traceScale = traceScale;
    // The cones: a pixel's trace is the same computation at either size (the
    // rays' seeds follow the trace pixel, so their noise would differ).
    rs.gather.trace = render::GatherTrace::Cones;
    return rs;
}

float value(const image::ImageRGBA32F& img, int x, int y) { return img.at(uint32_t(x), uint32_t(y))[1]; }

class Upsampling : public GpuTest {};

TEST_F(Upsampling, HalfResolutionTraceKeepsTheDepthEdge) {
    const scene::Scene s = platformScene();
    const image::ImageRGBA32F full = render(s, settings(1.0f));
    const image::ImageRGBA32F half = render(s, settings(0.5f));
    const int n = int(kSize), m = n / 2;

    // Which surface each pixel centre sees, from the geometry.
    std::vector<int> onPlatform(size_t(n * n));
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const glm::vec3 p = pixelOnPlane(s, settings(1.0f), uint32_t(x), uint32_t(y), kPlatformY);
            onPlatform[size_t(y * n + x)] = std::abs(p.x) <= kPlatformHalf && std::abs(p.z) <= kPlatformHalf;
        }
    auto surface = [&](int x, int y) { return onPlatform[size_t(glm::clamp(y, 0, n - 1) * n + glm::clamp(x, 0, n - 1))]; };

    // The half-resolution trace: trace pixel l stands for G-buffer pixel 2l + 1
    // (gather.comp), whose full-resolution trace is the same computation.
    auto low = [&](int lx, int ly) {
        return value(full, 2 * glm::clamp(lx, 0, m - 1) + 1, 2 * glm::clamp(ly, 0, m - 1) + 1);
    };
    // Plain bilinear upsampling of it, with the upsampler's sample positions.
    auto bilinear = [&](int x, int y) {
        const glm::vec2 q = (glm::vec2(x, y) + 0.5f) * 0.5f - 0.5f;
        const glm::ivec2 q0 = glm::ivec2(glm::floor(q));
        const glm::vec2 f = q - glm::vec2(q0);
        return (1 - f.y) * ((1 - f.x) * low(q0.x, q0.y) + f.x * low(q0.x + 1, q0.y)) +
               f.y * ((1 - f.x) * low(q0.x, q0.y + 1) + f.x * low(q0.x + 1, q0.y + 1));
    };

    // Edge pixels: another surface within the two full-resolution pixels the
    // upsampler's four trace pixels reach; flat pixels: none within four.
    double flatWorst = 0.0, flatSum = 0.0, edgeSumUp = 0.0, edgeSumBilinear = 0.0, edgeWorstUp = 0.0;
    int flat = 0, edge = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            bool mixed2 = false, mixed4 = false;
            for (int dy = -4; dy <= 4; ++dy)
                for (int dx = -4; dx <= 4; ++dx) {
                    const bool other = surface(x + dx, y + dy) != surface(x, y);
                    mixed4 |= other;
                    mixed2 |= other && std::abs(dx) <= 2 && std::abs(dy) <= 2;
                }
            const double ref = value(full, x, y);
            ASSERT_GT(ref, 0.0) << x << " " << y;
            const double up = std::abs(value(half, x, y) - ref) / ref;
            if (!mixed4) {
                flatWorst = std::max(flatWorst, up);
                flatSum += up;
                ++flat;
            } else if (mixed2) {
                edgeSumUp += up;
                edgeSumBilinear += std::abs(bilinear(x, y) - ref) / ref;
                edgeWorstUp = std::max(edgeWorstUp, up);
                ++edge;
            }
        }
    const double edgeUp = edgeSumUp / edge, edgeBilinear = edgeSumBilinear / edge;
    std::printf("flat pixels: %d, relative difference to the full-resolution trace: mean %.4f, worst %.4f\n", flat,
                flatSum / flat, flatWorst);
    std::printf("edge pixels: %d, mean relative difference: depth-aware %.4f (worst %.4f), bilinear %.4f\n", edge,
                edgeUp, edgeWorstUp, edgeBilinear);
    ASSERT_GT(flat, n * n / 2);
    ASSERT_GT(edge, 4 * 40);
    // Measured on lavapipe: flat pixels mean 0.0025, worst 0.065 (the
    // full-resolution trace itself steps by up to 8 % between neighbouring
    // pixels where a pixel's cone origin crosses into another voxel, which
    // no upsampling reproduces); edge pixels mean 0.142, bilinear 1.26 (8.9x
    // worse), worst 1.23. Bounds about 1.5x.
    EXPECT_LT(flatWorst, 0.1);
    EXPECT_LT(edgeUp, 0.21);
    EXPECT_LT(edgeUp * 6.0, edgeBilinear);
    // The depth weight 1 / (1 + 100 dz) keeps 3 % for this 0.3 m step seen from
    // 0.9 m (dz = 0.33); against the platform's 13x brighter indirect light
    // that still doubles the floor's value at a few pixels beside the edge.
    EXPECT_LT(edgeWorstUp, 1.85);
}

// A checkerboard floor of 2.5 cm squares (about 3 pixels) of albedo 0.9 and
// 0.1 under the emissive ceiling, traced at half resolution: the cone-traced
// diffuse term is demodulated (irradiance / pi), upsampled, and only then
// multiplied by each pixel's own albedo, so the indirect term is exactly the
// irradiance term times the G-buffer's albedo at every pixel, also where a
// trace pixel's neighbours lie on the other colour (an upsampled albedo-
// modulated term smeared 0.9 into the 0.1 squares there).
TEST_F(Upsampling, AlbedoIsAppliedAtFullResolutionAfterUpsampling) {
    scene::Scene s;
    const int bright = addMaterial(s, glm::vec3(0.9f)), dark = addMaterial(s, glm::vec3(0.1f));
    const float half = 0.0125f;
    for (int j = -24; j < 24; ++j)
        for (int i = -24; i < 24; ++i)
            addQuad(s, (i + j) % 2 == 0 ? bright : dark,
                    glm::vec3((float(i) + 0.5f) * 2.0f * half, 0.0f, (float(j) + 0.5f) * 2.0f * half), half);
    addQuad(s, addMaterial(s, glm::vec3(0.0f), glm::vec3(1.0f)), glm::vec3(0.0f, 1.0f, 0.0f), 1.0f,
            glm::angleAxis(glm::pi<float>(), glm::vec3(1, 0, 0)));
    addTopDownCamera(s, 0.9f, glm::radians(60.0f));
    render::Renderer r(context(), s, settings(0.5f));
    r.renderFrame();
    const image::ImageRGBA32F indirect = r.readTerm(sh::TERM_INDIRECT), irradiance = r.readTerm(sh::TERM_IRRADIANCE);
    const image::ImageRGBA32F albedo = r.readSurface().albedo;
    const int n = int(kSize);
    int lit = 0, beside = 0;
    double worst = 0.0;
    for (int y = 1; y + 1 < n; ++y)
        for (int x = 1; x + 1 < n; ++x) {
            const float a = albedo.at(uint32_t(x), uint32_t(y))[1];
            if (a <= 0.0f) continue;
            const float e = irradiance.at(uint32_t(x), uint32_t(y))[1], v = indirect.at(uint32_t(x), uint32_t(y))[1];
            ASSERT_GT(e, 0.0f) << x << " " << y;
            ++lit;
            bool other = false;
            for (int d = 0; d < 4; ++d) {
                const int dx = d == 0 ? 1 : (d == 1 ? -1 : 0), dy = d == 2 ? 1 : (d == 3 ? -1 : 0);
                other |= std::abs(albedo.at(uint32_t(x + dx), uint32_t(y + dy))[1] - a) > 0.1f;
            }
            beside += other;
            worst = std::max(worst, std::abs(double(v) - double(e) * a) / (double(e) * a));
        }
    std::printf("%d floor pixels, %d beside the other colour; largest |indirect - irradiance x albedo| / it: %.1e\n",
                lit, beside, worst);
    ASSERT_GT(lit, n * n / 2);
    ASSERT_GT(beside, n * n / 4);
    EXPECT_LT(worst, 1e-5);
}

}  // namespace
}  // namespace dvsgi::test
