// Issue #15 item 4's scene: a closed room whose walls are one voxel thick,
// the sun outside. Nothing inside is lit directly, so all the indirect light
// that reaches a probe cube at the room's centre came through the walls; a
// probe outside, beside the sunlit room, gets the indirect light that should
// be there. The goal is inside <= 1 % of outside at 64^3 and 128^3.
// A wall voxel holds both faces: it is lit, bounced and shown per side
// (shaders/lib/voxel_sides.glsl), which took the leak from 140 % / 42 % to
// 8.4 % / 11.8 %. What still leaks (docs/quality.md): coarse cells read by
// cones near a wall mix in the cells beyond it. This test measures the leak
// and guards it against getting worse.
#include <cstdio>

#include "gpu_fixture.h"
#include "light_helpers.h"
#include "vox_helper.h"
#include "vxgi/voxel_light_settings.h"

namespace dvsgi::test {
namespace {

constexpr float kInner = 0.375f;  // the room's inner half-size: a voxel boundary at 64^3 and 128^3
constexpr float kProbe = 0.1f;    // the probe cubes' half-size
// inside / outside indirect light measured on lavapipe, 2026-12-02 (the goal
// is 1 %); before the voxels' sides 140 % and 42 %, before the optical-depth
// sampling 196 % and 45 %.
constexpr double kLeak64 = 0.0837, kLeak128 = 0.118;

struct Probes {
    double inside = 0.0, outside = 0.0, insideDirect = 0.0, outsideDirect = 0.0;
};

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
    scene::Light sun;
    sun.name = "sun";
    sun.type = scene::LightType::Directional;
    sun.intensity = 3.0f;
    addLight(s, sun, glm::vec3(0.0f, 0.9f, 0.0f), glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f)));
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

Probes measure(uint32_t n) {
    render::RenderSettings rs = unitBoxGridSettings(n, 512);
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

class ThinWall : public GpuTest, public ::testing::WithParamInterface<uint32_t> {};

TEST_P(ThinWall, LightLeakingIntoAClosedRoomIsMeasuredAndBounded) {
    const uint32_t n = GetParam();
    const Probes p = measure(n);
    const double leak = p.inside / p.outside;
    std::printf("  %u^3: indirect inside %.5f, outside %.5f: inside / outside = %.1f %% (goal <= 1 %%); "
                "direct inside %.2e, outside %.4f\n",
                n, p.inside, p.outside, 100.0 * leak, p.insideDirect, p.outsideDirect);
    // The sun cannot reach the inside directly (shadow map): what is there leaked.
    EXPECT_LT(p.insideDirect, 1e-3 * p.outsideDirect);
    ASSERT_GT(p.outside, 0.0);
    // 1.25 x the measured leak (docs/quality.md): a fix shows as a large
    // margin, a regression fails.
    const double measured = n == 64 ? kLeak64 : kLeak128;
    EXPECT_LT(leak, 1.25 * measured) << "the thin-wall leak got worse";
}

INSTANTIATE_TEST_SUITE_P(Grids, ThinWall, ::testing::Values(64u, 128u));

}  // namespace
}  // namespace dvsgi::test
