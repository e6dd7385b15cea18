// The voxel light tests' synthetic voxels and CPU reference (inject_test.cpp,
// inject_edges_test.cpp): fragments summed into channels as voxelization sums
// them, the direct light each voxel should get in double, the lights, and a
// run of InjectPass with occlusion off.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "gpu/context.h"
#include "gpu/transfer.h"
#include "gpu_fixture.h"
#include "light_helpers.h"
#include "render/shadows.h"
#include "vxgi/inject.h"

namespace dvsgi::test {

namespace sh = dvsgi::shader;
using glm::dvec3;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr uint32_t kN = 32;

// Exact in float: the grid spans [-1, 1]^3.
inline vxgi::GridSpec grid() {
    vxgi::GridSpec g;
    g.origin = glm::vec3(-1.0f);
    g.voxelSize = 2.0f / float(kN);
    g.n = kN;
    return g;
}

// What the fragments of one voxel were, before summing into channels.
struct SyntheticVoxel {
    glm::vec3 albedo{0.0f}, emission{0.0f};
    std::vector<glm::vec3> normals;  // one per fragment; empty = unoccupied
    bool singleNormal = false;
};

inline glm::vec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<float> g;
    for (;;) {
        glm::vec3 v(g(rng), g(rng), g(rng));
        if (glm::length(v) > 1e-3f) return glm::normalize(v);
    }
}

// Sums the fragments into channels, as voxelization does.
inline AccumVolume toAccum(const std::vector<SyntheticVoxel>& voxels) {
    AccumVolume a(kN);
    for (int z = 0; z < int(kN); ++z)
        for (int y = 0; y < int(kN); ++y)
            for (int x = 0; x < int(kN); ++x) {
                const SyntheticVoxel& v = voxels[voxelIndex(kN, x, y, z)];
                for (const glm::vec3& n : v.normals) {
                    a.at(x, y, z, sh::CH_COUNT) += 1.0f;
                    for (int c = 0; c < 3; ++c) {
                        a.at(x, y, z, sh::CH_ALBEDO_R + uint32_t(c)) += v.albedo[c];
                        a.at(x, y, z, sh::CH_EMISSION_R + uint32_t(c)) += v.emission[c];
                        const float w = n[c] * n[c];
                        if (n[c] > 0.0f) a.at(x, y, z, sh::CH_NORMAL_POS_X + 2 * uint32_t(c)) += w;
                        if (n[c] < 0.0f) a.at(x, y, z, sh::CH_NORMAL_NEG_X + 2 * uint32_t(c)) += w;
                        a.at(x, y, z, sh::CH_FIRST_X + uint32_t(c)) += n[c];
                    }
                }
            }
    return a;
}

// Synthetic voxels summed into channels and uploaded, a static slot for every
// grid voxel, with an InjectPass to light them.
struct SyntheticGrid {
    explicit SyntheticGrid(std::vector<SyntheticVoxel> v)
        : voxels(std::move(v)), accum(toAccum(voxels)), volumes(context(), grid(), kN * kN * kN), pass(context()) {
        uploadAccum(volumes, accum);
    }
    std::vector<SyntheticVoxel> voxels;
    AccumVolume accum;
    vxgi::VoxelVolumes volumes;
    vxgi::InjectPass pass;
};

// ---- CPU reference, in double ----

struct Channels {
    double count;
    dvec3 albedo, emission, pos, neg, first;  // first: the mean normal (CH_FIRST_*)
};

inline Channels channels(const AccumVolume& a, int x, int y, int z) {
    Channels c;
    c.count = a.at(x, y, z, sh::CH_COUNT);
    for (int i = 0; i < 3; ++i) {
        c.albedo[i] = a.at(x, y, z, sh::CH_ALBEDO_R + uint32_t(i)) / c.count;
        c.emission[i] = a.at(x, y, z, sh::CH_EMISSION_R + uint32_t(i)) / c.count;
        c.pos[i] = a.at(x, y, z, sh::CH_NORMAL_POS_X + 2 * uint32_t(i)) / c.count;
        c.neg[i] = a.at(x, y, z, sh::CH_NORMAL_NEG_X + 2 * uint32_t(i)) / c.count;
        c.first[i] = a.at(x, y, z, sh::CH_FIRST_X + uint32_t(i)) / c.count;
    }
    return c;
}

// The voxel's representative normal: sqrt(pos) - sqrt(neg), normalized, or
// zero where opposite faces cancel.
inline dvec3 voxelNormal(const Channels& c) {
    const dvec3 n = glm::sqrt(c.pos) - glm::sqrt(c.neg);
    const double len = glm::length(n);
    return len > 1e-6 ? n / len : dvec3(0.0);
}

// The side code (shared/voxel_data.h): 0 one-sided, 1-3 two-sided along
// axis code - 1, SIDE_SEVERAL two-sided along more than one axis.
inline uint32_t sideCode(const Channels& c) {
    int count = 0, axis = 0;
    for (int a = 0; a < 3; ++a)
        if (std::min(c.pos[a], c.neg[a]) >= double(sh::TWO_SIDED_MIN_WEIGHT)) ++count, axis = a;
    return count == 0 ? sh::SIDE_ONE : (count > 1 ? sh::SIDE_SEVERAL : uint32_t(axis + 1));
}

// The default voxel light's attenuation toward unit L (inject.comp, Lambert):
// N.L with the mean normal, but a one-sided voxel of plane share below
// AXIS_FACES_BELOW_PLANE_SHARE (faces along the axes, or a fold a little off them) gets the lesser of that and
// its faces' cosines weighted by their shares. `axisFaces`: the voxel is such
// an edge; `ambiguous`: float rounding could take the other branch than double.
inline double lambertAttenuation(const Channels& c, const dvec3& L, bool& axisFaces, bool& ambiguous) {
    const double share = planeShareOf(c.pos, c.neg, c.first);
    const double lp = glm::length(glm::sqrt(c.pos) - glm::sqrt(c.neg)), la = glm::length(c.pos - c.neg);
    axisFaces = sideCode(c) == sh::SIDE_ONE && share < double(sh::AXIS_FACES_BELOW_PLANE_SHARE);
    ambiguous = std::abs(share - double(sh::AXIS_FACES_BELOW_PLANE_SHARE)) < 1e-3 || std::abs(lp - la - 1e-3) < 1e-4;
    for (int a = 0; a < 3; ++a)
        ambiguous = ambiguous || std::abs(std::min(c.pos[a], c.neg[a]) - double(sh::TWO_SIDED_MIN_WEIGHT)) < 1e-5;
    const double lambert = std::max(glm::dot(voxelNormal(c), L), 0.0);
    if (!axisFaces) return lambert;
    double faces = 0.0;
    for (int a = 0; a < 3; ++a) faces += (L[a] > 0.0 ? c.pos[a] : c.neg[a]) * std::abs(L[a]);
    return std::min(faces, lambert);
}

// Irradiance on a surface facing the light and the unit vector toward it.
inline dvec3 irradiance(const scene::PlacedLight& pl, const dvec3& P, dvec3& L) {
    const scene::Light& l = pl.light;
    const dvec3 I = dvec3(l.color) * double(l.intensity);
    if (l.type == scene::LightType::Directional) {
        L = -glm::normalize(dvec3(pl.direction));
        return I;
    }
    const dvec3 toLight = dvec3(pl.position) - P;
    const double d2 = glm::dot(toLight, toLight);
    L = toLight / std::sqrt(d2);
    dvec3 E = I / d2;  // inverse square
    if (l.type == scene::LightType::Spot) {
        // glTF's smooth falloff t, squared.
        const double cosTheta = glm::dot(-L, glm::normalize(dvec3(pl.direction)));
        const double cosOuter = std::cos(double(l.outerConeAngle)), cosInner = std::cos(double(l.innerConeAngle));
        const double t = std::clamp((cosTheta - cosOuter) / (cosInner - cosOuter), 0.0, 1.0);
        E *= t * t;
    }
    return E;
}

// Eq. 5 written as the paper has it for one normal N: W = N^2 and
// D_a = max(0, sign(N_a) L_a); a voxel of several fragments averages them.
inline double paperEq5(const SyntheticVoxel& v, const dvec3& L) {
    double sum = 0.0;
    for (const glm::vec3& fn : v.normals) {
        const dvec3 N(fn);
        for (int a = 0; a < 3; ++a) {
            const double W = N[a] * N[a];
            const double sign = N[a] > 0.0 ? 1.0 : (N[a] < 0.0 ? -1.0 : 0.0);
            sum += W * std::max(0.0, sign * L[a]);
        }
    }
    return sum / double(v.normals.size());
}

enum class Attenuation { Lambert, NormalWeightedChannels, NormalWeightedPaper };

// Direct light + emission of one occupied voxel, no occlusion; `ambiguous` as
// lambertAttenuation's.
inline dvec3 referenceRadiance(const AccumVolume& a, const SyntheticVoxel& v, int x, int y, int z,
                               const std::vector<scene::PlacedLight>& lights, const vxgi::GridSpec& g,
                               Attenuation mode, bool& ambiguous) {
    const Channels c = channels(a, x, y, z);
    ambiguous = false;
    // The light arrives at the voxel's centre (where the surface lies, on
    // average over where planes cross voxels); only shadows are looked up off it.
    const dvec3 P = dvec3(g.origin) + (dvec3(x, y, z) + 0.5) * double(g.voxelSize);
    dvec3 radiance = c.emission;
    for (const scene::PlacedLight& pl : lights) {
        dvec3 L;
        const dvec3 E = irradiance(pl, P, L);
        double att = 0.0;
        switch (mode) {
            case Attenuation::Lambert: {
                bool axisFaces = false;
                att = lambertAttenuation(c, L, axisFaces, ambiguous);
                break;
            }
            case Attenuation::NormalWeightedChannels:
                att = glm::dot(c.pos, glm::max(L, 0.0)) + glm::dot(c.neg, glm::max(-L, 0.0));
                break;
            case Attenuation::NormalWeightedPaper: att = paperEq5(v, L); break;
        }
        radiance += c.albedo / kPi * E * att;
    }
    return radiance;
}

// ---- the lights ----

inline scene::PlacedLight sun() {
    scene::PlacedLight p;
    p.light.name = "sun";
    p.light.type = scene::LightType::Directional;
    p.light.color = glm::vec3(1.0f, 0.8f, 0.6f);
    p.light.intensity = 3.0f;
    p.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.45f));
    return p;
}

inline scene::PlacedLight pointLight() {
    scene::PlacedLight p;
    p.light.name = "point";
    p.light.type = scene::LightType::Point;
    p.light.color = glm::vec3(0.5f, 1.0f, 0.75f);
    p.light.intensity = 6.0f;
    p.position = glm::vec3(-1.6f, 0.7f, 1.3f);  // outside the grid: no voxel sits on the light
    return p;
}

// Aimed so the outer cone cuts through the grid: both the falloff ramp and the
// dark outside of the cone are covered.
inline scene::PlacedLight spotLight() {
    scene::PlacedLight p;
    p.light.name = "spot";
    p.light.type = scene::LightType::Spot;
    p.light.color = glm::vec3(1.0f, 0.9f, 1.0f);
    p.light.intensity = 10.0f;
    p.light.innerConeAngle = 0.2f;
    p.light.outerConeAngle = 0.45f;
    p.position = glm::vec3(0.4f, 2.2f, -0.3f);
    p.direction = glm::normalize(glm::vec3(-0.2f, -1.0f, 0.15f));
    return p;
}

struct LightCase {
    std::string name;
    std::vector<scene::PlacedLight> lights;
};

inline std::vector<LightCase> lightCases() {
    return {{"directional", {sun()}},
            {"point", {pointLight()}},
            {"spot", {spotLight()}},
            {"all three", {sun(), pointLight(), spotLight()}}};
}

// Runs InjectPass over the accum volume with the given lights (occlusion off)
// and returns the `direct` volume.
inline Rgba16Volume inject(const vxgi::VoxelVolumes& volumes, const vxgi::InjectPass& pass,
                           const std::vector<scene::PlacedLight>& lights, bool normalWeighted,
                           bool keepSideReflection = false, bool edgeFaces = false) {
    const gpu::Context& ctx = context();
    scene::Bounds bounds;
    bounds.min = glm::vec3(-1.0f);
    bounds.max = glm::vec3(1.0f);
    // The renderer's own conversion from placed lights to GPU records.
    const render::LightSetup setup = render::setupLights(lights, bounds, 4, false);
    const gpu::Buffer lightBuffer =
        gpu::createBuffer(ctx, setup.lights.data(), setup.lights.size() * sizeof(sh::GpuLight),
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "test lights");
    const sh::GpuShadowView noView{};
    const gpu::Buffer views =
        gpu::createBuffer(ctx, &noView, sizeof(noView), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "test shadow views");
    const UnusedShadowMap shadow;
    const vxgi::ShadowInputs inputs{lightBuffer, uint32_t(setup.lights.size()), views, shadow.map, shadow.gradient,
                                    shadow.sampler.handle(), false};
    vxgi::VoxelLightSettings settings;
    settings.normalWeighted = normalWeighted;
    settings.occlusion = vxgi::Occlusion::None;
    settings.keepSideReflection = keepSideReflection;
    settings.edgeFaces = edgeFaces;
    gpu::Tracker tracker = volumeTracker(volumes);
    ctx.submitAndWait([&](VkCommandBuffer cmd) { pass.record(cmd, tracker, volumes, inputs, settings, nullptr); });
    return readDirect(volumes);
}

}  // namespace dvsgi::test
