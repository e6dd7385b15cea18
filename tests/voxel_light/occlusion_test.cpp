// Occlusion of the light at voxels: a wall between a sun and part of a floor,
// voxelized and lit by the Renderer with each occlusion mode.
#include <cmath>
#include <cstdio>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

#include "gpu_fixture.h"
#include "light_helpers.h"
#include "vxgi/voxel_light_settings.h"

namespace dvsgi::test {
namespace {

namespace sh = dvsgi::shader;

constexpr uint32_t kN = 32;
constexpr float kBox = 1.25f;          // grid on [-1.25, 1.25]^3: voxel 0.078125 m, exact
constexpr float kFloorY = -0.5f;       // voxel y 9.6: inside layer 9
constexpr int kFloorLayer = 9;
constexpr float kWallX = -0.27734375f; // voxel x 12.5: the middle of column 12
constexpr int kWallColumn = 12;
constexpr float kWallTop = 0.1f;
constexpr float kE = 4.0f;
const glm::vec3 kAlbedo(0.6f, 0.5f, 0.4f);
// The sun travels +X and down at 45 degrees, so the wall's shadow falls on the
// floor at +X of the wall, kWallTop - floor top = 0.569 m (7.3 voxels) long.
const glm::vec3 kSunDir = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f));

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
    scene::Light sun;
    sun.name = "sun";
    sun.type = scene::LightType::Directional;
    sun.intensity = kE;
    addLight(s, sun, glm::vec3(-2.0f, 2.0f, 0.0f), kSunDir);
    return s;
}

render::RenderSettings settings(vxgi::Occlusion mode) {
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
    rs.voxelLight.softKappa = 0.5f;
    return rs;
}

// Radiance of a fully lit floor voxel: normal +Y, so eq. 5 is W_y D_y = L_y.
glm::vec3 fullyLit() {
    const float Ly = -kSunDir.y;
    return kAlbedo / glm::pi<float>() * kE * Ly;
}

// The shader's voxel shadow ray, marched on the host over the read-back
// occupancy, in float like the shader.
float referenceVisibility(const AccumVolume& accum, const vxgi::GridSpec& g, glm::ivec3 v, bool soft,
                          float kappa) {
    const float s = g.voxelSize;
    const glm::vec3 n(0, 1, 0);
    const glm::vec3 P = g.origin + (glm::vec3(v) + 0.5f) * s + n * (0.5f * s);
    const glm::vec3 L = -kSunDir;
    const glm::vec3 p = (P - g.origin) / s;
    const glm::ivec3 self = glm::ivec3(glm::floor(p));
    const float maxT = 2.0f * float(g.n);
    float nu = 0.0f;
    glm::ivec3 last = self;
    for (float t = 1.0f; t < maxT; t += 0.5f) {
        const glm::ivec3 c = glm::ivec3(glm::floor(p + L * t));
        if (glm::any(glm::lessThan(c, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(c, glm::ivec3(int(g.n)))))
            break;
        if (c == last || c == self) continue;
        last = c;
        if (accum.at(c.x, c.y, c.z, sh::CH_COUNT) <= 0.0f) continue;
        if (!soft) return 0.0f;
        nu += (1.0f - nu) * std::min(kappa / t, 1.0f);
        if (nu > 0.999f) return 0.0f;
    }
    return 1.0f - nu;
}

struct FloorResult {
    Rgba16Volume radiance;
    AccumVolume accum{kN};
    vxgi::GridSpec grid;
};

FloorResult renderFloor(vxgi::Occlusion mode) {
    render::Renderer r(context(), wallScene(), settings(mode));
    r.renderFrame();
    FloorResult out;
    out.grid = r.volumes()->grid;
    out.radiance = readRgba16(r.volumes()->radiance);
    out.accum = readAccum(*r.volumes());
    return out;
}

// Floor voxels by region along x: shadowed (behind the wall, away from the
// penumbra edges) and open (either side, away from the shadow).
bool shadowed(int x) { return x >= kWallColumn + 2 && x <= kWallColumn + 6; }
bool open(int x) { return (x >= 4 && x <= kWallColumn - 2) || (x >= 23 && x <= 27); }
bool awayFromFloorEdges(int z) { return z >= 6 && z <= 25; }

void expectLit(const glm::vec4& got, const char* mode, int x, int z) {
    const glm::vec3 want = fullyLit();
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(got[c], want[c], 2e-3f * want[c] + 1e-5f) << mode << ": open floor voxel x=" << x << " z=" << z;
}

class VoxelOcclusion : public GpuTest {};

TEST_F(VoxelOcclusion, FloorLayerIsVoxelized) {
    const FloorResult f = renderFloor(vxgi::Occlusion::None);
    int occupied = 0;
    for (int z = 0; z < int(kN); ++z)
        for (int x = 0; x < int(kN); ++x) {
            if (!awayFromFloorEdges(z) || !(open(x) || shadowed(x))) continue;
            ASSERT_GT(f.accum.at(x, kFloorLayer, z, sh::CH_COUNT), 0.0f) << x << " " << z;
            // Without occlusion every floor voxel gets the full sun.
            expectLit(f.radiance.at(x, kFloorLayer, z), "none", x, z);
            ++occupied;
        }
    EXPECT_GT(occupied, 200);
}

TEST_F(VoxelOcclusion, ShadowMapDarkensVoxelsBehindTheWall) {
    const FloorResult f = renderFloor(vxgi::Occlusion::ShadowMap);
    int dark = 0, lit = 0;
    for (int z = 0; z < int(kN); ++z)
        for (int x = 0; x < int(kN); ++x) {
            if (!awayFromFloorEdges(z)) continue;
            const glm::vec4 got = f.radiance.at(x, kFloorLayer, z);
            if (shadowed(x)) {
                EXPECT_LT(glm::length(glm::vec3(got)), 1e-4f) << "shadowed floor voxel x=" << x << " z=" << z;
                ++dark;
            } else if (open(x)) {
                expectLit(got, "shadow map", x, z);
                ++lit;
            }
        }
    EXPECT_GT(dark, 50);
    EXPECT_GT(lit, 200);
}

// Hard and soft raycasts: the region checks, and every floor voxel against
// the same march over the read-back occupancy.
void checkRaycast(vxgi::Occlusion mode) {
    const bool soft = mode == vxgi::Occlusion::RaycastSoft;
    const char* name = soft ? "raycast soft" : "raycast hard";
    const FloorResult f = renderFloor(mode);
    const glm::vec3 lit = fullyLit();
    int dark = 0, open_ = 0, penumbra = 0, mismatches = 0;
    for (int z = 0; z < int(kN); ++z)
        for (int x = 0; x < int(kN); ++x) {
            if (!awayFromFloorEdges(z) || std::abs(x - kWallColumn) <= 1) continue;
            if (f.accum.at(x, kFloorLayer, z, sh::CH_COUNT) <= 0.0f) continue;
            const glm::vec4 got = f.radiance.at(x, kFloorLayer, z);
            const float vis = got.g / lit.g;
            if (open(x)) {
                expectLit(got, name, x, z);
                ++open_;
            }
            if (shadowed(x)) {
                if (soft) {
                    EXPECT_GT(vis, 0.01f) << name << ": x=" << x << " z=" << z;
                    EXPECT_LT(vis, 0.99f) << name << ": x=" << x << " z=" << z;
                } else {
                    EXPECT_LT(glm::length(glm::vec3(got)), 1e-4f) << name << ": x=" << x << " z=" << z;
                }
                ++dark;
            }
            if (vis > 0.01f && vis < 0.99f) ++penumbra;
            const float want = referenceVisibility(f.accum, f.grid, {x, kFloorLayer, z}, soft, 0.5f);
            for (int c = 0; c < 3; ++c)
                if (std::abs(got[c] - lit[c] * want) > 2e-3f * lit[c] + 1e-5f && mismatches++ < 5)
                    ADD_FAILURE() << name << ": floor voxel x=" << x << " z=" << z << " visibility " << vis
                                  << ", host march " << want;
        }
    std::printf("  %s: %d shadowed, %d open, %d with visibility in (0.01, 0.99)\n", name, dark, open_, penumbra);
    EXPECT_EQ(mismatches, 0);
    EXPECT_GT(dark, 50);
    EXPECT_GT(open_, 200);
    if (soft) {
        EXPECT_GE(penumbra, dark);
    } else {
        EXPECT_EQ(penumbra, 0);
    }
}

TEST_F(VoxelOcclusion, RaycastHardDarkensVoxelsBehindTheWall) { checkRaycast(vxgi::Occlusion::RaycastHard); }

TEST_F(VoxelOcclusion, RaycastSoftGivesPartialVisibilityBehindTheWall) {
    checkRaycast(vxgi::Occlusion::RaycastSoft);
}

// The per-light mode (lightOcclusion by light name) reaches the shader when
// no global override is set.
TEST_F(VoxelOcclusion, PerLightModeSelectsRaycast) {
    render::RenderSettings rs = settings(vxgi::Occlusion::PerLight);
    rs.lightOcclusion = {{"sun", vxgi::Occlusion::RaycastHard}};
    rs.shadows = false;  // shadow maps off: only the raycast can darken the floor
    render::Renderer r(context(), wallScene(), rs);
    r.renderFrame();
    const Rgba16Volume radiance = readRgba16(r.volumes()->radiance);
    for (int x : {kWallColumn + 3, 25}) {
        if (shadowed(x)) {
            EXPECT_LT(radiance.at(x, kFloorLayer, 16).g, 1e-4f) << x;
        } else {
            expectLit(radiance.at(x, kFloorLayer, 16), "per light", x, 16);
        }
    }
}

}  // namespace
}  // namespace dvsgi::test
