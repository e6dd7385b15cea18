// The per-pixel gather against a closed form: a black floor beside a 2 m x 2 m
// wall that emits L = 1 toward it, the wall perpendicular to the floor. The
// irradiance on the floor is Lambert's polygon formula; the six cones' own
// answer (each cone's hit fraction, sampled uniformly over its 30-degree solid
// angle, with the paper's weights) shows how much of dvsgi's error is the
// six-cone partition and how much the tracing of each cone.
#include <cmath>
#include <cstdio>
#include <random>

#include <glm/gtc/constants.hpp>

#include "gpu_fixture.h"
#include "shared/composite_pass.h"
#include "shared/voxel_data.h"

namespace dvsgi::test {
namespace {

namespace sh = dvsgi::shader;

// The wall: x = -1, 0 <= y <= 2, |z| <= 1, emitting toward +X.
const glm::dvec3 kWall[4] = {{-1, 0, -1}, {-1, 2, -1}, {-1, 2, 1}, {-1, 0, 1}};

// E / (pi L) at p on the floor (normal +Y): Lambert's formula, the sum over
// the polygon's edges of the angle each subtends times the cosine term.
double closedForm(const glm::dvec3& p) {
    double sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        const glm::dvec3 a = glm::normalize(kWall[i] - p), b = glm::normalize(kWall[(i + 1) % 4] - p);
        sum += std::acos(glm::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::normalize(glm::cross(a, b)).y;
    }
    return std::abs(sum) / (2.0 * glm::pi<double>());
}

bool hitsWall(const glm::dvec3& p, const glm::dvec3& r) {
    if (r.x >= 0.0) return false;
    const glm::dvec3 h = p + r * ((-1.0 - p.x) / r.x);
    return h.y >= 0.0 && h.y <= 2.0 && std::abs(h.z) <= 1.0;
}

// The six cones of lib/cone_trace.glsl around n = +Y (basis t = +Z, b = +X),
// each cone's fraction of rays that meet the wall, weighted 1/3.5 and 0.5/3.5.
double sixConeAnswer(const glm::dvec3& p, std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const glm::dvec3 n(0, 1, 0), t(0, 0, 1), b(1, 0, 0);
    const double cosMax = std::cos(glm::radians(30.0));
    double e = 0.0;
    for (int k = 0; k < 6; ++k) {
        const double phi = glm::two_pi<double>() * (k - 1) / 5.0;
        const glm::dvec3 d =
            k == 0 ? n : glm::normalize(0.5 * n + 0.8660254 * (std::cos(phi) * t + std::sin(phi) * b));
        const glm::dvec3 e1 = glm::normalize(glm::cross(std::abs(d.y) < 0.99 ? n : b, d)), e2 = glm::cross(d, e1);
        constexpr int kRays = 2000;
        int hits = 0;
        for (int i = 0; i < kRays; ++i) {
            const double c = 1.0 - u(rng) * (1.0 - cosMax), s = std::sqrt(1.0 - c * c);
            const double a = glm::two_pi<double>() * u(rng);
            hits += hitsWall(p, c * d + s * (std::cos(a) * e1 + std::sin(a) * e2));
        }
        e += (k == 0 ? 1.0 : 0.5) / 3.5 * double(hits) / kRays;
    }
    return e;
}

// The black floor and the emissive wall, seen from above, gathered at 64^3.
render::RenderSettings wallScene(scene::Scene& s, render::GatherTrace trace) {
    addQuad(s, addMaterial(s, glm::vec3(0.0f)), glm::vec3(0.0f), 1.0f);
    addQuad(s, addMaterial(s, glm::vec3(0.0f), glm::vec3(1.0f)), glm::vec3(-1.0f, 1.0f, 0.0f), 1.0f,
            glm::angleAxis(-glm::half_pi<float>(), glm::vec3(0, 0, 1)));  // normal +X
    addTopDownCamera(s, 1.8f, glm::radians(60.0f));
    render::RenderSettings rs;
    rs.width = rs.height = 128;
    rs.shadowMapSize = 256;
    rs.voxels = 64;
    rs.outputTerm = sh::TERM_IRRADIANCE;  // E / pi
    rs.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    rs.voxelLight.bounces = 0;  // the floor is black: the gather is all there is
    rs.emitterLights = false;   // the wall's emission in the voxels, gathered by the cones or rays
    rs.gather.trace = trace;
    rs.gather.traceScale = 1.0f;
    rs.gather.spin = false;  // the paper's six cones, as sixConeAnswer turns them; each pixel's own rays
    rs.hasVoxelBox = true;  // the whole wall inside the grid: 3.2 m, 5 cm voxels
    rs.voxelBoxMin = glm::vec3(-1.1f, -0.6f, -1.6f);
    rs.voxelBoxMax = glm::vec3(2.1f, 2.6f, 1.6f);
    return rs;
}

// The floor pixels away from its edges, binned by their distance from the
// wall in fours of voxels up to 28: calls f(bin, x, y, exact E / (pi L)).
template <typename F>
void forEachBinnedPixel(const scene::Scene& s, const render::RenderSettings& rs, int bins, F&& f) {
    const double voxel = 3.2 / 64.0;
    for (uint32_t y = 0; y < rs.height; ++y)
        for (uint32_t x = 0; x < rs.width; ++x) {
            const glm::vec3 p = pixelOnPlane(s, rs, x, y, 0.0f);
            if (std::abs(p.x) > 0.98f || std::abs(p.z) > 0.6f) continue;  // away from the floor's edges
            const int bin = int((p.x + 1.0) / voxel / 4.0);
            if (bin < bins) f(bin, x, y, closedForm(glm::dvec3(p.x, 0.0, p.z)));
        }
}

TEST_F(GpuTest, GatherFromAPerpendicularEmissiveWallAgainstItsClosedForm) {
    scene::Scene s;
    const render::RenderSettings rs = wallScene(s, render::GatherTrace::Cones);
    const image::ImageRGBA32F img = render(s, rs);

    // Pixels binned by their distance from the wall, four voxels a bin, up to
    // 1.4 m: farther, the wall is small in the hemisphere and the six-cone
    // partition itself drifts (+8.5 % to +18 % over 28-40 voxels).
    constexpr int kBins = 7;
    double got[kBins] = {}, exact[kBins] = {}, gotSampled[kBins] = {}, exactSampled[kBins] = {}, six[kBins] = {};
    int count[kBins] = {};
    double gotSum = 0.0, exactSum = 0.0;
    std::mt19937 rng(11);
    forEachBinnedPixel(s, rs, kBins, [&](int bin, uint32_t x, uint32_t y, double e) {
        const double g = img.at(x, y)[0];
        got[bin] += g;
        exact[bin] += e;
        ++count[bin];
        gotSum += g;
        exactSum += e;
        if (y % 4 == 0) {  // the six cones' answer is sampled: every fourth row
            const glm::vec3 p = pixelOnPlane(s, rs, x, y, 0.0f);
            gotSampled[bin] += g;
            exactSampled[bin] += e;
            six[bin] += sixConeAnswer(glm::dvec3(p.x, 0.0, p.z), rng);
        }
    });
    std::printf("voxels from the wall: dvsgi / closed form, six cones / closed form, dvsgi / six cones\n");
    double worstPartition = 0.0, worstTrace = 0.0;
    for (int b = 0; b < kBins; ++b) {
        ASSERT_GT(count[b], 0);
        const double sixOverExact = six[b] / exactSampled[b];
        const double traceOverSix = gotSampled[b] / six[b];
        std::printf("  %2d-%2d: %.3f  %.3f  %.3f\n", 4 * b, 4 * b + 4, got[b] / exact[b], sixOverExact, traceOverSix);
        worstPartition = std::max(worstPartition, std::abs(sixOverExact - 1.0));
        if (b > 0) worstTrace = std::max(worstTrace, std::abs(traceOverSix - 1.0));
    }
    std::printf("these pixels: dvsgi / closed form %.3f\n", gotSum / exactSum);
    // The six-cone partition itself is right here: measured within 3.4 %
    // (the sampling's noise included).
    EXPECT_LT(worstPartition, 0.045);
    // The tracing of each cone is what errs (docs/quality.md, "A wall beside
    // a floor"): measured +19.2 % over these pixels and at most +20.2 % in a
    // bin past the first, where the cones start among the wall's own cells
    // (+42.7 %). Bounds 1.5x.
    EXPECT_NEAR(gotSum / exactSum, 1.0, 0.29);
    EXPECT_LT(worstTrace, 0.30);
}

// The same floor gathered by rays (--gather-trace rays, the default): each
// pixel's cosine rays through the wall's voxels, no cone at all, so what is
// left is the voxels' own error (the wall a layer of 5 cm voxels, the rays'
// start a voxel off the floor) and the rays' noise.
TEST_F(GpuTest, GatherByRaysFromAPerpendicularEmissiveWallAgainstItsClosedForm) {
    scene::Scene s;
    render::RenderSettings rs = wallScene(s, render::GatherTrace::Rays);
    rs.gather.rays = 64;
    const image::ImageRGBA32F img = render(s, rs);
    constexpr int kBins = 7;
    double got[kBins] = {}, exact[kBins] = {};
    double gotSum = 0.0, exactSum = 0.0;
    forEachBinnedPixel(s, rs, kBins, [&](int bin, uint32_t x, uint32_t y, double e) {
        got[bin] += img.at(x, y)[0];
        exact[bin] += e;
        gotSum += img.at(x, y)[0];
        exactSum += e;
    });
    std::printf("voxels from the wall: dvsgi (rays) / closed form\n");
    double worst = 0.0;
    for (int b = 0; b < kBins; ++b) {
        ASSERT_GT(exact[b], 0.0);
        std::printf("  %2d-%2d: %.3f\n", 4 * b, 4 * b + 4, got[b] / exact[b]);
        worst = std::max(worst, std::abs(got[b] / exact[b] - 1.0));
    }
    std::printf("these pixels: dvsgi (rays) / closed form %.3f\n", gotSum / exactSum);
    // Measured +4.8 % over these pixels, +4.0 to +6.6 % per bin (the cones:
    // +19.2 %, +42.7 % in the first bin): the wall's voxels reach up to a voxel
    // past its edges (conservative voxelization), 5 % of its area here.
    // Bounds 1.5x.
    EXPECT_NEAR(gotSum / exactSum, 1.0, 0.072);
    EXPECT_LT(worst, 0.10);
}

}  // namespace
}  // namespace dvsgi::test
