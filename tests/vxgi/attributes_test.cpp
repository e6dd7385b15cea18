// What the voxels hold: summed attributes whose averages (sum / CH_COUNT) are
// fragment-weighted means of the surfaces inside, without clamping.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "scene/load.h"
#include "vox_helper.h"

namespace dvsgi::test {
namespace {

namespace sh = dvsgi::shader;

class VoxelAttributes : public GpuTest, public ::testing::WithParamInterface<vxgi::VoxelizerKind> {};

const vxgi::GridSpec kGrid = exactGrid(glm::vec3(0.0f), 1.0f, 32);
const glm::vec3 kRed(1, 0, 0), kBlue(0, 0, 1);

using Counts = std::vector<uint32_t>;  // per voxel, VoxelSet order

// Fragments an axis-aligned rectangle lying strictly inside one voxel layer
// sends to each voxel: one per triangle whose closed projection touches the
// voxel's column (geometry path), one per triangle touching the voxel
// (compute path): the same numbers. Both triangles of a rectangle touch the columns along their
// shared diagonal, so those get two.
Counts expectedCounts(const scene::Scene& s) {
    Counts c(size_t(kGrid.n) * kGrid.n * kGrid.n, 0);
    for (const Triangle& t : voxelTriangles(s, kGrid)) {
        VoxelSet one = referenceVoxelize({t}, kGrid.n);
        for (size_t i = 0; i < c.size(); ++i) c[i] += one.bits[i];
    }
    return c;
}

// Calls f(x, z) for every occupied voxel of layer y.
template <typename F>
void forOccupiedInLayer(const VoxelSet& occ, int y, F f) {
    for (int z = 0; z < int(kGrid.n); ++z)
        for (int x = 0; x < int(kGrid.n); ++x)
            if (occ.get(x, y, z)) f(x, z);
}

struct TwoLayers {
    VoxelReadback a, b, both;
    Counts expectA, expectB;
};

// Voxelizes rectangle A alone, B alone, and both together.
TwoLayers twoRects(vxgi::VoxelizerKind kind, glm::vec3 albedoA, glm::vec3 loA, glm::vec3 hiA, float signA,
                   glm::vec3 albedoB, glm::vec3 loB, glm::vec3 hiB, float signB) {
    scene::Scene sa, sb, sab;
    addRect(sa, addMaterial(sa, albedoA), loA, hiA, 1, signA);
    addRect(sb, addMaterial(sb, albedoB), loB, hiB, 1, signB);
    addRect(sab, addMaterial(sab, albedoA), loA, hiA, 1, signA);
    addRect(sab, addMaterial(sab, albedoB), loB, hiB, 1, signB);
    return {voxelizeScene(sa, kGrid, kind), voxelizeScene(sb, kGrid, kind), voxelizeScene(sab, kGrid, kind), expectedCounts(sa),
            expectedCounts(sb)};
}

TEST_P(VoxelAttributes, TwoSurfacesInOneLayerAverage) {
    // Planes y = 10.25 and 10.75 both lie in layer y = 10 and cover the faces
    // of the voxels x, z in [12, 20).
    const TwoLayers r = twoRects(GetParam(), kRed, {12, 10.25f, 12}, {20, 10.25f, 20}, 1.0f, kBlue, {12, 10.75f, 12},
                                 {20, 10.75f, 20}, 1.0f);
    const int n = int(kGrid.n);
    int interior = 0, diagonal = 0;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const size_t i = (size_t(z) * n + size_t(y)) * n + size_t(x);
                const float ca = r.a.count(x, y, z), cb = r.b.count(x, y, z), c = r.both.count(x, y, z);
                ASSERT_EQ(ca, float(r.expectA[i])) << x << " " << y << " " << z;
                ASSERT_EQ(cb, float(r.expectB[i])) << x << " " << y << " " << z;
                ASSERT_EQ(c, ca + cb) << x << " " << y << " " << z;
                if (c == 0.0f) continue;
                ASSERT_EQ(y, 10);
                // Same footprint, same diagonal: every voxel holds as many red
                // fragments as blue ones, so the mean is exact.
                EXPECT_NEAR(r.both.average(x, y, z, sh::CH_ALBEDO_R), 0.5f, 1e-5f);
                EXPECT_EQ(r.both.average(x, y, z, sh::CH_ALBEDO_G), 0.0f);
                EXPECT_NEAR(r.both.average(x, y, z, sh::CH_ALBEDO_B), 0.5f, 1e-5f);
                if (x >= 12 && x < 20 && z >= 12 && z < 20) {
                    ++interior;
                    if (c == 2.0f)
                        continue;
                    ++diagonal;
                    EXPECT_EQ(c, 4.0f) << x << " " << z;
                }
            }
    EXPECT_EQ(interior, 64);
    std::printf("interior voxels: %d, %d of them on the rectangles' shared diagonal (count 4, else 2)\n", interior,
                diagonal);
}

TEST_P(VoxelAttributes, PartialOverlapIsCountWeighted) {
    // Red covers [12, 20)^2, blue only x in [12, 16).
    const TwoLayers r = twoRects(GetParam(), kRed, {12, 10.25f, 12}, {20, 10.25f, 20}, 1.0f, kBlue, {12, 10.75f, 12},
                                 {16, 10.75f, 20}, 1.0f);
    const int n = int(kGrid.n);
    int mixed = 0, redOnly = 0;
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
            const int y = 10;
            const size_t i = (size_t(z) * n + size_t(y)) * n + size_t(x);
            const float ca = r.a.count(x, y, z), cb = r.b.count(x, y, z), c = r.both.count(x, y, z);
            ASSERT_EQ(ca, float(r.expectA[i]));
            ASSERT_EQ(cb, float(r.expectB[i]));
            ASSERT_EQ(c, ca + cb);
            if (c == 0.0f) continue;
            const glm::vec3 expected = (kRed * ca + kBlue * cb) / c;
            EXPECT_NEAR(r.both.average(x, y, z, sh::CH_ALBEDO_R), expected.r, 1e-5f) << x << " " << z;
            EXPECT_EQ(r.both.average(x, y, z, sh::CH_ALBEDO_G), 0.0f);
            EXPECT_NEAR(r.both.average(x, y, z, sh::CH_ALBEDO_B), expected.b, 1e-5f) << x << " " << z;
            if (cb == 0.0f) {
                ++redOnly;
                EXPECT_EQ(r.both.average(x, y, z, sh::CH_ALBEDO_R), 1.0f);
            } else {
                ++mixed;
            }
        }
    EXPECT_GT(mixed, 0);
    EXPECT_GT(redOnly, 0);
    // Nothing outside the layer.
    EXPECT_EQ(r.both.occupancy().count(), size_t(mixed + redOnly));
}

TEST_P(VoxelAttributes, EmissionIsNotClamped) {
    scene::Scene s;
    const glm::vec3 emission(500, 200, 1000);
    addRect(s, addMaterial(s, glm::vec3(0.2f, 0.4f, 0.6f), emission), {5, 7.5f, 5}, {11, 7.5f, 13}, 1, 1.0f);
    const VoxelReadback r = voxelizeScene(s, kGrid, GetParam());
    const VoxelSet occ = r.occupancy();
    ASSERT_GT(occ.count(), 0u);
    forOccupiedInLayer(occ, 7, [&](int x, int z) {
        EXPECT_FLOAT_EQ(r.average(x, 7, z, sh::CH_EMISSION_R), 500.0f);
        EXPECT_FLOAT_EQ(r.average(x, 7, z, sh::CH_EMISSION_G), 200.0f);
        EXPECT_FLOAT_EQ(r.average(x, 7, z, sh::CH_EMISSION_B), 1000.0f);
        EXPECT_FLOAT_EQ(r.average(x, 7, z, sh::CH_ALBEDO_G), 0.4f);
    });
}

// An emissive texture scales the emission (both voxelizers; the compute one
// samples it only when some material has one, so a scene that has one must
// still get it).
TEST_P(VoxelAttributes, EmissiveTextureScalesTheEmission) {
    scene::Scene s;
    const int m = addMaterial(s, glm::vec3(1.0f), glm::vec3(4.0f));
    s.materials[size_t(m)].baseColorTexture = addUniformTexture(s, 51, 102, 204);
    s.materials[size_t(m)].emissiveTexture = addUniformTexture(s, 64, 128, 255);
    addRect(s, m, {5, 7.5f, 5}, {11, 7.5f, 13}, 1, 1.0f);
    const VoxelReadback r = voxelizeScene(s, kGrid, GetParam());
    const VoxelSet occ = r.occupancy();
    ASSERT_GT(occ.count(), 0u);
    forOccupiedInLayer(occ, 7, [&](int x, int z) {
        EXPECT_NEAR(r.average(x, 7, z, sh::CH_EMISSION_R), 4.0f * 64.0f / 255.0f, 1e-4f);
        EXPECT_NEAR(r.average(x, 7, z, sh::CH_EMISSION_G), 4.0f * 128.0f / 255.0f, 1e-4f);
        EXPECT_NEAR(r.average(x, 7, z, sh::CH_EMISSION_B), 4.0f, 1e-4f);
        EXPECT_NEAR(r.average(x, 7, z, sh::CH_ALBEDO_G), 102.0f / 255.0f, 1e-4f);
    });
}

TEST_P(VoxelAttributes, OppositeNormalsKeepBothOrientations) {
    const TwoLayers r = twoRects(GetParam(), glm::vec3(0.5f), {12, 10.25f, 12}, {20, 10.25f, 20}, 1.0f, glm::vec3(0.5f),
                                 {12, 10.75f, 12}, {20, 10.75f, 20}, -1.0f);
    const VoxelSet occ = r.both.occupancy();
    ASSERT_GT(occ.count(), 0u);
    for (int z = 0; z < int(kGrid.n); ++z)
        for (int x = 0; x < int(kGrid.n); ++x) {
            if (!occ.get(x, 10, z)) continue;
            EXPECT_NEAR(r.both.average(x, 10, z, sh::CH_NORMAL_POS_Y), 0.5f, 1e-6f);
            EXPECT_NEAR(r.both.average(x, 10, z, sh::CH_NORMAL_NEG_Y), 0.5f, 1e-6f);
            for (uint32_t ch : {sh::CH_NORMAL_POS_X, sh::CH_NORMAL_NEG_X, sh::CH_NORMAL_POS_Z, sh::CH_NORMAL_NEG_Z})
                EXPECT_EQ(r.both.at(x, 10, z, ch), 0.0f);
        }
}

TEST_P(VoxelAttributes, TiltedNormalWeightsSumToOne) {
    // Normal (0, 0.6, 0.8) and a general one: the six weights of every voxel
    // sum to the fragment count, split by n_a^2.
    scene::Scene s;
    const int m = addMaterial(s, glm::vec3(0.5f));
    addTriangles(s, m, {{glm::vec3(4, 4, 7), glm::vec3(14, 4, 7), glm::vec3(4, 8, 4)}});
    addTriangles(s, m, {{glm::vec3(18, 18, 20), glm::vec3(27, 21, 18), glm::vec3(20, 27, 25)}});
    const VoxelReadback r = voxelizeScene(s, kGrid, GetParam());
    const VoxelSet occ = r.occupancy();
    const glm::vec3 n1 = glm::normalize(glm::cross(glm::vec3(10, 0, 0), glm::vec3(0, 4, -3)));
    ASSERT_NEAR(n1.y, 0.6f, 1e-6f);
    int checked = 0;
    for (int z = 0; z < int(kGrid.n); ++z)
        for (int y = 0; y < int(kGrid.n); ++y)
            for (int x = 0; x < int(kGrid.n); ++x) {
                if (!occ.get(x, y, z)) continue;
                float sum = 0.0f;
                for (uint32_t ch = sh::CH_NORMAL_POS_X; ch <= sh::CH_NORMAL_NEG_Z; ++ch) sum += r.average(x, y, z, ch);
                EXPECT_NEAR(sum, 1.0f, 1e-5f) << x << " " << y << " " << z;
                if (x < 16) {
                    EXPECT_NEAR(r.average(x, y, z, sh::CH_NORMAL_POS_Y), 0.36f, 1e-5f);
                    EXPECT_NEAR(r.average(x, y, z, sh::CH_NORMAL_POS_Z), 0.64f, 1e-5f);
                }
                ++checked;
            }
    EXPECT_GT(checked, 50);
}

// A texture of a white and a black half on a rectangle whose material and
// texture are not the scene's first, behind textures of another size: each
// voxel over the white half samples white, each over the black half black.
// The compute voxelizer once took the texture's size from textureSize on its
// dynamically indexed texture array, which lavapipe answered with another
// texture's size for some invocations: texels were fetched where that size
// put them, and Sponza's floor voxels came out 6 % bright and unrelated to the
// floor's pattern. The geometry-shader voxelizer's implicit-level texture()
// on the array sampled this rectangle white throughout. Both now fetch texels
// by hand at the size the material carries (docs/quality.md, "Textures in
// the voxelizers").
TEST_P(VoxelAttributes, TextureSampledAtItsOwnSizeWhateverItsSlot) {
    scene::Scene s;
    for (int k = 0; k < 3; ++k) {
        const int m = addMaterial(s, glm::vec3(0.5f));
        s.materials[size_t(m)].baseColorTexture = addUniformTexture(s, 10, 20, 30);
        addRect(s, m, {2, 3.5f + float(k), 2}, {6, 3.5f + float(k), 6}, 1, 1.0f);
    }
    scene::Texture halves;
    halves.name = "halves";
    halves.width = halves.height = 256;
    halves.srgb = false;
    for (uint32_t y = 0; y < halves.height; ++y)
        for (uint32_t x = 0; x < halves.width; ++x) {
            const uint8_t v = x < halves.width / 2 ? 255 : 0;
            halves.rgba8.insert(halves.rgba8.end(), {v, v, v, 255});
        }
    s.textures.push_back(halves);
    const int m = addMaterial(s, glm::vec3(1.0f));
    s.materials[size_t(m)].baseColorTexture = int(s.textures.size()) - 1;
    // Layer 20 from 2 to 30 on x and z, u along x from 0 to 1: about nine
    // texels to a voxel.
    scene::Primitive p;
    for (glm::vec2 c : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)}) {
        scene::Vertex v;
        v.position = glm::vec3(2.0f + 28.0f * c.x, 20.5f, 2.0f + 28.0f * c.y);
        v.uv = c;
        p.vertices.push_back(v);
    }
    p.indices = {0, 2, 1, 0, 3, 2};
    addMeshNode(s, std::move(p), m, glm::vec3(0.0f), glm::quat(1, 0, 0, 0), glm::vec3(1.0f));
    const VoxelReadback r = voxelizeScene(s, kGrid, GetParam());
    int white = 0, black = 0;
    forOccupiedInLayer(r.occupancy(), 20, [&](int x, int z) {
        if (std::min(x, z) < 3 || std::max(x, z) > 28) return;  // the rectangle's border: samples on its edge
        const float u = (float(x) + 0.5f - 2.0f) / 28.0f, albedo = r.average(x, 20, z, sh::CH_ALBEDO_G);
        if (u < 0.45f) {
            EXPECT_GT(albedo, 0.99f) << x << " " << z;
            ++white;
        } else if (u > 0.55f) {
            EXPECT_LT(albedo, 0.01f) << x << " " << z;
            ++black;
        }
    });
    EXPECT_GT(white, 300);
    EXPECT_GT(black, 300);
}

INSTANTIATE_TEST_SUITE_P(Voxelizers, VoxelAttributes, ::testing::ValuesIn(kVoxelizers), voxelizerTestName);


// The two voxelizers store different counts (fragments per pixel column and
// layer, samples per triangle), but a voxel that only one material touches
// must average to that material's albedo and emission on both.
TEST_F(GpuTest, VoxelizersAgreeOnSingleMaterialAverages) {
    const scene::Scene s = scene::builtinCornellBox();
    const auto items = scene::drawItems(s, scene::worldMatrices(s));
    const vxgi::GridSpec grid = vxgi::fitGrid(scene::worldBounds(s, items), 32);
    const VoxelReadback geometry = voxelizeScene(s, grid, vxgi::VoxelizerKind::Geometry);
    const VoxelReadback compute = voxelizeScene(s, grid, vxgi::VoxelizerKind::Compute);
    // Per voxel, the materials whose triangles touch it (reference test).
    std::vector<uint32_t> materialsTouching(size_t(grid.n) * grid.n * grid.n, 0);
    for (size_t m = 0; m < s.materials.size(); ++m) {
        scene::Scene one = s;
        for (scene::Primitive& p : one.primitives)
            if (p.material != m) p.indices.clear();
        const VoxelSet set = referenceVoxelize(voxelTriangles(one, grid), grid.n);
        for (size_t i = 0; i < set.bits.size(); ++i) materialsTouching[i] += set.bits[i];
    }
    int compared = 0;
    float worst = 0.0f;
    const int n = int(grid.n);
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const size_t i = (size_t(z) * n + size_t(y)) * n + size_t(x);
                if (materialsTouching[i] != 1 || geometry.count(x, y, z) == 0.0f || compute.count(x, y, z) == 0.0f)
                    continue;
                for (uint32_t ch : {sh::CH_ALBEDO_R, sh::CH_ALBEDO_G, sh::CH_ALBEDO_B, sh::CH_EMISSION_R,
                                    sh::CH_EMISSION_G, sh::CH_EMISSION_B}) {
                    const float a = geometry.average(x, y, z, ch), b = compute.average(x, y, z, ch);
                    worst = std::max(worst, std::abs(a - b) / std::max(1.0f, std::abs(a)));
                    EXPECT_NEAR(a, b, 1e-5f * std::max(1.0f, std::abs(a))) << x << " " << y << " " << z << " ch " << ch;
                }
                ++compared;
            }
    std::printf("single-material voxels compared: %d, largest relative difference %.2g\n", compared, double(worst));
    EXPECT_GT(compared, 1000);
}

}  // namespace
}  // namespace dvsgi::test
