// Occlusion of the light at voxels, voxelized and lit by the Renderer with each
// occlusion mode, against what the geometry and the documented formulas say:
// a wall under a 45-degree sun (where the hard shadow ends), and horizontal
// shelves under an overhead sun (the soft raycast's nu += (1 - nu) kappa / t in
// closed form).
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

#include "gpu_fixture.h"
#include "light_helpers.h"
#include "vxgi/voxel_light_settings.h"

namespace dvsgi::test {
namespace {

namespace sh = dvsgi::shader;

constexpr uint32_t kN = 32;
constexpr float kBox = 1.25f;   // grid on [-1.25, 1.25]^3
constexpr float kVoxel = 2.0f * kBox / float(kN);  // 0.078125 m: dyadic, so voxel coordinates below are exact
constexpr float kFloorY = -0.5f;  // voxel y 9.6: inside layer 9
constexpr int kFloorLayer = 9;
constexpr float kE = 4.0f;
const glm::vec3 kAlbedo(0.6f, 0.5f, 0.4f);

// World coordinate of voxel coordinate v (0 = the grid's low face).
constexpr float world(float v) { return -kBox + v * kVoxel; }

// Where a floor voxel's light is occluded from. The voxel shadow rays start at
// its centre pushed half a voxel along +Y, voxel y exactly 10.0: the face
// between layers 9 and 10. The shadow map is looked up on the floor: at the
// top of the eighth of the voxel its extents reach, voxel y 9.625 (the floor
// at 9.6 lies in eighth 4).
constexpr float kLitY = 10.0f;
constexpr float kMapY = 9.625f;

// --- A wall in the middle of column 12 (voxel x 12.5) from the floor to
// voxel y 17.9 (inside layer 17), lit by a sun travelling +X and down at 45°.
constexpr int kWallColumn = 12;
constexpr float kWallX = world(12.5f);
constexpr float kWallTop = world(17.9f);
const glm::vec3 kSunDir = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f));

// --- Overhead sun and two horizontal shelves in the middle of layers 13 and
// 17, spanning voxel x [2.5, 16.5] and [10.5, 22.5] and z [2.5, 29.5]; their
// edges lie mid-voxel so the conservative cover is unambiguous: columns 2..16
// and 10..22.
struct Shelf {
    int layer;
    float x0, x1;  // voxel coordinates
    int col0() const { return int(std::floor(x0)); }
    int col1() const { return int(std::floor(x1)); }
};
const Shelf kShelves[2] = {{13, 2.5f, 16.5f}, {17, 10.5f, 22.5f}};

render::RenderSettings settings(vxgi::Occlusion mode, float kappa = 0.5f) {
    render::RenderSettings rs;
    rs.width = rs.height = 16;
    rs.shadowMapSize = 512;
    rs.voxels = kN;
    rs.hasVoxelBox = true;
    rs.voxelBoxMin = glm::vec3(-kBox);
    rs.voxelBoxMax = glm::vec3(kBox);
    rs.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    rs.voxelLight.bounces = 0;
    rs.voxelLight.occlusion = mode;
    rs.voxelLight.softKappa = kappa;
    return rs;
}

void addSun(scene::Scene& s, glm::vec3 dir) {
    scene::Light sun;
    sun.name = "sun";
    sun.type = scene::LightType::Directional;
    sun.intensity = kE;
    addLight(s, sun, -2.0f * dir, dir);
}

scene::Scene wallScene() {
    scene::Scene s;
    const int floorMat = addMaterial(s, kAlbedo);
    const int wallMat = addMaterial(s, glm::vec3(0.3f), glm::vec3(0.0f), true);
    addQuad(s, floorMat, glm::vec3(0.0f, kFloorY, 0.0f), 1.0f);
    // A unit quad turned to face -X (toward the sun), squashed along its local
    // x (world y) to the wall's height.
    const float halfHeight = 0.5f * (kWallTop - kFloorY);
    const int wall = addQuad(s, wallMat, glm::vec3(kWallX, kFloorY + halfHeight, 0.0f), 1.0f,
                             glm::angleAxis(glm::half_pi<float>(), glm::vec3(0, 0, 1)));
    s.nodes[size_t(wall)].scale = glm::vec3(halfHeight, 1.0f, 1.0f);
    addTopDownCamera(s, 3.0f, glm::radians(60.0f));
    addSun(s, kSunDir);
    return s;
}

scene::Scene shelfScene() {
    scene::Scene s;
    const int floorMat = addMaterial(s, kAlbedo);
    const int shelfMat = addMaterial(s, glm::vec3(0.3f), glm::vec3(0.0f), true);
    addQuad(s, floorMat, glm::vec3(0.0f, kFloorY, 0.0f), 1.0f);
    for (const Shelf& sh : kShelves) {
        const int q = addQuad(s, shelfMat, glm::vec3(world(0.5f * (sh.x0 + sh.x1)), world(sh.layer + 0.5f), 0.0f), 1.0f);
        s.nodes[size_t(q)].scale = glm::vec3(0.5f * (sh.x1 - sh.x0) * kVoxel, 1.0f, 13.5f * kVoxel);
    }
    addTopDownCamera(s, 3.0f, glm::radians(60.0f));
    addSun(s, glm::vec3(0.0f, -1.0f, 0.0f));
    return s;
}

// Radiance of a fully lit floor voxel: normal +Y, so eq. 5 is W_y D_y = L_y.
glm::vec3 fullyLit(glm::vec3 sunDir) { return kAlbedo / glm::pi<float>() * kE * -sunDir.y; }

struct FloorResult {
    Rgba16Volume radiance;
    AccumVolume accum{kN};
};

FloorResult renderFloor(const scene::Scene& s, const render::RenderSettings& rs) {
    render::Renderer r(context(), s, rs);
    r.renderFrame();
    FloorResult out;
    out.radiance = readRgba16(r.volumes()->radiance);
    out.accum = readAccum(*r.volumes());
    return out;
}

bool occupied(const FloorResult& f, int x, int y, int z) { return f.accum.at(x, y, z, sh::CH_COUNT) > 0.0f; }

// The floor spans voxel x and z [3.2, 28.8]; these columns and rows are whole floor voxels.
bool onFloor(int x) { return x >= 4 && x <= 27; }
bool awayFromFloorEdges(int z) { return z >= 6 && z <= 25; }

// Radiance is stored in fp16: rounding alone moves a value by up to half a
// step, 2^-11 of the binade's bottom, i.e. up to 9.8e-4 of a value just above a
// power of two. The bound is that step; the measured worst errors are printed.
constexpr float kRelTol = 1e-3f;

struct Worst {
    float rel = 0.0f;
    void add(float got, float want) { rel = std::max(rel, std::abs(got - want) / want); }
};

void expectRadiance(const glm::vec4& got, glm::vec3 want, const char* what, int x, int z, Worst* worst = nullptr) {
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got[c], want[c], kRelTol * want[c] + 1e-6f) << what << ": floor voxel x=" << x << " z=" << z;
        if (worst) worst->add(got[c], want[c]);
    }
}

void expectDark(const glm::vec4& got, const char* what, int x, int z) {
    EXPECT_EQ(glm::vec3(got), glm::vec3(0.0f)) << what << ": shadowed floor voxel x=" << x << " z=" << z;
}

class VoxelOcclusion : public GpuTest {};

TEST_F(VoxelOcclusion, WithoutOcclusionEveryFloorVoxelGetsTheFullSun) {
    const FloorResult f = renderFloor(wallScene(), settings(vxgi::Occlusion::None));
    Worst worst;
    int count = 0;
    for (int z = 0; z < int(kN); ++z)
        for (int x = 0; x < int(kN); ++x) {
            if (!awayFromFloorEdges(z) || !onFloor(x) || std::abs(x - kWallColumn) <= 1) continue;
            ASSERT_TRUE(occupied(f, x, kFloorLayer, z)) << x << " " << z;
            expectRadiance(f.radiance.at(x, kFloorLayer, z), fullyLit(kSunDir), "none", x, z, &worst);
            ++count;
        }
    std::printf("  no occlusion: %d floor voxels, worst relative error %.2e\n", count, worst.rel);
    EXPECT_EQ(count, 20 * 21);
}

// The shadow map holds the wall's true top (voxel y 17.9). The ray from the
// lookup point of column x (voxel (x + 0.5, 9.625)) toward the sun meets the
// wall's plane (x = 12.5) at y = x - 2.375: below the top for x <= 20 (column
// 20 by 0.275 voxel, 21 mm: the map spans the scene's bounds, 2.9 m over 512
// texels, so 2.7 texels across the light less the 1.5-texel normal offset's
// 1.06 across it; column 21 passes 0.725 voxel above). Looked up half a voxel above the
// centre (y 10), as before the lookup moved onto the surface, column 20 was
// lit: every shadow edge moved toward the light by that height.
TEST_F(VoxelOcclusion, ShadowMapShadowEndsWhereTheWallTopSays) {
    const FloorResult f = renderFloor(wallScene(), settings(vxgi::Occlusion::ShadowMap));
    const float topY = (kWallTop + kBox) / kVoxel;
    int dark = 0, lit = 0;
    for (int z = 0; z < int(kN); ++z)
        for (int x = 0; x < int(kN); ++x) {
            if (!awayFromFloorEdges(z) || !onFloor(x) || x == kWallColumn) continue;
            const glm::vec4 got = f.radiance.at(x, kFloorLayer, z);
            const bool behind = x > kWallColumn && float(x) + 0.5f + (kMapY - (float(kWallColumn) + 0.5f)) < topY;
            if (behind) {
                expectDark(got, "shadow map", x, z);
                ++dark;
            } else {
                expectRadiance(got, fullyLit(kSunDir), "shadow map", x, z);
                ++lit;
            }
        }
    EXPECT_EQ(dark, 8 * 20);  // columns 13..20
    EXPECT_EQ(lit, 15 * 20);
}

// The hard raycast sees the voxelized wall, column 12 from layer 9 to 17 (top
// face at y = 18). From the lit point of column x the ray enters the column at
// x = 13, y = x - 2.5, so it is blocked exactly for 13 <= x <= 20: one column
// longer than the shadow map's, because the voxels round the wall's top up.
// Every entry height is half a voxel from the top face, so the march's
// half-voxel samples cannot slip past a corner.
TEST_F(VoxelOcclusion, RaycastHardShadowEndsWhereTheVoxelizedWallSays) {
    const FloorResult f = renderFloor(wallScene(), settings(vxgi::Occlusion::RaycastHard));
    // The premise: the wall's voxels are what conservative voxelization of it gives.
    for (int z = 6; z <= 25; ++z)
        for (int y = kFloorLayer; y <= 19; ++y) {
            ASSERT_EQ(occupied(f, kWallColumn, y, z), y <= 17) << "wall column, layer " << y << " z " << z;
            ASSERT_FALSE(occupied(f, kWallColumn + 1, y, z) && y > kFloorLayer) << "layer " << y << " z " << z;
        }
    int dark = 0, lit = 0;
    for (int z = 0; z < int(kN); ++z)
        for (int x = 0; x < int(kN); ++x) {
            if (!awayFromFloorEdges(z) || !onFloor(x) || x == kWallColumn) continue;
            const glm::vec4 got = f.radiance.at(x, kFloorLayer, z);
            const float entryY = float(x) + 0.5f + (kLitY - float(kWallColumn + 1));  // y where the ray enters column 12
            if (x > kWallColumn && entryY < 18.0f) {
                expectDark(got, "raycast hard", x, z);
                ++dark;
            } else {
                expectRadiance(got, fullyLit(kSunDir), "raycast hard", x, z);
                ++lit;
            }
        }
    EXPECT_EQ(dark, 8 * 20);  // columns 13..20
    EXPECT_EQ(lit, 15 * 20);
}

// Under an overhead sun the ray from a floor voxel's lit point (y = 10, a voxel
// face) rises straight up and enters layer k at t = k - 10 voxels (where the
// march's samples at t = 1, 1.5, 2, ... also land). Each
// occupied voxel met at distance t multiplies the visibility by 1 - min(kappa/t, 1),
// so a floor voxel under the shelves of layers 13 and 17 gets
//   (1 - kappa/3) (1 - kappa/7),
// under one of them 1 - kappa/3 or 1 - kappa/7, and 1 in the open. Hard mode:
// 0 under any shelf.
void checkShelves(vxgi::Occlusion mode, float kappa) {
    const bool soft = mode == vxgi::Occlusion::RaycastSoft;
    const FloorResult f = renderFloor(shelfScene(), settings(mode, kappa));
    // The premise: each shelf covers exactly its columns, in its own layer.
    for (int x = 0; x < int(kN); ++x)
        for (int y = kFloorLayer + 1; y < int(kN); ++y) {
            bool want = false;
            for (const Shelf& s : kShelves) want |= y == s.layer && x >= s.col0() && x <= s.col1();
            ASSERT_EQ(occupied(f, x, y, 16), want) << "voxel x " << x << " layer " << y;
        }
    const glm::vec3 sun(0.0f, -1.0f, 0.0f);
    Worst worst;
    int regions[4] = {0, 0, 0, 0};  // open, lower shelf only, upper only, both
    for (int z = 0; z < int(kN); ++z)
        for (int x = 0; x < int(kN); ++x) {
            if (!awayFromFloorEdges(z) || !onFloor(x)) continue;
            float vis = 1.0f;
            int region = 0;
            for (int i = 0; i < 2; ++i) {
                const Shelf& s = kShelves[i];
                if (x < s.col0() || x > s.col1()) continue;
                const float t = float(s.layer) - kLitY;
                vis *= soft ? 1.0f - std::min(kappa / t, 1.0f) : 0.0f;
                region |= 1 << i;
            }
            ++regions[region];
            const glm::vec4 got = f.radiance.at(x, kFloorLayer, z);
            if (vis == 0.0f)
                expectDark(got, "raycast", x, z);
            else
                expectRadiance(got, fullyLit(sun) * vis, soft ? "raycast soft" : "raycast hard", x, z, &worst);
        }
    if (soft)
        std::printf("  soft kappa %.2f: visibility %.4f / %.4f / %.4f (lower / upper / both), worst relative error "
                    "%.2e\n",
                    kappa, 1.0f - std::min(kappa / 3.0f, 1.0f), 1.0f - std::min(kappa / 7.0f, 1.0f),
                    (1.0f - std::min(kappa / 3.0f, 1.0f)) * (1.0f - kappa / 7.0f), worst.rel);
    else
        std::printf("  hard: open floor voxels' worst relative error %.2e\n", worst.rel);
    EXPECT_EQ(regions[0], 5 * 20);  // columns 23..27
    EXPECT_EQ(regions[1], 6 * 20);  // 4..9
    EXPECT_EQ(regions[2], 6 * 20);  // 17..22
    EXPECT_EQ(regions[3], 7 * 20);  // 10..16
}

TEST_F(VoxelOcclusion, RaycastSoftFollowsTheClosedFormUnderShelves) {
    for (float kappa : {0.5f, 2.0f}) {
        SCOPED_TRACE(kappa);
        checkShelves(vxgi::Occlusion::RaycastSoft, kappa);
    }
}

TEST_F(VoxelOcclusion, RaycastHardIsZeroUnderShelves) { checkShelves(vxgi::Occlusion::RaycastHard, 0.5f); }

// The per-light mode (lightOcclusion by light name) reaches the shader when
// no global override is set.
TEST_F(VoxelOcclusion, PerLightModeSelectsRaycast) {
    render::RenderSettings rs = settings(vxgi::Occlusion::PerLight);
    rs.lightOcclusion = {{"sun", vxgi::Occlusion::RaycastHard}};
    rs.shadows = false;  // shadow maps off: only the raycast can darken the floor
    const FloorResult f = renderFloor(wallScene(), rs);
    // Column 20 is dark only in the voxel raycast (the shadow map lights it).
    for (int x : {15, 20}) expectDark(f.radiance.at(x, kFloorLayer, 16), "per light", x, 16);
    expectRadiance(f.radiance.at(25, kFloorLayer, 16), fullyLit(kSunDir), "per light", 25, 16);
}

}  // namespace
}  // namespace dvsgi::test
