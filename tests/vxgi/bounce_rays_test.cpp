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

// voxelNormal of the voxel at c from the read-back attribute sums, packed as the rays read it.
glm::vec3 normalOf(const VoxelReadback& attributes, glm::ivec3 c) {
    glm::vec3 n(0.0f);
    for (int a = 0; a < 3; ++a)
        n[a] = std::sqrt(attributes.at(c.x, c.y, c.z, shader::CH_NORMAL_POS_X + 2 * a)) -
               std::sqrt(attributes.at(c.x, c.y, c.z, shader::CH_NORMAL_NEG_X + 2 * a));
    const float len = glm::length(n);
    if (len <= 1e-6f) return glm::vec3(0.0f);
    // As the rays read it (BIND_BOUNCE_RAY_NORMALS): each axis in steps of 1/RAY_NORMAL_SCALE.
    const float scale = shader::RAY_NORMAL_SCALE;
    return glm::floor(glm::clamp(n / len, -1.0f, 1.0f) * scale + 0.5f) / scale;
}

// passesInFront: the ray p + d t, inside voxel c, leaves it (at tExit) before
// the plane through c's centre across c's normal nc.
bool passesInFront(glm::ivec3 c, glm::vec3 nc, glm::vec3 p, glm::vec3 d, float t, float tExit) {
    const glm::vec3 m = glm::abs(nc);
    if (std::max({m.x, m.y, m.z}) < 0.98f) return false;  // edges, corners, tilted surfaces: solid
    const float ahead = glm::dot(glm::vec3(c) + 0.5f - (p + d * t), nc), along = glm::dot(d, nc);
    if (ahead * along <= 0.0f) return false;
    return t + ahead / along > tExit;
}

// What a ray from p along d meets in `radiance`: the first occupied voxel not
// on the surface of `self` (normal n) that it does not pass in front of, as
// voxelRay does, cell by cell (nothing if that is the cell it starts in).
float march(const Rgba16Volume& radiance, const VoxelReadback& attributes, glm::vec3 p, glm::vec3 d,
            glm::ivec3 self, glm::vec3 n) {
    glm::ivec3 c = glm::ivec3(glm::floor(p));
    glm::ivec3 step(0);
    glm::vec3 tMax(1e30f), tDelta(1e30f);
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0f) continue;
        step[a] = d[a] > 0.0f ? 1 : -1;
        tDelta[a] = 1.0f / std::fabs(d[a]);
        tMax[a] = ((d[a] > 0.0f ? float(c[a] + 1) : float(c[a])) - p[a]) / d[a];
    }
    float t = 0.0f;  // where the ray entered cell c
    for (bool first = true;; first = false) {
        for (int a = 0; a < 3; ++a)
            if (c[a] < 0 || c[a] >= int(kN)) return 0.0f;
        const glm::vec4 r = radiance.at(c.x, c.y, c.z);
        const int a = tMax.x <= tMax.y && tMax.x <= tMax.z ? 0 : (tMax.y <= tMax.z ? 1 : 2);
        if (r.a > 0.0f) {
            const bool inSlab = std::fabs(glm::dot(glm::vec3(c - self), n)) < 1.5f;
            const bool own = inSlab && glm::dot(wallNormal(c), n) > 0.8f;
            // Starting inside another surface's voxel: its back, no light.
            if (!own && (first || !passesInFront(c, normalOf(attributes, c), p, d, t, tMax[a])))
                return first ? 0.0f : r.r;
        }
        t = tMax[a];
        c[a] += step[a];
        tMax[a] += tDelta[a];
    }
}

// voxelRaysCosine's mean over its rays: R2 directions shifted per voxel,
// cosine-distributed about n, from one voxel off the voxel's centre.
float cpuRays(const Rgba16Volume& radiance, const VoxelReadback& attributes, glm::ivec3 v, glm::vec3 n) {
    const uint32_t seed = shader::raySeed(v);
    const glm::vec3 t = glm::normalize(std::fabs(n.x) < 0.9f ? glm::cross(n, glm::vec3(1, 0, 0))
                                                             : glm::cross(n, glm::vec3(0, 1, 0)));
    const glm::vec3 b = glm::cross(n, t);
    const glm::vec3 origin = glm::vec3(v) + 0.5f + n;
    const glm::vec2 shift(float(seed & 0xffffu) / 65536.0f, float(seed >> 16) / 65536.0f);
    double sum = 0.0;
    for (uint32_t i = 0; i < kRays; ++i) {
        const glm::vec2 u = glm::fract(shift + float(i) * glm::vec2(shader::RAY_R2_U, shader::RAY_R2_V));
        const float rad = std::sqrt(u.x), phi = 6.28318530717959f * u.y;
        const glm::vec3 d = glm::normalize(t * (rad * std::cos(phi)) + b * (rad * std::sin(phi)) +
                                           n * std::sqrt(std::max(1.0f - u.x, 0.0f)));
        sum += march(radiance, attributes, origin, d, v, n);
    }
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
