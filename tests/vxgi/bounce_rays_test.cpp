// The voxel bounce's rays (--bounce-trace rays, shaders/lib/voxel_rays.glsl)
// against the same rays marched on the CPU: an open box of emissive walls
// (32^3), its radiance read back before the bounce, and for every inner wall
// voxel the rays the shader casts (same directions, same start, same rule for
// the voxel's own surface) walked voxel by voxel through that radiance. What
// one bounce adds to each voxel must be albedo times their mean.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "gpu_fixture.h"
#include "light_helpers.h"
#include "shared/bounce_pass.h"
#include "shared/voxel_data.h"
#include "ray_march.h"
#include "vox_helper.h"
#include "vxgi/voxel_light_settings.h"

namespace dvsgi::test {
namespace {

constexpr uint32_t kN = 32;
constexpr float kHalf = 0.71875f;  // walls in the middle of voxel layers 4 and 27 of [-1, 1]^3
constexpr int kLow = 4, kHigh = 27, kInnerLo = 6, kInnerHi = 25;
constexpr float kRho = 0.5f, kL = 1.0f;
constexpr uint32_t kRays = 16;

// The inward normal of a voxel in exactly one wall layer (the box's faces; the
// top is open), or zero for voxels in none or in two (edges: their normal is
// diagonal, so no ray counts them as its own surface).
glm::vec3 wallNormal(glm::ivec3 c) {
    glm::vec3 n(0.0f);
    int walls = 0;
    for (int a = 0; a < 3; ++a) {
        if (c[a] == kLow) n[a] = 1.0f, ++walls;
        if (c[a] == kHigh && a != 1) n[a] = -1.0f, ++walls;
    }
    return walls == 1 ? n : glm::vec3(0.0f);
}

// voxelRaysCosine's mean over its rays: R2 directions shifted per voxel,
// cosine-distributed about n, from one voxel off the voxel's centre.
float cpuRays(const Rgba16Volume& radiance, const VoxelReadback& attributes, glm::ivec3 v, glm::vec3 n) {
    const uint32_t seed = shader::raySeed(v);
    const glm::vec3 origin = glm::vec3(v) + 0.5f + n;
    // The voxel's own surface: its wall's layer, by the walls' own normals.
    const auto own = [&](glm::ivec3 c) {
        return std::fabs(glm::dot(glm::vec3(c - v), n)) < 1.5f && glm::dot(wallNormal(c), n) > 0.8f;
    };
    const auto normalAt = [&](glm::ivec3 c) { return rayNormalOf(attributes, c); };
    double sum = 0.0;
    for (uint32_t i = 0; i < kRays; ++i)
        sum += marchRay(radiance, origin, cosineRay(n, seed, i), own, normalAt, RayStart::Voxel).r;
    return float(sum / kRays);
}

Rgba16Volume radianceAfter(const scene::Scene& s, uint32_t bounces, VoxelReadback* attributes = nullptr) {
    render::RenderSettings rs = unitBoxGridSettings(kN, 256);
    rs.voxelLight.bounceTrace = vxgi::BounceTrace::Rays;
    rs.voxelLight.bounceRays = kRays;
    rs.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    rs.voxelLight.bounces = bounces;
    render::Renderer r(context(), s, rs);
    r.renderFrame();
    if (attributes) *attributes = readVoxels(*r.volumes());
    return readRgba16(r.volumes()->radiance);
}

class BounceRays : public GpuTest {};

TEST_F(BounceRays, MatchTheSameRaysMarchedOnTheCpu) {
    scene::Scene s;
    addInwardBox(s, addMaterial(s, glm::vec3(kRho), glm::vec3(kL)), glm::vec3(0.0f), kHalf, true);
    addTopDownCamera(s, 0.0f, 1.0f);
    VoxelReadback attributes;
    const Rgba16Volume before = radianceAfter(s, 0, &attributes), after = radianceAfter(s, 1);
    double sumGpu = 0.0, sumCpu = 0.0, worst = 0.0;
    int count = 0;
    forEachWallVoxel(kLow, kHigh, kInnerLo, kInnerHi, [&](glm::ivec3 v) {
        if (v.y == kHigh) return;  // the opening
        const float gpu = after.at(v.x, v.y, v.z).r - before.at(v.x, v.y, v.z).r;
        const float cpu = kRho * cpuRays(before, attributes, v, wallNormal(v));
        sumGpu += gpu;
        sumCpu += cpu;
        worst = std::max(worst, double(std::fabs(gpu - cpu)));
        ++count;
    });
    std::printf("  %d wall voxels: reflected light GPU %.5f, CPU %.5f (%+.3f%%); worst voxel off by %.4f\n", count,
                sumGpu / count, sumCpu / count, 100.0 * (sumGpu / sumCpu - 1.0), worst);
    ASSERT_GT(count, 1000);
    EXPECT_NEAR(sumGpu / sumCpu, 1.0, 0.002);
    EXPECT_LT(worst, 0.02);
}

}  // namespace
}  // namespace dvsgi::test
