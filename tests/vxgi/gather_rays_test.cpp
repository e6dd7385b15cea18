// The per-pixel gather by rays (--gather-trace rays, gather.comp's RAYS and
// lib/voxel_rays.glsl's pixelRaysCosine) against the same rays marched on the
// CPU: an open box of emissive walls (32^3) seen from above, its radiance
// read back after the frame, and for every floor pixel the rays the shader
// casts (the same directions from the pixel's seed, the same start off the
// floor, the same rules for the floor's own voxels) walked cell by cell
// through that radiance. The irradiance term is E / pi, their mean.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "gpu_fixture.h"
#include "light_helpers.h"
#include "ray_march.h"
#include "render/gather.h"
#include "shared/bounce_pass.h"
#include "shared/composite_pass.h"
#include "vox_helper.h"

namespace dvsgi::test {
namespace {

constexpr uint32_t kN = 32;
constexpr uint32_t kRays = 16;
constexpr float kOffset = 1.0f;  // voxels

class GatherRays : public GpuTest {};

// The gather by kRays rays per pixel over the voxels' own light (no voxel
// bounce), starting `offset` voxels off the surface, every pixel traced
// (trace pixel = image pixel, whose seed the CPU repeats) with its own rays
// (not resolved with its neighbours').
void gatherEveryPixelByRays(render::RenderSettings& rs, float offset) {
    rs.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    rs.voxelLight.bounces = 0;
    rs.gather.trace = render::GatherTrace::Rays;
    rs.gather.rays = kRays;
    rs.gather.rayOffsetVoxels = offset;
    rs.gather.traceScale = 1.0f;
    rs.gather.spin = false;
}

// One frame rendered with `rs`, and what the CPU needs to march the same rays:
// the output image, the radiance volume, the attribute sums (the rays'
// normals) and the extents and side light (EdgeModel, with rs's
// --edge-voxels setting).
struct GatherFrame {
    image::ImageRGBA32F img;
    Rgba16Volume radiance;
    VoxelReadback attributes;
    EdgeModel edges;
};

GatherFrame renderGather(const scene::Scene& s, const render::RenderSettings& rs) {
    render::Renderer r(context(), s, rs);
    r.renderFrame();
    GatherFrame f{r.readOutput(), readRgba16(r.volumes()->radiance), readVoxels(*r.volumes()), {}};
    f.edges = edgeModel(context(), *r.volumes(), f.attributes, rs.voxelLight.edgeFaces);
    return f;
}

// The rays of one block of GATHER_RAY_BLOCK^2 trace pixels (gatherRaySeed),
// as points of the unit square before they are lifted onto the hemisphere:
// together they are one R2 sequence, so every cell of a grid holding four
// points on average holds two to six (a hash per pixel, as before, leaves
// cells empty or with twice as many).
TEST(GatherRaySeed, ABlockOfPixelsSpreadsItsRaysOverTheSquare) {
    for (uint32_t count : {16u, 64u})
        for (glm::uvec2 corner : {glm::uvec2(0, 0), glm::uvec2(4, 8), glm::uvec2(100, 36)}) {
            const uint32_t side = shader::GATHER_RAY_BLOCK, points = side * side * count;
            const uint32_t m = uint32_t(std::lround(std::sqrt(points / 4.0)));
            std::vector<int> cells(size_t(m) * m, 0);
            for (uint32_t y = 0; y < side; ++y)
                for (uint32_t x = 0; x < side; ++x) {
                    const uint32_t seed = shader::gatherRaySeed(corner.x + x, corner.y + y, count);
                    const glm::vec2 shift(float(seed & 0xffffu) / 65536.0f, float(seed >> 16) / 65536.0f);
                    for (uint32_t i = 0; i < count; ++i) {
                        const glm::vec2 u =
                            glm::fract(shift + float(i) * glm::vec2(shader::RAY_R2_U, shader::RAY_R2_V));
                        ++cells[size_t(std::min(uint32_t(u.y * m), m - 1)) * m + std::min(uint32_t(u.x * m), m - 1)];
                    }
                }
            const auto [lo, hi] = std::minmax_element(cells.begin(), cells.end());
            EXPECT_GE(*lo, 2) << count << " rays, block at " << corner.x << "," << corner.y;
            EXPECT_LE(*hi, 6) << count << " rays, block at " << corner.x << "," << corner.y;
        }
}

// The box's half size: its walls in the middle of voxel layers 4 and 27 of
// [-1, 1]^3, or 0.3 of a voxel toward the grid's faces from there. Then the
// floor pixels nearest a wall start their rays in its voxel behind the plane
// through the voxel's centre, the case pixelRayStart counts as in front.
class GatherRaysBox : public GatherRays, public ::testing::WithParamInterface<float> {};

TEST_P(GatherRaysBox, MatchTheSameRaysMarchedOnTheCpu) {
    const float half = GetParam();
    // Whole voxels (the default), and edge voxels as their faces: the CPU
    // march then takes the extents and the faces too (ray_march.h, EdgeModel).
    for (bool faces : {false, true}) {
    SCOPED_TRACE(faces ? "--edge-voxels faces" : "--edge-voxels whole");
    scene::Scene s;
    addInwardBox(s, addMaterial(s, glm::vec3(0.5f), glm::vec3(1.0f)), glm::vec3(0.0f), half, true);
    addTopDownCamera(s, 0.6f, glm::radians(70.0f));
    render::RenderSettings rs = unitBoxGridSettings(kN, 256);
    rs.width = rs.height = 48;
    rs.outputTerm = shader::TERM_IRRADIANCE;  // E / pi
    gatherEveryPixelByRays(rs, kOffset);  // the walls' emission is all the voxels hold
    rs.voxelLight.edgeFaces = faces;
    const auto [img, radiance, attributes, edges] = renderGather(s, rs);
    const float voxel = 2.0f / float(kN);
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    const auto normalAt = [&](glm::ivec3 c) { return rayNormalOf(attributes, c); };

    double sumGpu = 0.0, sumCpu = 0.0, worst = 0.0;
    int count = 0, behind = 0;
    for (uint32_t y = 0; y < rs.height; ++y)
        for (uint32_t x = 0; x < rs.width; ++x) {
            const glm::vec3 world = pixelOnPlane(s, rs, x, y, -half);
            // The floor up to the walls, whose voxels the rays of the pixels
            // beside them start in (the pixel's rule for such a start).
            if (std::fabs(world.x) > half - 0.1f * voxel || std::fabs(world.z) > half - 0.1f * voxel) continue;
            const glm::vec3 p = (world + 1.0f) / voxel;
            const auto own = [&](glm::ivec3 c) {
                return std::fabs(glm::dot(glm::vec3(c) + 0.5f - p, n)) < 1.5f && glm::dot(normalAt(c), n) > 0.8f;
            };
            // Rays starting in a one-sided voxel of another surface, behind its centre's plane.
            const float start = pixelRayOffset(radiance, normalAt, p, n, kOffset);
            const glm::vec3 origin = p + n * start;
            const glm::ivec3 c = glm::ivec3(glm::floor(origin));
            const glm::vec3 nc = normalAt(c);
            behind += radiance.at(c.x, c.y, c.z).a >= 1.0f && !own(c) && glm::dot(nc, nc) > 0.25f &&
                      glm::dot(origin - (glm::vec3(c) + 0.5f), nc) < 0.0f;
            const uint32_t seed = shader::gatherRaySeed(x, y, kRays);
            double cpu = 0.0;
            for (uint32_t i = 0; i < kRays; ++i)
                cpu += pixelRay(radiance, p, n, start, cosineRay(n, seed, i), own, normalAt, edges).r;
            cpu /= kRays;
            const double gpu = img.at(x, y)[0];
            sumGpu += gpu;
            sumCpu += cpu;
            worst = std::max(worst, std::fabs(gpu - cpu));
            ++count;
        }
    std::printf("  %s: %d floor pixels (%d starting behind a wall voxel's centre plane): E/pi GPU %.5f, CPU %.5f "
                "(%+.3f%%); worst pixel off by %.4f\n",
                faces ? "faces" : "whole", count, behind, sumGpu / count, sumCpu / count,
                100.0 * (sumGpu / sumCpu - 1.0), worst);
    ASSERT_GT(count, 500);
    if (half > 0.72f) {
        EXPECT_GT(behind, 20);
    }
    EXPECT_NEAR(sumGpu / sumCpu, 1.0, 0.003);
    // One ray of 16 meeting a wall on one side and not on the other would be 1/16.
    EXPECT_LT(worst, 0.5 / kRays);
    }
}

INSTANTIATE_TEST_SUITE_P(WallAt, GatherRaysBox, ::testing::Values(0.71875f, 0.7375f),
                         [](const ::testing::TestParamInfo<float>& i) {
                             return i.param < 0.72f ? std::string("VoxelCentres") : std::string("OffCentres");
                         });

// The floor of the open box of emissive walls under a black quad hanging
// `quadUp` voxels over it (facing down, or up as the floor does), seen from
// `cameraUp` voxels up between the two with a wide view; the gather's rays
// start `offset` voxels off the floor. For the floor pixels under the quad's
// middle: the GPU's E / pi against the same rays on the CPU (pixelRay, with
// its start from pixelRayOffset), and against them marched by marchRay alone
// (no sheet met) from max(start, passFrom) voxels up.
struct UnderQuad {
    int count = 0, sheets = 0;  // pixels, and those finding a sheet (sheetAhead)
    double gpu = 0.0, cpu = 0.0, passing = 0.0, start = 0.0, worst = 0.0;  // means; worst |GPU - CPU|
};

UnderQuad floorUnderQuad(float quadUp, bool facingDown, float cameraUp, float offset, float passFrom) {
    constexpr float kHalf = 0.71875f;  // the floor in the middle of its voxel layer
    const float voxel = 2.0f / float(kN), floorY = -kHalf;
    scene::Scene s;
    addInwardBox(s, addMaterial(s, glm::vec3(0.5f), glm::vec3(1.0f)), glm::vec3(0.0f), kHalf, true);
    addQuad(s, addMaterial(s, glm::vec3(0.0f)), glm::vec3(0.0f, floorY + quadUp * voxel, 0.0f), 5.0f * voxel,
            facingDown ? glm::angleAxis(glm::pi<float>(), glm::vec3(1, 0, 0)) : glm::quat(1, 0, 0, 0));
    addTopDownCamera(s, floorY + cameraUp * voxel, glm::radians(150.0f));
    render::RenderSettings rs = unitBoxGridSettings(kN, 256);
    rs.width = rs.height = 48;
    rs.outputTerm = shader::TERM_IRRADIANCE;  // E / pi
    gatherEveryPixelByRays(rs, offset);
    const auto [img, radiance, attributes, edges] = renderGather(s, rs);
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    const auto normalAt = [&](glm::ivec3 c) { return rayNormalOf(attributes, c); };
    UnderQuad u;
    for (uint32_t y = 0; y < rs.height; ++y)
        for (uint32_t x = 0; x < rs.width; ++x) {
            const glm::vec3 world = pixelOnPlane(s, rs, x, y, floorY);
            if (std::max(std::fabs(world.x), std::fabs(world.z)) > 2.0f * voxel) continue;  // under the quad's middle
            const glm::vec3 p = (world + 1.0f) / voxel;
            const auto own = [&](glm::ivec3 c) {
                return std::fabs(glm::dot(glm::vec3(c) + 0.5f - p, n)) < 1.5f && glm::dot(normalAt(c), n) > 0.8f;
            };
            const float start = pixelRayOffset(radiance, normalAt, p, n, offset);
            int axis;
            u.sheets += sheetAhead(radiance, normalAt, edges, p, n, start, axis) >= 0.0f;
            const uint32_t seed = shader::gatherRaySeed(x, y, kRays);
            double cpu = 0.0, passing = 0.0;
            for (uint32_t i = 0; i < kRays; ++i) {
                const glm::vec3 d = cosineRay(n, seed, i);
                cpu += pixelRay(radiance, p, n, start, d, own, normalAt, edges).r;
                passing += marchRay(radiance, p + n * std::max(start, passFrom), d, own, normalAt, RayStart::Pixel,
                                    true, nullptr, &edges)
                               .r;
            }
            const double gpu = img.at(x, y)[0];
            u.gpu += gpu;
            u.cpu += cpu / kRays;
            u.passing += passing / kRays;
            u.start += start;
            u.worst = std::max(u.worst, std::fabs(gpu - cpu / kRays));
            ++u.count;
        }
    const double count = std::max(u.count, 1);
    u.gpu /= count;
    u.cpu /= count;
    u.passing /= count;
    u.start /= count;
    return u;
}

// A surface closer to the floor than the rays' start: a black quad facing
// down hangs 1.3 voxels over the floor, and the rays start 2 voxels off the
// floor. They start just before the quad's voxel instead (pixelRayOffset), so
// the floor under it sees the quad, not the walls beyond it.
TEST_F(GatherRays, SurfaceCloserThanTheStartIsMetNotSkipped) {
    constexpr float kStart = 2.0f;
    const UnderQuad u = floorUnderQuad(1.3f, true, 0.9f, kStart, kStart);
    std::printf("  %d floor pixels under the quad, rays starting %.2f voxels up: E/pi GPU %.5f, CPU %.5f; starting "
                "%.0f voxels up, past the quad: %.5f; worst pixel off by %.4f\n",
                u.count, u.start, u.gpu, u.cpu, kStart, u.passing, u.worst);
    ASSERT_GT(u.count, 200);
    EXPECT_NEAR(u.start, 0.45, 0.01);  // half a voxel to the quad's voxel, less the margin
    EXPECT_NEAR(u.gpu / u.cpu, 1.0, 0.01);
    EXPECT_LT(u.worst, 0.5 / kRays);
    // Under a black quad 4.5 voxels wide on each side, 0.85 voxels above the
    // rays' start, only grazing rays get out: 3 % of the cosine-weighted
    // hemisphere for a disc that wide. Started past it, they see the walls.
    EXPECT_LT(u.gpu, 0.1);
    EXPECT_GT(u.passing, 0.4);
}

// A sheet closer to the floor than the rays' start and facing the floor's way:
// the black quad faces up, `gap` voxels over the floor, in the floor's own
// voxel (0.4) or in the next one up (0.7). The march would pass it as the
// floor's own surface; the extents place it, so the rays that cross its plane
// within a voxel of the pixel's column meet its back (sheetAhead, meetsSheet).
class GatherRaysSheet : public GatherRays, public ::testing::WithParamInterface<float> {};

TEST_P(GatherRaysSheet, SheetInFrontOfTheStartIsMetFromBehind) {
    const float gap = GetParam();
    const UnderQuad u = floorUnderQuad(gap, false, 0.4f * gap, kOffset, 0.0f);
    std::printf("  sheet %.1f voxels up: %d floor pixels under it, %d finding it: E/pi GPU %.5f, CPU %.5f; passing it "
                "as the floor's own: %.5f; worst pixel off by %.4f\n",
                gap, u.count, u.sheets, u.gpu, u.cpu, u.passing, u.worst);
    ASSERT_GT(u.count, 200);
    EXPECT_EQ(u.sheets, u.count);
    EXPECT_NEAR(u.gpu / u.cpu, 1.0, 0.01);
    EXPECT_LT(u.worst, 0.5 / kRays);
    // The rays that cross the sheet's plane more than a voxel beside the
    // pixel's column go on past it: those more than about 60 degrees off the
    // normal, a quarter of the cosine-weighted hemisphere at most, and less
    // where the sheet lies closer. Passing the sheet, every ray sees the walls.
    EXPECT_LT(u.gpu, 0.25 * u.passing);
    EXPECT_GT(u.passing, 0.4);
}

INSTANTIATE_TEST_SUITE_P(Gaps, GatherRaysSheet, ::testing::Values(0.4f, 0.7f),
                         [](const ::testing::TestParamInfo<float>& i) {
                             return i.param < 0.5f ? std::string("InTheFloorsVoxel") : std::string("InTheNextVoxel");
                         });

// The rays' ambient occlusion, the mean over a pixel's rays of
// f(r) = 1 / (1 + lambda r) at the distance r (voxels) where each stops, under
// a solid ceiling 10.5 voxels above the rays' start: against the same rays on
// the CPU, for lambda 0 (every ray that meets the ceiling counts 1) and 0.5.
TEST_F(GatherRays, AmbientOcclusionMatchesTheSameRaysOnTheCpu) {
    constexpr uint32_t n = 64;
    const float voxel = 4.0f / float(n);  // the grid on [-2, 2]^3
    const auto world = [&](float v) { return -2.0f + v * voxel; };
    scene::Scene s;
    const int grey = addMaterial(s, glm::vec3(0.5f));
    addQuad(s, grey, glm::vec3(0.0f, world(24.5f), 0.0f), 28.0f * voxel);
    for (int layer = 36; layer < 44; ++layer)  // a solid ceiling, its faces down
        addQuad(s, grey, glm::vec3(0.0f, world(float(layer) + 0.5f), 0.0f), 28.0f * voxel,
                glm::angleAxis(glm::pi<float>(), glm::vec3(1, 0, 0)));
    addTopDownCamera(s, world(30.0f), glm::radians(40.0f));
    for (float lambda : {0.0f, 0.5f}) {
        render::RenderSettings rs;
        rs.width = rs.height = 24;
        rs.shadowMapSize = 256;
        rs.voxels = n;
        rs.hasVoxelBox = true;
        rs.voxelBoxMin = glm::vec3(-2.0f);
        rs.voxelBoxMax = glm::vec3(2.0f);
        rs.outputTerm = shader::TERM_AO;  // 1 - occlusion
        rs.gather.aoLambda = lambda;
        gatherEveryPixelByRays(rs, kOffset);
        const auto [img, radiance, attributes, edges] = renderGather(s, rs);
        const glm::vec3 up(0.0f, 1.0f, 0.0f);
        const auto normalAt = [&](glm::ivec3 c) { return rayNormalOf(attributes, c); };
        double sumGpu = 0.0, sumCpu = 0.0, worst = 0.0;
        for (uint32_t y = 0; y < rs.height; ++y)
            for (uint32_t x = 0; x < rs.width; ++x) {
                const glm::vec3 p = (pixelOnPlane(s, rs, x, y, world(24.5f)) + 2.0f) / voxel;
                const auto own = [&](glm::ivec3 c) {
                    return std::fabs(glm::dot(glm::vec3(c) + 0.5f - p, up)) < 1.5f && glm::dot(normalAt(c), up) > 0.8f;
                };
                const uint32_t seed = shader::gatherRaySeed(x, y, kRays);
                double occlusion = 0.0;
                for (uint32_t i = 0; i < kRays; ++i) {
                    float t = INFINITY;
                    marchRay(radiance, p + up * kOffset, cosineRay(up, seed, i), own, normalAt, RayStart::Pixel, true,
                             &t);
                    if (std::isfinite(t)) occlusion += 1.0 / (1.0 + lambda * t);
                }
                const double cpu = occlusion / kRays, gpu = 1.0 - img.at(x, y)[0];
                sumGpu += gpu;
                sumCpu += cpu;
                worst = std::max(worst, std::fabs(gpu - cpu));
            }
        const double pixels = double(rs.width * rs.height);
        std::printf("  lambda %.1f: occlusion GPU %.5f, CPU %.5f; worst pixel off by %.5f\n", lambda, sumGpu / pixels,
                    sumCpu / pixels, worst);
        // The term is stored as RGBA16F 1 - occlusion: steps of 2^-11 near 0.9
        // (measured: the means 0.0002 apart, the worst pixel 0.0005).
        EXPECT_NEAR(sumGpu / pixels, sumCpu / pixels, 0.0005) << "lambda " << lambda;
        EXPECT_LT(worst, 0.001) << "lambda " << lambda;
    }
}

}  // namespace
}  // namespace dvsgi::test
