// Direct light per voxel (InjectPass) on synthetic attribute volumes, against
// a CPU evaluation of the paper's eq. 2 (Lambert N.L) and eq. 5 (normal-
// weighted W_x D_x + W_y D_y + W_z D_z), for the three light types; the light
// per side of two-sided voxels, and what the filter's base level shows of them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include <glm/gtc/constants.hpp>

#include "inject_reference.h"
#include "shared/aniso_filter_pass.h"
#include "vxgi/aniso_filter.h"

namespace dvsgi::test {
namespace {

// A mix of voxel kinds: empty, one random normal, one axis-aligned normal
// (exercises n_a = 0), two opposite normals (equal or unequal fragment counts:
// a thin wall's two faces) and two unrelated normals.
std::vector<SyntheticVoxel> makeVoxels(uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::uniform_int_distribution<int> kind(0, 9), frags(1, 4), axis(0, 5);
    std::vector<SyntheticVoxel> out(size_t(kN) * kN * kN);
    for (SyntheticVoxel& v : out) {
        const int k = kind(rng);
        if (k < 3) continue;
        v.albedo = glm::vec3(u01(rng), u01(rng), u01(rng));
        if (u01(rng) < 0.3f) v.emission = glm::vec3(u01(rng), u01(rng), u01(rng)) * 50.0f;
        const int f = frags(rng);
        if (k < 6) {
            v.normals.assign(size_t(f), randomUnit(rng));
            v.singleNormal = true;
        } else if (k == 6) {
            glm::vec3 n(0.0f);
            const int a = axis(rng);
            n[a / 2] = a % 2 ? -1.0f : 1.0f;
            v.normals.assign(size_t(f), n);
            v.singleNormal = true;
        } else if (k < 9) {
            const glm::vec3 n = randomUnit(rng);
            const int back = k == 7 ? f : frags(rng);  // k == 7: the faces cancel exactly
            v.normals.assign(size_t(f), n);
            v.normals.insert(v.normals.end(), size_t(back), -n);
        } else {
            const glm::vec3 a = randomUnit(rng);
            glm::vec3 b = randomUnit(rng);
            if (glm::dot(a, b) < -0.5f) b = -b;  // keep the average normal well defined
            v.normals.assign(size_t(f), a);
            v.normals.insert(v.normals.end(), size_t(frags(rng)), b);
        }
    }
    return out;
}

class InjectDirect : public GpuTest {};


struct Mismatches {
    int checked = 0, failed = 0;
    double worstRel = 0.0;
};

// fp16 keeps 11 significant bits: a rounding moves a value by up to 9.8e-4 of
// it just above a power of two, and the worst measured error is 9.74e-4; 1.5e-3
// leaves room for float-vs-double differences in normalize, sqrt and 1/d^2.
void compare(const Rgba16Volume& gpu, const AccumVolume& accum, const std::vector<SyntheticVoxel>& voxels,
             const std::vector<scene::PlacedLight>& lights, Attenuation mode, bool singleNormalOnly,
             const std::string& what) {
    const vxgi::GridSpec g = grid();
    Mismatches m;
    for (int z = 0; z < int(kN); ++z)
        for (int y = 0; y < int(kN); ++y)
            for (int x = 0; x < int(kN); ++x) {
                const SyntheticVoxel& v = voxels[voxelIndex(kN, x, y, z)];
                const glm::vec4 got = gpu.at(x, y, z);
                if (v.normals.empty()) {
                    ++m.checked;
                    if (got != glm::vec4(0.0f) && m.failed++ < 5)
                        ADD_FAILURE() << what << ": empty voxel (" << x << "," << y << "," << z << ") holds " << got.r
                                      << " " << got.g << " " << got.b << " " << got.a;
                    continue;
                }
                if (singleNormalOnly && !v.singleNormal) continue;
                ++m.checked;
                bool ambiguous = false;
                const dvec3 want = referenceRadiance(accum, v, x, y, z, lights, g, mode, ambiguous);
                if (ambiguous) {
                    --m.checked;
                    continue;
                }
                // Alpha holds 1 + the voxel's side code.
                bool ok = got.a == 1.0f + float(sideCode(channels(accum, x, y, z)));
                for (int c = 0; c < 3; ++c) {
                    const double err = std::abs(double(got[c]) - want[c]);
                    ok = ok && err <= 1.5e-3 * std::abs(want[c]) + 2e-5;
                    if (want[c] > 1e-3) m.worstRel = std::max(m.worstRel, err / want[c]);
                }
                if (!ok && m.failed++ < 5)
                    ADD_FAILURE() << what << ": voxel (" << x << "," << y << "," << z << ") with "
                                  << v.normals.size() << " fragments: GPU " << got.r << " " << got.g << " " << got.b
                                  << " a=" << got.a << ", CPU " << want.r << " " << want.g << " " << want.b;
            }
    EXPECT_EQ(m.failed, 0) << what << ": " << m.failed << " of " << m.checked << " voxels differ";
    std::printf("  %-45s %6d voxels, worst relative error %.2e\n", what.c_str(), m.checked, m.worstRel);
}

TEST_F(InjectDirect, NormalWeightedMatchesEq5) {
    const SyntheticGrid sg(makeVoxels(7));
    const auto& [voxels, accum, volumes, pass] = sg;
    for (const LightCase& lc : lightCases()) {
        const Rgba16Volume got = inject(volumes, pass, lc.lights, true);
        compare(got, accum, voxels, lc.lights, Attenuation::NormalWeightedChannels, false,
                lc.name + ", eq. 5 from the channels");
        compare(got, accum, voxels, lc.lights, Attenuation::NormalWeightedPaper, true,
                lc.name + ", eq. 5 as written (single normals)");
        // Averaging the paper's formula over fragments is what the signed
        // channels encode, so it holds for mixed voxels too.
        compare(got, accum, voxels, lc.lights, Attenuation::NormalWeightedPaper, false,
                lc.name + ", eq. 5 averaged over fragments");
    }
}

TEST_F(InjectDirect, LambertMatchesEq2) {
    const SyntheticGrid sg(makeVoxels(11));
    const auto& [voxels, accum, volumes, pass] = sg;
    for (const LightCase& lc : lightCases())
        compare(inject(volumes, pass, lc.lights, false), accum, voxels, lc.lights, Attenuation::Lambert, false,
                lc.name + ", eq. 2");
}

// The two attenuations agree for a single axis-aligned normal (W = 1 on one
// axis) and differ for oblique ones: eq. 5 is not N.L in general.
TEST_F(InjectDirect, Eq5AndEq2AgreeOnlyForAxisAlignedNormals) {
    std::vector<SyntheticVoxel> voxels(size_t(kN) * kN * kN);
    SyntheticVoxel& aligned = voxels[voxelIndex(kN, 10, 10, 10)];
    aligned.albedo = glm::vec3(0.8f);
    aligned.normals = {glm::vec3(0, 1, 0)};
    SyntheticVoxel& oblique = voxels[voxelIndex(kN, 20, 10, 10)];
    oblique.albedo = glm::vec3(0.8f);
    oblique.normals = {glm::normalize(glm::vec3(1, 1, 0))};
    const SyntheticGrid sg(voxels);
    const auto& [synthetic, accum, volumes, pass] = sg;
    scene::PlacedLight light = sun();
    light.light.color = glm::vec3(1.0f);
    light.direction = glm::normalize(glm::vec3(-1.0f, -2.0f, 0.0f));
    const Rgba16Volume eq5 = inject(volumes, pass, {light}, true), eq2 = inject(volumes, pass, {light}, false);
    const double E = light.light.intensity, rho = 0.8;
    const dvec3 L = -glm::normalize(dvec3(light.direction));
    // (0,1,0): both give L_y.
    EXPECT_NEAR(eq5.at(10, 10, 10).r, rho / kPi * E * L.y, 1e-3);
    EXPECT_NEAR(eq2.at(10, 10, 10).r, rho / kPi * E * L.y, 1e-3);
    // (1,1,0)/sqrt2: eq. 5 gives 0.5 max(L_x,0) + 0.5 L_y, eq. 2 (L_x + L_y)/sqrt2.
    EXPECT_NEAR(eq5.at(20, 10, 10).r, rho / kPi * E * 0.5 * (std::max(L.x, 0.0) + L.y), 1e-3);
    EXPECT_NEAR(eq2.at(20, 10, 10).r, rho / kPi * E * std::max((L.x + L.y) / std::sqrt(2.0), 0.0), 1e-3);
}

// A two-sided voxel's sides are lit as faces with normals +axis and -axis
// (from the same light sample as the voxel), and start with no reflected light.
// RGB9E5 keeps 9 bits under a shared exponent, with no implicit leading one:
// half a step is up to 2^-9 of the largest component (measured worst 1.95e-3).
TEST_F(InjectDirect, TwoSidedVoxelsAreLitPerSide) {
    const SyntheticGrid sg(makeVoxels(5));
    const auto& [voxels, accum, volumes, pass] = sg;
    const vxgi::GridSpec g = grid();
    for (const LightCase& lc : lightCases()) {
        inject(volumes, pass, lc.lights, true);
        const std::vector<glm::uvec4> sides = vxgi::readSideLight(context(), volumes);
        int twoSided = 0, failed = 0;
        double worst = 0.0;
        for (int z = 0; z < int(kN); ++z)
            for (int y = 0; y < int(kN); ++y)
                for (int x = 0; x < int(kN); ++x) {
                    if (voxels[voxelIndex(kN, x, y, z)].normals.empty()) continue;
                    const Channels c = channels(accum, x, y, z);
                    const uint32_t code = sideCode(c);
                    if (code < 1 || code > 3) continue;
                    ++twoSided;
                    const int axis = int(code) - 1;
                    const dvec3 P = dvec3(g.origin) + (dvec3(x, y, z) + 0.5) * double(g.voxelSize);
                    const glm::uvec4 got = sides[voxelIndex(kN, x, y, z)];
                    EXPECT_EQ(got.z, 0u);
                    EXPECT_EQ(got.w, 0u);
                    for (int k = 0; k < 2; ++k) {
                        dvec3 want = c.emission;
                        for (const scene::PlacedLight& pl : lc.lights) {
                            dvec3 L;
                            const dvec3 E = irradiance(pl, P, L);
                            want += c.albedo / kPi * E * std::max(k == 0 ? L[axis] : -L[axis], 0.0);
                        }
                        const glm::vec3 side = vxgi::unpackRgb9e5(k == 0 ? got.x : got.y);
                        const double largest = std::max({want.r, want.g, want.b});
                        for (int ch = 0; ch < 3; ++ch) {
                            const double err = std::abs(double(side[ch]) - want[ch]);
                            if (largest > 1e-3) worst = std::max(worst, err / largest);
                            if (err > 2.0e-3 * largest + 1e-6 && failed++ < 5)
                                ADD_FAILURE() << lc.name << ": voxel (" << x << "," << y << "," << z << ") side " << k
                                              << " channel " << ch << ": GPU " << side[ch] << ", CPU " << want[ch];
                        }
                    }
                }
        std::printf("  %-12s %5d two-sided voxels, worst error %.2e of the largest component\n", lc.name.c_str(),
                    twoSided, worst);
        EXPECT_GT(twoSided, 100) << "the synthetic voxels should hold thin walls";
        EXPECT_EQ(failed, 0);
    }
}

// How much of a one-sided voxel's light a ray travelling along direction
// `dir` sees (aniso_filter.comp, seenFront): all of it face on or edge on,
// none from behind.
double seenFront(const dvec3& n, int dir) {
    const double along = kSign[dir] * n[kAxis[dir]];
    return std::clamp((sh::VOXEL_BACK_FADE_END - along) / (sh::VOXEL_BACK_FADE_END - sh::VOXEL_BACK_FADE_START), 0.0,
                      1.0);
}

// The filter's base level over two-sided voxels: rays along a voxel's axis
// see the side they meet (travelling toward -axis, the +axis side), rays
// across it an opaque black edge, and a voxel two-sided along several axes
// is black every way, all with opacity 1; one-sided voxels show their
// radiance to the rays that meet their front (seenFront).
TEST_F(InjectDirect, FilterShowsTwoSidedVoxelsSideBySide) {
    const SyntheticGrid sg(makeVoxels(9));
    const auto& [voxels, accum, volumes, pass] = sg;
    inject(volumes, pass, {sun(), pointLight()}, true);
    const vxgi::AnisoFilterPass filter(context());
    gpu::Tracker tracker = volumeTracker(volumes);
    context().submitAndWait([&](VkCommandBuffer cmd) { filter.record(cmd, tracker, volumes, true, nullptr, "test filter"); });
    const Rgba16Volume radiance = readRgba16(volumes.radiance);
    const std::vector<glm::uvec4> sides = vxgi::readSideLight(context(), volumes);
    int counts[5] = {0, 0, 0, 0, 0};
    for (int dir = 0; dir < 6; ++dir) {
        // What a ray travelling `dir` sees of each voxel.
        Rgba16Volume seen = radiance;
        for (int z = 0; z < int(kN); ++z)
            for (int y = 0; y < int(kN); ++y)
                for (int x = 0; x < int(kN); ++x) {
                    if (voxels[voxelIndex(kN, x, y, z)].normals.empty()) continue;
                    const uint32_t code = sideCode(channels(accum, x, y, z));
                    glm::vec4& t = seen.at(x, y, z);
                    if (dir == 0) {
                        ++counts[code];
                        // The radiance's opacity marks the voxels the filter looks up.
                        EXPECT_EQ(t.a, sh::twoSidedOpacity(code));
                    }
                    if (code == sh::SIDE_ONE) {
                        const float seen = float(seenFront(voxelNormal(channels(accum, x, y, z)), dir));
                        t = glm::vec4(glm::vec3(t) * seen, t.a);
                        continue;
                    }
                    t = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
                    if (code == sh::SIDE_SEVERAL || int(code) - 1 != kAxis[dir]) continue;
                    const glm::uvec4 w = sides[voxelIndex(kN, x, y, z)];
                    const bool plusSide = kSign[dir] < 0;
                    t = glm::vec4(vxgi::unpackRgb9e5(plusSide ? w.x : w.y) + vxgi::unpackRgb9e5(plusSide ? w.z : w.w),
                                  t.a);
                }
        const Rgba16Volume want = filterDirectionalLevel(seen, dir), got = readDirectional(volumes, uint32_t(dir), 0);
        int failed = 0;
        for (int z = 0; z < int(want.n); ++z)
            for (int y = 0; y < int(want.n); ++y)
                for (int x = 0; x < int(want.n); ++x)
                    for (int c = 0; c < 4; ++c) {
                        const float g = got.at(x, y, z)[c], w = want.at(x, y, z)[c];
                        // One fp16 rounding of the stored result.
                        if (std::abs(g - w) > 1.5e-3f * std::abs(w) + 1e-6f && failed++ < 3)
                            ADD_FAILURE() << "direction " << dir << " cell (" << x << "," << y << "," << z
                                          << ") channel " << c << ": GPU " << g << ", host " << w;
                    }
        EXPECT_EQ(failed, 0) << "direction " << dir;
    }
    std::printf("  voxels: %d one-sided, %d / %d / %d two-sided along x / y / z, %d along several axes\n", counts[0],
                counts[1], counts[2], counts[3], counts[4]);
    for (int code = 0; code < 5; ++code) EXPECT_GT(counts[code], 20) << "side code " << code;
}

// A feedback frame's bounce blends a two-sided voxel's reflected light with
// last frame's, so inject keeps the side light's reflected words then, and
// zeroes them otherwise (K bounces start from none).
TEST_F(InjectDirect, SideReflectionIsKeptOnlyForFeedbackFrames) {
    const SyntheticGrid sg(makeVoxels(13));
    const auto& [voxels, accum, volumes, pass] = sg;
    std::vector<glm::uvec4> marked(size_t(volumes.slots), glm::uvec4(0u));
    for (size_t i = 0; i < marked.size(); ++i) marked[i] = glm::uvec4(0u, 0u, 0x1000u + uint32_t(i), 0x2000u + uint32_t(i));
    for (bool keep : {true, false}) {
        gpu::uploadImage(context(), volumes.sides, marked.data(), marked.size() * sizeof(glm::uvec4),
                         gpu::use::ComputeReadWrite);
        inject(volumes, pass, {sun()}, true, keep);
        const std::vector<glm::uvec4> sides = vxgi::readSideLight(context(), volumes);
        const std::vector<uint32_t> index = vxgi::readVoxelIndex(context(), volumes);
        int twoSided = 0, failed = 0;
        for (size_t i = 0; i < index.size(); ++i) {
            if (voxels[i].normals.empty()) continue;
            const int z = int(i / (kN * kN)), y = int(i / kN % kN), x = int(i % kN);
            const uint32_t code = sideCode(channels(accum, x, y, z));
            if (code < 1 || code > 3) continue;
            ++twoSided;
            const uint32_t slot = sh::indexSlot(index[i]) - 1;
            const glm::uvec2 want = keep ? glm::uvec2(marked[slot].z, marked[slot].w) : glm::uvec2(0u);
            if ((sides[i].z != want.x || sides[i].w != want.y) && failed++ < 3)
                ADD_FAILURE() << (keep ? "kept" : "zeroed") << ": voxel " << x << " " << y << " " << z << " holds "
                              << sides[i].z << " " << sides[i].w << ", want " << want.x << " " << want.y;
        }
        EXPECT_GT(twoSided, 100);
        EXPECT_EQ(failed, 0) << (keep ? "kept" : "zeroed");
    }
}

}  // namespace
}  // namespace dvsgi::test
