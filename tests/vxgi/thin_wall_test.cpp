// Issue #15 item 4's scene: a closed room whose walls are one voxel thick,
// the sun outside. Nothing inside is lit directly, so all the indirect light
// that reaches a probe cube at the room's centre came through the walls; a
// probe outside, beside the sunlit room, gets the indirect light that should
// be there. The goal is inside <= 1 % of outside at 64^3 and 128^3.
// A wall voxel holds both faces: it is lit, bounced and shown per side
// (shaders/lib/voxel_sides.glsl), which took the leak from 140 % / 42 % to
// 8.4 % / 11.8 %. What still leaks with cones (docs/quality.md): coarse cells
// read near a wall mix in the cells beyond it. This test measures the leak
// and guards it against getting worse; with the bounce's rays
// (--bounce-trace rays), which stop at the first voxel they cross, it holds
// the goal. The ThinWallPixels tests check what
// the per-pixel gather shows beside a thin wall (no glow, no dark band).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

#include "gpu_fixture.h"
#include "light_helpers.h"
#include "vox_helper.h"
#include "shared/composite_pass.h"
#include "vxgi/voxel_light_settings.h"

namespace dvsgi::test {
namespace {

constexpr float kInner = 0.375f;  // the room's inner half-size: a voxel boundary at 64^3 and 128^3
constexpr float kProbe = 0.1f;    // the probe cubes' half-size
constexpr int kBands = 32;        // pixel bins, whole voxels from a wall, -16..15
// inside / outside indirect light measured on lavapipe, 2026-12-02 (the goal
// is 1 %); before the voxels' sides 140 % and 42 %, before the optical-depth
// sampling 196 % and 45 %.
constexpr double kLeak64 = 0.0837, kLeak128 = 0.118;

struct Probes {
    double inside = 0.0, outside = 0.0, insideDirect = 0.0, outsideDirect = 0.0;
};

// A directional light of 3 W/m^2 travelling along `direction`.
void addSun(scene::Scene& s, glm::vec3 direction) {
    scene::Light sun;
    sun.name = "sun";
    sun.type = scene::LightType::Directional;
    sun.intensity = 3.0f;
    addLight(s, sun, glm::vec3(0.0f, 0.9f, 0.0f), glm::normalize(direction));
}

scene::Scene thinWallRoom(uint32_t n) {
    const float v = 2.0f / float(n);
    scene::Scene s;
    const int grey = addMaterial(s, glm::vec3(0.8f));
    // Each wall a closed slab 0.8 voxel thick inside the voxel layer just
    // outside the inner boundary: one voxel layer holds both of its faces.
    const float mid = kInner + 0.5f * v, half = 0.4f * v, span = kInner + v;
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 extent(span), centre(0.0f);
            extent[axis] = half;
            centre[axis] = sign * mid;
            addBox(s, grey, extent, centre, false);
        }
    addBox(s, grey, glm::vec3(kProbe), glm::vec3(0.0f), false);               // inside
    addBox(s, grey, glm::vec3(kProbe), glm::vec3(0.7f, -0.55f, 0.0f), false);  // outside, +X side
    addBox(s, grey, glm::vec3(0.95f, 0.4f * v, 0.95f), glm::vec3(0.0f, -0.8f, 0.0f), false);  // ground
    addTopDownCamera(s, 0.9f, glm::radians(60.0f));
    addSun(s, glm::vec3(-0.4f, -1.0f, -0.3f));
    return s;
}

// Mean luminance of radiance and of direct light over a probe's voxels.
void probeMeans(const Rgba16Volume& radiance, const Rgba16Volume& direct, glm::vec3 centre, double& lit,
                double& directLit) {
    const int n = int(radiance.n);
    const float v = 2.0f / float(n);
    auto index = [&](float w) { return int((w + 1.0f) / v); };
    double sum = 0.0, sumDirect = 0.0;
    int count = 0;
    for (int z = index(centre.z - kProbe) - 1; z <= index(centre.z + kProbe) + 1; ++z)
        for (int y = index(centre.y - kProbe) - 1; y <= index(centre.y + kProbe) + 1; ++y)
            for (int x = index(centre.x - kProbe) - 1; x <= index(centre.x + kProbe) + 1; ++x) {
                const glm::vec4 r = radiance.at(x, y, z);
                if (r.a <= 0.0f) continue;
                const glm::vec4 d = direct.at(x, y, z);
                sum += 0.2126 * r.r + 0.7152 * r.g + 0.0722 * r.b;
                sumDirect += 0.2126 * d.r + 0.7152 * d.g + 0.0722 * d.b;
                ++count;
            }
    ASSERT_GT(count, 0);
    lit = sum / count;
    directLit = sumDirect / count;
}

Probes measure(uint32_t n, vxgi::BounceTrace trace) {
    render::RenderSettings rs = unitBoxGridSettings(n, 512);
    rs.voxelLight.bounceTrace = trace;
    rs.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    rs.voxelLight.bounces = 3;
    render::Renderer r(context(), thinWallRoom(n), rs);
    r.renderFrame();
    const Rgba16Volume radiance = readRgba16(r.volumes()->radiance), direct = readDirect(*r.volumes());
    Probes p;
    double lit = 0.0;
    probeMeans(radiance, direct, glm::vec3(0.0f), lit, p.insideDirect);
    p.inside = lit - p.insideDirect;
    probeMeans(radiance, direct, glm::vec3(0.7f, -0.55f, 0.0f), lit, p.outsideDirect);
    p.outside = lit - p.outsideDirect;
    return p;
}

class ThinWall : public GpuTest, public ::testing::WithParamInterface<std::tuple<uint32_t, vxgi::BounceTrace>> {};

TEST_P(ThinWall, LightLeakingIntoAClosedRoomIsMeasuredAndBounded) {
    const auto [n, trace] = GetParam();
    const bool rays = trace == vxgi::BounceTrace::Rays;
    const Probes p = measure(n, trace);
    const double leak = p.inside / p.outside;
    std::printf("  %u^3, %s: indirect inside %.5f, outside %.5f: inside / outside = %.2f %% (goal <= 1 %%); "
                "direct inside %.2e, outside %.4f\n",
                n, rays ? "rays" : "cones", p.inside, p.outside, 100.0 * leak, p.insideDirect, p.outsideDirect);
    // The sun cannot reach the inside directly (shadow map): what is there leaked.
    EXPECT_LT(p.insideDirect, 1e-3 * p.outsideDirect);
    ASSERT_GT(p.outside, 0.0);
    // 1.25 x the measured leak (docs/quality.md): a fix shows as a large
    // margin, a regression fails.
    // Rays stop at the first voxel they cross, so nothing comes in (measured 0).
    if (rays) {
        EXPECT_LE(leak, 0.01);
        return;
    }
    const double measured = n == 64 ? kLeak64 : kLeak128;
    EXPECT_LT(leak, 1.25 * measured) << "the thin-wall leak got worse";
}

INSTANTIATE_TEST_SUITE_P(Grids, ThinWall,
                         ::testing::Combine(::testing::Values(64u, 128u),
                                            ::testing::Values(vxgi::BounceTrace::Cones, vxgi::BounceTrace::Rays)),
                         [](const auto& info) {
                             return std::to_string(std::get<0>(info.param)) +
                                    (std::get<1>(info.param) == vxgi::BounceTrace::Rays ? "_rays" : "_cones");
                         });

// The per-pixel gather beside a thin wall. Its first samples, finer than the
// directional volumes' two-voxel cells, read the radiance volume, which has
// one value per voxel: a thin wall's voxel showed eq. 5's radiance (half its
// sunlit side) to pixels on both sides, a glowing band inside along the
// walls' base and a dark one beside their sunlit side. Where the voxels a
// sample reads are two-sided it now reads the directional sample (sides by
// the way the cone travels), and the radiance volume holds the darker side.
// Pixels' mean E / pi binned by whole voxels from the wall (signed: + the
// sunlit side), 128^2, every pixel traced.
struct Bands {
    double sum[kBands] = {};
    int count[kBands] = {};
    double mean(int from, int to) const {  // bins [from, to] (signed voxels)
        double s = 0.0;
        int c = 0;
        for (int b = from; b <= to; ++b) {
            s += sum[b + kBands / 2];
            c += count[b + kBands / 2];
        }
        return c ? s / c : 0.0;
    }
};

class ThinWallPixels : public GpuTest {};

render::RenderSettings pixelSettings(uint32_t n, uint32_t bounces) {
    render::RenderSettings rs = unitBoxGridSettings(n, 512);
    rs.width = rs.height = 128;
    rs.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    rs.voxelLight.bounces = bounces;
    rs.outputTerm = shader::TERM_IRRADIANCE;
    rs.gather.traceScale = 1.0f;
    return rs;
}

void addBand(Bands& b, const image::ImageRGBA32F& img, uint32_t x, uint32_t y, double voxelsFromWall) {
    const int bin = int(std::floor(voxelsFromWall)) + kBands / 2;
    if (bin < 0 || bin >= kBands) return;
    const float* p = &img.rgba[(size_t(y) * img.width + x) * 4];
    b.sum[bin] += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    ++b.count[bin];
}

// A wall 0.6 high and 1.2 wide between x = x0 and x1 standing on ground two
// voxels thick whose top face is at `top`, seen from 0.6 above it, the sun
// on the wall's +x side.
scene::Scene wallOnGround(float v, float top, float x0, float x1) {
    scene::Scene s;
    const int grey = addMaterial(s, glm::vec3(0.8f));
    addBox(s, grey, glm::vec3(0.95f, 2.0f * v, 0.95f), glm::vec3(0.0f, top - 2.0f * v, 0.0f), false);
    addBox(s, grey, glm::vec3(0.5f * (x1 - x0), 0.3f, 0.6f), glm::vec3(0.5f * (x0 + x1), top + 0.3f, 0.0f), false);
    addTopDownCamera(s, 0.6f, glm::radians(70.0f));
    addSun(s, glm::vec3(-1.0f, -1.0f, -0.2f));
    return s;
}

// The ground's E/pi beside a wall 0.6 high on ground whose top face is at
// `top`, seen by addTopDownCamera from 0.6 up: pixels binned by whole voxels
// from x = lo on the -x side and from x = bandHi on the +x side, leaving out
// where the wall (its far face at x = face) stands or hides the ground from
// the camera (there the ray crosses the far face below the wall's top).
Bands groundBands(const scene::Scene& s, const render::RenderSettings& rs, const image::ImageRGBA32F& img, float top,
                  float v, float lo, float face, float bandHi) {
    Bands b;
    const float wallTop = top + 0.6f;
    for (uint32_t y = 0; y < rs.height; ++y)
        for (uint32_t x = 0; x < rs.width; ++x) {
            const glm::vec3 p = pixelOnPlane(s, rs, x, y, top);
            if (std::abs(p.z) > 0.4f) continue;
            if (p.x >= lo && (p.x <= face || 0.6f - (0.6f - top) * face / p.x < wallTop)) continue;
            addBand(b, img, x, y, p.x < lo ? (p.x - lo) / v : (p.x - bandHi) / v);
        }
    return b;
}

void checkRoomFloorBands(const scene::Scene& s, const render::RenderSettings& rs, uint32_t n, bool rays);

// The room above, seen from inside: the floor, away from the probe's shadow.
// Inside, everything is leaked light; the band within a voxel of the walls
// must not be brighter than the floor two to five voxels in. The gather's
// cones let some through; its rays (the default) none.
TEST_F(ThinWallPixels, RoomFloorShowsNoGlowAlongTheWalls) {
    constexpr uint32_t n = 64;
    scene::Scene s = thinWallRoom(n);
    s.cameras.clear();
    for (scene::Node& node : s.nodes) node.camera = -1;
    addTopDownCamera(s, 0.3f, glm::radians(110.0f));  // inside, looking down at the floor
    for (render::GatherTrace trace : {render::GatherTrace::Cones, render::GatherTrace::Rays}) {
        const bool rays = trace == render::GatherTrace::Rays;
        SCOPED_TRACE(rays ? "rays" : "cones");
        render::RenderSettings rs = pixelSettings(n, 3);
        rs.gather.trace = trace;
        checkRoomFloorBands(s, rs, n, rays);
    }
}

void checkRoomFloorBands(const scene::Scene& s, const render::RenderSettings& rs, uint32_t n, bool rays) {
    const image::ImageRGBA32F img = render(s, rs);
    const float v = 2.0f / float(n);
    Bands b;
    for (uint32_t y = 0; y < rs.height; ++y)
        for (uint32_t x = 0; x < rs.width; ++x) {
            const glm::vec3 p = pixelOnPlane(s, rs, x, y, -kInner);
            if (std::max(std::abs(p.x), std::abs(p.z)) > kInner) continue;
            if (std::max(std::abs(p.x), std::abs(p.z)) < 2.0f * kProbe) continue;
            addBand(b, img, x, y, (kInner - std::max(std::abs(p.x), std::abs(p.z))) / v);
        }
    const double band = b.mean(0, 0), inner = b.mean(2, 5);
    std::printf("  %s: floor inside, E/pi: within a voxel of the walls %.5f, 2-5 voxels in %.5f (ratio %.2f; "
                "1.50 before)\n",
                rays ? "rays" : "cones", band, inner, band / inner);
    if (rays) {
        EXPECT_EQ(inner, 0.0);  // the voxel bounce's rays and the gather's let nothing through the walls
        EXPECT_EQ(band, 0.0);
        return;
    }
    ASSERT_GT(inner, 0.0);
    EXPECT_LT(band / inner, 1.0);  // not brighter (measured 0.31: the walls' inner sides are dark)
}

// A thin wall standing on thick ground, the sun on its +x side: beside the
// sunlit side the ground gets the wall's light (no dark band; nearer the wall,
// more of it), beside the shadowed side no light through it (0.85x the ground
// further away; with the cones 1.09x, 2.31x before the two-sided voxels' near
// samples, 1.29x while they checked only the voxels on the sample's own line).
TEST_F(ThinWallPixels, BesideAWallSeeTheSideFacingThem) {
    constexpr uint32_t n = 64;
    const float v = 2.0f / float(n);
    const float top = -0.5f + 2.0f * v;  // the ground's top face
    // Both faces of the wall in the voxel layer x in [0, v).
    const scene::Scene s = wallOnGround(v, top, 0.1f * v, 0.9f * v);
    const render::RenderSettings rs = pixelSettings(n, 1);
    const image::ImageRGBA32F img = render(s, rs);
    const Bands b = groundBands(s, rs, img, top, v, 0.0f, 0.9f * v, v);  // bands from the voxel layer's faces
    const double litNear = b.mean(1, 3), litFar = b.mean(4, 6), darkNear = b.mean(-3, -1), darkFar = b.mean(-6, -4);
    std::printf("  E/pi beside the sunlit side 1-3 voxels %.4f, 4-6 voxels %.4f (ratio %.2f, 0.64 before); "
                "beside the shadowed side %.4f, %.4f (ratio %.2f, 2.31 before)\n",
                litNear, litFar, litNear / litFar, darkNear, darkFar, darkNear / darkFar);
    ASSERT_GT(litFar, 0.0);
    ASSERT_GT(darkFar, 0.0);
    // Measured 1.24 and 0.85 since the gather traces rays, filtered (1.17 and
    // 1.09 with the cones; 1.08 and 1.29 with the eight voxels checked alone).
    EXPECT_GT(litNear / litFar, 1.12);
    EXPECT_LT(darkNear / darkFar, 1.0);
}

// The voxel debug view (--view voxels:radiance) of a thin wall lit by the sun
// on one side, seen from either side, no bounce: the sunlit side shows
// rho / pi E cos(theta) (times the view's 0.8 shade for x faces), the other
// side black. The radiance texel holds the darker side (black here), so a
// view that showed the texel showed both sides black. Then one bounce off a
// floor on the sunlit side only, which each side's own reflected light shows.
TEST_F(ThinWallPixels, VoxelViewShowsTheSideFacingTheCamera) {
    constexpr uint32_t n = 64;
    const float v = 2.0f / float(n);
    constexpr float kRho = 0.8f;
    scene::Scene s;
    const int grey = addMaterial(s, glm::vec3(kRho));
    // Both faces of the wall in the voxel layer x in [0, v).
    addBox(s, grey, glm::vec3(0.4f * v, 0.4f, 0.4f), glm::vec3(0.5f * v, 0.0f, 0.0f), false);
    const glm::vec3 sunDir(-1.0f, -0.3f, -0.2f);
    addSun(s, sunDir);
    addTopDownCamera(s, 0.0f, glm::radians(40.0f));
    const size_t camera = s.nodes.size() - 1;
    render::RenderSettings rs = pixelSettings(n, 0);
    rs.width = rs.height = 32;
    rs.view.mode = render::ViewMode::VoxelRadiance;
    // The mean over the middle 16 x 16 pixels (all on the wall) seen from x.
    auto seenFrom = [&](float x) {
        scene::Node& cam = s.nodes[camera];
        cam.translation = glm::vec3(x, 0.0f, 0.0f);
        cam.rotation = glm::angleAxis(glm::half_pi<float>() * (x > 0.0f ? 1.0f : -1.0f), glm::vec3(0, 1, 0));
        const image::ImageRGBA32F img = render(s, rs);
        double sum = 0.0;
        for (uint32_t y = 8; y < 24; ++y)
            for (uint32_t px = 8; px < 24; ++px) sum += img.rgba[(size_t(y) * img.width + px) * 4];
        return sum / 256.0;
    };
    const double sunlit = seenFrom(0.9f), shadowed = seenFrom(-0.9f);
    const double want = 0.8 * kRho / glm::pi<double>() * 3.0 * -glm::normalize(sunDir).x;
    std::printf("  voxel view of a thin wall: sunlit side %.4f (rho/pi E cos x 0.8 = %.4f), shadowed side %.4f\n",
                sunlit, want, shadowed);
    EXPECT_NEAR(sunlit / want, 1.0, 0.02);
    EXPECT_LT(shadowed, 1e-3);

    // One bounce with a lit floor on the sunlit side only: that side shows its
    // direct and its reflected light, the other side still nothing (showing a
    // side's direct light with the other's reflected light would fail both).
    addBox(s, grey, glm::vec3(0.4f, v, 0.4f), glm::vec3(0.45f + v, -0.4f - v, 0.0f), false);
    rs.voxelLight.bounces = 1;
    const double sunlitBounced = seenFrom(0.9f), shadowedBounced = seenFrom(-0.9f);
    std::printf("  with one bounce off a floor on the sunlit side: sunlit side %.4f (+%.1f %%), shadowed side %.4f\n",
                sunlitBounced, 100.0 * (sunlitBounced / sunlit - 1.0), shadowedBounced);
    EXPECT_GT(sunlitBounced, 1.02 * sunlit);  // measured +4.1 %
    EXPECT_LT(shadowedBounced, 0.1 * (sunlitBounced - sunlit));
}

// A slab 0.7 voxel thick standing on thick ground, sun on its +x side, moved
// across the lattice in tenths of a voxel: at offsets 0.05-0.25 both faces
// lie in one voxel layer (a two-sided voxel), from 0.35 on in two (a
// one-sided layer per face). The light beside it should not depend on where
// the lattice falls, and today it does: next to the shadowed side the two
// layers let about 10x the light through, next to the sunlit side they show
// 1.4x it (against a traced reference, scripts/slab-compare.py, two layers
// are right beside the sunlit side and one layer 34 % too dark; the two
// layers leak to the shadowed side). Sponza's outer walls are such slabs at 128^3, and its indirect light
// moves by up to 18 % with the lattice (docs/quality.md, "Sponza's indirect
// light and where the lattice falls"). This measures the spread and guards it
// against getting worse; the goal is no spread.
TEST_F(ThinWallPixels, SlabAcrossTheLatticeIsMeasuredAndBounded) {
    constexpr uint32_t n = 64;
    const float v = 2.0f / float(n);
    const float top = -0.5f + 2.0f * v;  // the ground's top face
    double darkNear[2] = {1e30, 0.0}, darkFar[2] = {1e30, 0.0}, litNear[2] = {1e30, 0.0};  // min, max
    for (int tenth = 0; tenth < 10; ++tenth) {
        const float offset = 0.05f + 0.1f * float(tenth);
        const float x0 = offset * v, x1 = (offset + 0.7f) * v;
        const scene::Scene s = wallOnGround(v, top, x0, x1);
        const render::RenderSettings rs = pixelSettings(n, 3);
        const Bands b = groundBands(s, rs, render(s, rs), top, v, x0, x1, x1);  // bands from the slab's faces
        const double values[3] = {b.mean(-3, -1), b.mean(-8, -4), b.mean(1, 3)};
        double* ranges[3] = {darkNear, darkFar, litNear};
        for (int k = 0; k < 3; ++k) {
            ASSERT_GT(values[k], 0.0) << "offset " << offset;
            ranges[k][0] = std::min(ranges[k][0], values[k]);
            ranges[k][1] = std::max(ranges[k][1], values[k]);
        }
        std::printf("  offset %.2f (%s): E/pi beside the shadowed side 1-3 voxels %.4f, 4-8 voxels %.4f; beside the "
                    "sunlit side 1-3 voxels %.4f\n",
                    offset, offset + 0.7f < 1.0f ? "one layer" : "two layers", values[0], values[1], values[2]);
    }
    const double spreadDarkNear = darkNear[1] / darkNear[0], spreadDarkFar = darkFar[1] / darkFar[0],
                 spreadLitNear = litNear[1] / litNear[0];
    std::printf("  largest over smallest across the offsets: shadowed side 1-3 voxels %.2f, 4-8 voxels %.2f; sunlit "
                "side 1-3 voxels %.2f (the goal is 1)\n",
                spreadDarkNear, spreadDarkFar, spreadLitNear);
    // Measured on lavapipe, 2026-12-05, since the voxel bounce traces rays: the
    // one-layer slab's shadowed side 1-3 voxels away gets 0.0062-0.0075 (the
    // CPU path tracer: 0.0069; with the bounce's cones 0.02-0.04 came through),
    // the two layers' 0.062-0.118, which the per-pixel gather lets through; so
    // the shadowed side's spreads, 18.9 and 3.41, now measure the two layers'
    // leak against a right figure (4.21 and 1.43 with cones), and the bounds
    // are on the leak itself. Sunlit side: 1.39 (1.39 with cones).
    // Since the six cones turn per pixel (--cone-spin, 2026-12-06) the resolve's
    // 3x3 tent also blends floor pixels across the slab, which is under a
    // pixel wide from above: the one layer's shadowed side 1-3 voxels away
    // 0.0098-0.0109, the two layers' 0.064-0.118, 4-8 voxels away 0.035-0.037;
    // sunlit side 1.35. Since the per-pixel gather traces rays, filtered
    // (2026-12-06), the two layers leak no more than one: the shadowed side
    // 1-3 voxels away gets 0.0101-0.0114 at every offset, 4-8 voxels away
    // 0.0120-0.0132; the spreads are 1.12, 1.09 and, sunlit side, 1.16.
    // Since rays pass beside thin walls' ends (2026-12-07), the one layer's
    // shadowed side 4-8 voxels away gets 0.0114-0.0115 (nearer the tracer's
    // 0.0082; the two layers' 0.0121-0.0131), 1-3 voxels away 0.0102-0.0117:
    // spreads 1.15, 1.15 and, sunlit side, 1.13. Since the gather's rays start
    // before a surface facing back within their offset (pixelRayOffset), the
    // two layers' shadowed side 1-3 voxels away gets 0.0097-0.0107 (the
    // tracer's 0.0069), the one layer's 0.0107-0.0116: spread 1.20.
    // Bounds 1.5x the values, and the spreads' excess over 1.
    EXPECT_LT(darkNear[0], 0.015);
    EXPECT_LT(darkNear[1], 0.017);
    EXPECT_LT(darkFar[1], 0.02);
    EXPECT_LT(spreadDarkNear, 1.3);
    EXPECT_LT(spreadDarkFar, 1.23);
    EXPECT_LT(spreadLitNear, 1.2);
}

}  // namespace
}  // namespace dvsgi::test
