// Direct light per voxel with --edge-voxels faces (inject.comp): the share of
// a voxel that is one plane lit with Lambert, the rest face by face along the
// axes, and an edge voxel's faces kept apart for the rays (lib/voxel_rays.glsl,
// facesSeen), against a CPU evaluation in double; the default's edges of axis
// faces (the lesser of face by face and Lambert with the mean normal); and the
// analytic cases of an edge lit head on along one face and along both.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "inject_reference.h"

namespace dvsgi::test {
namespace {

// Edges (axis faces of two axes), corners (three), a corner with a plane
// through it, and plain planes; fragment counts and the faces' signs at random.
std::vector<SyntheticVoxel> makeEdgeVoxels(uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::uniform_int_distribution<int> kind(0, 7), frags(1, 4), coin(0, 1), axis(0, 2);
    std::vector<SyntheticVoxel> out(size_t(kN) * kN * kN);
    for (SyntheticVoxel& v : out) {
        const int k = kind(rng);
        if (k < 2) continue;
        v.albedo = glm::vec3(u01(rng), u01(rng), u01(rng));
        if (u01(rng) < 0.2f) v.emission = glm::vec3(u01(rng), u01(rng), u01(rng)) * 20.0f;
        if (k == 2) {
            v.normals.assign(size_t(frags(rng)), randomUnit(rng));
            v.singleNormal = true;
            continue;
        }
        const int axes = k < 5 ? 2 : 3, first = axis(rng);
        for (int i = 0; i < axes; ++i) {
            glm::vec3 n(0.0f);
            n[(first + i) % 3] = coin(rng) ? 1.0f : -1.0f;
            v.normals.insert(v.normals.end(), size_t(frags(rng)), n);
        }
        if (k == 7) v.normals.insert(v.normals.end(), size_t(frags(rng)), randomUnit(rng));
    }
    return out;
}

double planeShare(const Channels& c) { return planeShareOf(c.pos, c.neg, c.first); }

struct EdgeLight {
    dvec3 radiance;
    dvec3 face[3];  // the faces along x, y, z, each on the side its weights favour
    bool faces;     // the voxel shows its faces
    bool ambiguous; // float rounding could take the other branch than double
};

EdgeLight referenceEdgeLight(const Channels& c, const dvec3& P, const std::vector<scene::PlacedLight>& lights) {
    const double share = planeShare(c);
    const double lp = glm::length(glm::sqrt(c.pos) - glm::sqrt(c.neg)), la = glm::length(c.pos - c.neg);
    const dvec3 n = voxelNormal(c);
    EdgeLight out;
    out.faces = sideCode(c) == sh::SIDE_ONE && share < sh::FACES_BELOW_PLANE_SHARE;
    out.ambiguous = std::abs(share - sh::FACES_BELOW_PLANE_SHARE) < 1e-3 || std::abs(lp - la - 1e-3) < 1e-4;
    // One fragment in ten along an axis's other sign sits on the two-sided threshold.
    for (int a = 0; a < 3; ++a)
        out.ambiguous = out.ambiguous || std::abs(std::min(c.pos[a], c.neg[a]) - sh::TWO_SIDED_MIN_WEIGHT) < 1e-5;
    out.radiance = c.emission;
    for (dvec3& f : out.face) f = c.emission;
    for (const scene::PlacedLight& pl : lights) {
        dvec3 L;
        const dvec3 E = irradiance(pl, P, L);
        const dvec3 planeLight = c.albedo / kPi * E * (share * std::max(glm::dot(n, L), 0.0));
        out.radiance += planeLight;
        for (int a = 0; a < 3; ++a) {
            out.face[a] += planeLight;
            const double w = L[a] > 0.0 ? c.pos[a] : c.neg[a];
            const dvec3 faceLight = c.albedo / kPi * E * ((1.0 - share) * std::abs(L[a]));
            out.radiance += w * faceLight;
            const double faceSign = c.pos[a] >= c.neg[a] ? 1.0 : -1.0;
            if (faceSign * L[a] > 0.0) out.face[a] += faceLight;
        }
    }
    return out;
}

class InjectEdges : public GpuTest {};

TEST_F(InjectEdges, DefaultLightsAxisEdgesByTheLesserOfFacesAndMeanNormal) {
    const SyntheticGrid sg(makeEdgeVoxels(5));
    const auto& [voxels, accum, volumes, pass] = sg;
    const vxgi::GridSpec g = grid();
    for (const LightCase& lc : lightCases()) {
        const Rgba16Volume direct = inject(volumes, pass, lc.lights, false);
        int checked = 0, axisEdges = 0, lowered = 0, failed = 0;
        double worst = 0.0;
        for (int z = 0; z < int(kN); ++z)
            for (int y = 0; y < int(kN); ++y)
                for (int x = 0; x < int(kN); ++x) {
                    if (voxels[voxelIndex(kN, x, y, z)].normals.empty()) continue;
                    const Channels c = channels(accum, x, y, z);
                    const dvec3 P = dvec3(g.origin) + (dvec3(x, y, z) + 0.5) * double(g.voxelSize);
                    dvec3 want = c.emission;
                    bool axisFaces = false, ambiguous = false, below = false;
                    for (const scene::PlacedLight& pl : lc.lights) {
                        dvec3 L;
                        const dvec3 E = irradiance(pl, P, L);
                        const double att = lambertAttenuation(c, L, axisFaces, ambiguous);
                        below = below || att < std::max(glm::dot(voxelNormal(c), L), 0.0) - 1e-3;
                        want += c.albedo / kPi * E * att;
                    }
                    if (ambiguous) continue;
                    ++checked;
                    axisEdges += axisFaces;
                    lowered += below;
                    const glm::vec4 got = direct.at(x, y, z);
                    bool ok = true;
                    for (int ch = 0; ch < 3; ++ch) {
                        const double err = std::abs(double(got[ch]) - want[ch]);
                        ok = ok && err <= 1.5e-3 * std::abs(want[ch]) + 2e-5;
                        if (want[ch] > 1e-3) worst = std::max(worst, err / want[ch]);
                    }
                    if (!ok && failed++ < 5)
                        ADD_FAILURE() << lc.name << ": voxel (" << x << "," << y << "," << z << "), axis faces "
                                      << axisFaces << ": GPU " << got.r << " " << got.g << " " << got.b << ", CPU "
                                      << want.r << " " << want.g << " " << want.b;
                }
        std::printf("  %-12s %5d voxels (%d edges of axis faces, %d below Lambert), worst error %.2e\n",
                    lc.name.c_str(), checked, axisEdges, lowered, worst);
        EXPECT_EQ(failed, 0);
        EXPECT_GT(axisEdges, 5000) << "the synthetic voxels should hold edges and corners of axis faces";
        EXPECT_GT(lowered, 1000) << "and some the faces light less than the mean normal";
    }
}

// fp16 (direct light): 1.5e-3 of the value, as InjectDirect; RGB9E5 (the
// faces' light): 2e-3 of the largest component, as the side light.
TEST_F(InjectEdges, EdgeVoxelsAreLitFaceByFace) {
    const SyntheticGrid sg(makeEdgeVoxels(3));
    const auto& [voxels, accum, volumes, pass] = sg;
    const vxgi::GridSpec g = grid();
    for (const LightCase& lc : lightCases()) {
        const Rgba16Volume direct = inject(volumes, pass, lc.lights, false, false, true);
        const std::vector<glm::uvec4> sides = vxgi::readSideLight(context(), volumes);
        int checked = 0, faces = 0, planes = 0, failed = 0;
        double worstDirect = 0.0, worstFace = 0.0;
        for (int z = 0; z < int(kN); ++z)
            for (int y = 0; y < int(kN); ++y)
                for (int x = 0; x < int(kN); ++x) {
                    if (voxels[voxelIndex(kN, x, y, z)].normals.empty()) continue;
                    const Channels c = channels(accum, x, y, z);
                    const dvec3 P = dvec3(g.origin) + (dvec3(x, y, z) + 0.5) * double(g.voxelSize);
                    const EdgeLight want = referenceEdgeLight(c, P, lc.lights);
                    if (want.ambiguous) continue;
                    ++checked;
                    faces += want.faces;
                    planes += planeShare(c) >= sh::FACES_BELOW_PLANE_SHARE;
                    const glm::vec4 got = direct.at(x, y, z);
                    bool ok = got.a == 1.0f + float(sideCode(c));
                    for (int ch = 0; ch < 3; ++ch) {
                        const double err = std::abs(double(got[ch]) - want.radiance[ch]);
                        ok = ok && err <= 1.5e-3 * std::abs(want.radiance[ch]) + 2e-5;
                        if (want.radiance[ch] > 1e-3) worstDirect = std::max(worstDirect, err / want.radiance[ch]);
                    }
                    if (want.faces) {
                        const glm::uvec4 t = sides[voxelIndex(kN, x, y, z)];
                        for (int k = 0; k < 4; ++k) {
                            const dvec3 w = k < 3 ? want.face[k] : want.radiance;
                            const glm::vec3 s = vxgi::unpackRgb9e5(t[k]);
                            const double largest = std::max({w.r, w.g, w.b});
                            for (int ch = 0; ch < 3; ++ch) {
                                const double err = std::abs(double(s[ch]) - w[ch]);
                                if (largest > 1e-3) worstFace = std::max(worstFace, err / largest);
                                ok = ok && err <= 2e-3 * largest + 1e-6;
                            }
                        }
                    }
                    if (!ok && failed++ < 5)
                        ADD_FAILURE() << lc.name << ": voxel (" << x << "," << y << "," << z << "), "
                                      << voxels[voxelIndex(kN, x, y, z)].normals.size() << " fragments, faces "
                                      << want.faces << ": GPU " << got.r << " " << got.g << " " << got.b << ", CPU "
                                      << want.radiance.r << " " << want.radiance.g << " " << want.radiance.b
                                      << ", alpha " << got.a << " code " << sideCode(c);
                }
        std::printf("  %-12s %5d voxels (%d show faces, %d planes), worst error %.2e direct, %.2e faces\n",
                    lc.name.c_str(), checked, faces, planes, worstDirect, worstFace);
        EXPECT_EQ(failed, 0);
        EXPECT_GT(faces, 5000) << "the synthetic voxels should hold edges and corners";
        EXPECT_GT(planes, 1000) << "and planes";
    }
}

// One voxel of one +x and one +y fragment (a box's edge, or a room's inside
// corner), albedo (0.5, 0.25, 1), lit by the test sun travelling along
// `direction`: its direct light, its side-light texel (the faces' light with
// --edge-voxels faces) and the colour E rho / pi is scaled by.
struct LitEdge {
    glm::vec4 direct;
    glm::uvec4 sides;
    glm::vec3 colour;
};

LitEdge injectOneEdge(const glm::vec3& direction, bool edgeFaces) {
    std::vector<SyntheticVoxel> voxels(size_t(kN) * kN * kN);
    SyntheticVoxel& edge = voxels[voxelIndex(kN, 5, 6, 7)];
    edge.albedo = glm::vec3(0.5f, 0.25f, 1.0f);
    edge.normals = {glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)};
    const SyntheticGrid sg(voxels);
    const auto& [synthetic, accum, volumes, pass] = sg;
    scene::PlacedLight light = sun();
    light.direction = glm::normalize(direction);
    LitEdge out;
    out.direct = inject(volumes, pass, {light}, false, false, edgeFaces).at(5, 6, 7);
    out.sides = vxgi::readSideLight(context(), volumes)[voxelIndex(kN, 5, 6, 7)];
    out.colour = light.light.color * edge.albedo;
    return out;
}

constexpr double kSunFull = 3.0 / kPi;  // E rho / pi per unit albedo, the test sun's intensity 3

// Lit head on along +x: its +x face gets E rho / pi, its +y face, edge on,
// none; so the voxel as a whole holds half of E rho / pi, with either
// --edge-voxels. Lit as a plane with the mean normal (+x +y)/sqrt(2) it held
// 1/sqrt(2) of it.
TEST_F(InjectEdges, BoxEdgeLitAlongOneFace) {
    for (bool edgeFaces : {true, false}) {
        const LitEdge got = injectOneEdge(glm::vec3(-1.0f, 0.0f, 0.0f), edgeFaces);
        const double want = 0.5 * kSunFull;
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_NEAR(got.direct[ch], want * got.colour[ch], 1.5e-3 * want * got.colour[ch])
                << (edgeFaces ? "faces" : "whole") << " channel " << ch;
        if (!edgeFaces) continue;
        const glm::vec3 faceX = vxgi::unpackRgb9e5(got.sides.x), faceY = vxgi::unpackRgb9e5(got.sides.y);
        for (int ch = 0; ch < 3; ++ch) {
            EXPECT_NEAR(faceX[ch], kSunFull * got.colour[ch], 2e-3 * kSunFull) << "the +x face, head on";
            EXPECT_EQ(faceY[ch], 0.0f) << "the +y face, edge on";
        }
    }
}

// Lit along (+x +y)/sqrt(2): each face gets cos 45 degrees, so the voxel
// holds E rho / pi / sqrt(2); with the mean normal it got the whole E rho /
// pi, the sqrt(2) too much that made cornell-lights' corners too bright
// (docs/quality.md, "Edge voxels of axis faces").
TEST_F(InjectEdges, EdgeLitAlongBothFacesHoldsTheirMeanCosine) {
    for (bool edgeFaces : {true, false}) {
        const LitEdge got = injectOneEdge(glm::vec3(-1.0f, -1.0f, 0.0f), edgeFaces);
        const double want = kSunFull / std::sqrt(2.0);
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_NEAR(got.direct[ch], want * got.colour[ch], 1.5e-3 * want * got.colour[ch])
                << (edgeFaces ? "faces" : "whole") << " channel " << ch;
    }
}

}  // namespace
}  // namespace dvsgi::test
