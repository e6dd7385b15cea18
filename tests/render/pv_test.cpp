// Progressive screen-space voxelization (--voxelizer pv): the cleanup against
// a CPU model of its rule, the injection against the geometric voxelizer, and
// stale voxels freed once the camera sees the space they held.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "gpu/context.h"
#include "gpu/transfer.h"
#include "gpu_fixture.h"
#include "shared/pv_pass.h"
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"
#include "vxgi/pv_voxelize.h"
#include "vxgi/volumes.h"
#include "vxgi/voxel_storage_io.h"

namespace dvsgi::test {
namespace {

namespace sh = dvsgi::shader;

constexpr uint32_t kN = 32;  // the grid spans [-1, 1]^3: voxels of 1/16 m, layer 16 starts at y = 0
float layerCentre(int i) { return -1.0f + (float(i) + 0.5f) / 16.0f; }

scene::PlacedCamera topDownCamera(float height) {
    scene::PlacedCamera c;
    c.camera.yfov = glm::radians(60.0f);
    c.camera.znear = 0.01f;
    c.camera.zfar = 100.0f;
    c.world = glm::translate(glm::mat4(1.0f), glm::vec3(0, height, 0)) *
              glm::mat4_cast(glm::angleAxis(-glm::half_pi<float>(), glm::vec3(1, 0, 0)));
    return c;
}

// The cleanup rule of pv_cleanup.comp for one view, on the host: nine rays
// over the voxel's projected footprint.
enum class Verdict { Keep, Band, Free };
struct Classified {
    Verdict verdict;
    bool ambiguous;  // a ray within rounding of a pixel edge or of the tolerance
};
template <class DepthAt>
Classified classify(const glm::mat4& viewProj, glm::ivec2 size, DepthAt depthAt, glm::vec3 c, float halfDiagonal,
                    float tolerance) {
    const glm::vec4 clip = viewProj * glm::vec4(c, 1.0f);
    if (clip.w <= 0.0f) return {Verdict::Keep, false};
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    if (std::abs(ndc.x) > 1.0f || std::abs(ndc.y) > 1.0f || ndc.z < 0.0f || ndc.z > 1.0f) return {Verdict::Keep, false};
    float r = 0.0f;
    for (int a = 0; a < 3; ++a) {
        const glm::vec4 e = clip + halfDiagonal * viewProj[a];
        const glm::vec2 d = glm::abs(glm::vec2(e) / e.w - glm::vec2(ndc));
        r = std::max(r, std::max(d.x, d.y));
    }
    const glm::mat4 inv = glm::inverse(viewProj);
    bool ambiguous = false;
    int freed = 0;
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            const glm::vec2 q = glm::vec2(ndc) + r * glm::vec2(i, j);
            if (std::abs(q.x) > 1.0f || std::abs(q.y) > 1.0f) continue;
            const glm::vec2 at = (q * 0.5f + 0.5f) * glm::vec2(size);
            const glm::ivec2 pixel = glm::clamp(glm::ivec2(at), glm::ivec2(0), size - 1);
            const float recorded = depthAt(pixel);
            // Rounding may put the GPU's ray in a neighbouring pixel: only a
            // problem where that pixel records another depth.
            for (const glm::vec2 nudge : {glm::vec2(-1e-3f, 0), glm::vec2(1e-3f, 0), glm::vec2(0, -1e-3f), glm::vec2(0, 1e-3f)})
                ambiguous |= depthAt(glm::clamp(glm::ivec2(at + nudge), glm::ivec2(0), size - 1)) != recorded;
            if (recorded >= 1.0f) {
                ++freed;
                continue;
            }
            const glm::vec4 s = inv * glm::vec4(q, recorded, 1.0f);
            const glm::vec4 o = inv * glm::vec4(q, ndc.z, 1.0f);
            const float gap = glm::distance(glm::vec3(s) / s.w, glm::vec3(o) / o.w);
            ambiguous |= std::abs(gap - tolerance) < 1e-4f;
            if (gap <= tolerance) return {Verdict::Band, ambiguous};
            if (recorded > ndc.z) ++freed;
        }
    return {freed == 9 ? Verdict::Free : Verdict::Keep, ambiguous};
}

class PvCleanup : public GpuTest, public ::testing::WithParamInterface<bool> {};

// A synthetic depth buffer over a grid full of voxel columns: a floor at
// y = 0 on the left third of the image, nothing in the middle, a shelf at
// y = 0.5 on the right. Each voxel must be freed, kept or kept with its sums
// reduced to one fragment's worth (the camera's band) exactly as the rule
// says. Parameter: the buffer is the camera's (perspective, from above) or
// layer 1 of the shadow maps (orthographic, with a tolerance of its own; a
// shadow map's band keeps sums as they are).
TEST_P(PvCleanup, FreesKeepsAndUpdatesVoxelsAsTheRuleSays) {
    const bool shadow = GetParam();
    gpu::Context& ctx = context();
    const vxgi::GridSpec grid = vxgi::gridForBox(glm::vec3(-1.0f), glm::vec3(1.0f), kN);
    vxgi::VoxelVolumes volumes(ctx, grid);

    // Columns over the whole grid, every other column, all layers: sums of 3
    // fragments with distinct values.
    vxgi::DenseAttributes before(kN);
    for (int z = 0; z < int(kN); z += 2)
        for (int x = 0; x < int(kN); x += 2)
            for (int y = 0; y < int(kN); ++y) {
                before.at(x, y, z, sh::CH_COUNT) = 3.0f;
                before.at(x, y, z, sh::CH_ALBEDO_R) = 0.3f * float(x + 1);
                before.at(x, y, z, sh::CH_ALBEDO_G) = 0.2f * float(y + 1);
                before.at(x, y, z, sh::CH_EMISSION_B) = 0.1f * float(z + 1);
                before.at(x, y, z, sh::CH_NORMAL_POS_Y) = 3.0f;
            }
    vxgi::uploadAttributes(ctx, volumes, before);

    const glm::ivec2 size(64, 64);
    const scene::PlacedCamera camera = topDownCamera(2.0f);
    const glm::mat4 viewProj =
        shadow ? glm::ortho(-1.1f, 1.1f, -1.1f, 1.1f, 0.5f, 4.0f) * render::viewMatrix(camera)
               : render::projectionMatrix(camera, size.x, size.y) * render::viewMatrix(camera);
    const float shadowTolerance = shadow ? 0.01f : 0.0f;
    auto planeDepth = [&](float y) {
        const glm::vec4 clip = viewProj * glm::vec4(0.0f, y, 0.0f, 1.0f);
        return clip.z / clip.w;
    };
    const float floorDepth = planeDepth(0.0f), shelfDepth = planeDepth(0.5f);
    auto depthAt = [&](glm::ivec2 p) { return p.x < 24 ? floorDepth : (p.x < 40 ? 1.0f : shelfDepth); };
    std::vector<float> depth(size_t(size.x) * size.y);
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) depth[size_t(y) * size.x + x] = depthAt({x, y});

    // The other buffer records nothing and is not among the views.
    const std::vector<float> nothing(depth.size(), 1.0f);
    std::vector<float> layers = nothing;
    layers.insert(layers.end(), depth.begin(), depth.end());
    gpu::ImageDesc d;
    d.format = VK_FORMAT_D32_SFLOAT;
    d.extent = {uint32_t(size.x), uint32_t(size.y), 1};
    d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    d.name = "camera depth";
    gpu::Image cameraDepth(ctx, d);
    gpu::uploadImage(ctx, cameraDepth, shadow ? nothing.data() : depth.data(), depth.size() * sizeof(float),
                     gpu::use::DepthRead);
    d.layers = 2;
    d.name = "shadow maps";
    gpu::Image shadowMaps(ctx, d);
    gpu::uploadImage(ctx, shadowMaps, shadow ? layers.data() : std::vector<float>(2 * depth.size(), 1.0f).data(),
                     2 * depth.size() * sizeof(float), gpu::use::ShaderRead);
    const sh::PvDepthView view{viewProj, glm::inverse(viewProj),
                               glm::vec4(shadow ? 1.0f : sh::PV_CAMERA_LAYER, shadowTolerance, 0, 0)};
    gpu::Buffer views = gpu::createBuffer(ctx, &view, sizeof(view), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "views");
    gpu::SamplerDesc sd;
    sd.filter = VK_FILTER_NEAREST;
    sd.mipmap = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sd.address = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    gpu::Sampler point(ctx, sd);

    gpu::Tracker tracker = volumeTracker(volumes);
    tracker.assume(cameraDepth, gpu::use::DepthRead);
    tracker.assume(shadowMaps, gpu::use::ShaderRead);
    vxgi::PvVoxelizer pv(ctx);
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        pv.cleanup(cmd, tracker, volumes, {cameraDepth, shadowMaps, views, 1, point.handle()}, nullptr);
    });
    const vxgi::DenseAttributes after = vxgi::readAttributes(ctx, volumes);

    const float halfDiagonal = 0.5f * std::sqrt(3.0f) * grid.voxelSize;
    std::map<Verdict, int> seen;
    int ambiguous = 0;
    for (int z = 0; z < int(kN); z += 2)
        for (int x = 0; x < int(kN); x += 2)
            for (int y = 0; y < int(kN); ++y) {
                const glm::vec3 c(layerCentre(x), layerCentre(y), layerCentre(z));
                Classified k = classify(viewProj, size, depthAt, c, halfDiagonal, halfDiagonal + shadowTolerance);
                if (shadow && k.verdict == Verdict::Band) k.verdict = Verdict::Keep;
                if (k.ambiguous) {
                    ++ambiguous;
                    continue;
                }
                ++seen[k.verdict];
                const float count = after.at(x, y, z, sh::CH_COUNT);
                if (k.verdict == Verdict::Free) {
                    ASSERT_EQ(count, 0.0f) << "voxel (" << x << ", " << y << ", " << z << ") should be freed";
                    continue;
                }
                // Band: scaled to one fragment; kept: unchanged.
                const float scale = k.verdict == Verdict::Band ? 1.0f / 3.0f : 1.0f;
                for (uint32_t ch = 0; ch < sh::VOXEL_CHANNELS; ++ch)
                    ASSERT_NEAR(after.at(x, y, z, ch), before.at(x, y, z, ch) * scale, 1e-5f)
                        << "channel " << ch << " of voxel (" << x << ", " << y << ", " << z << ")";
            }
    std::printf("  kept %d, in the band %d, freed %d, skipped as ambiguous %d\n", seen[Verdict::Keep],
                seen[Verdict::Band], seen[Verdict::Free], ambiguous);
    EXPECT_GT(seen[Verdict::Keep], 100);
    if (!shadow) {
        EXPECT_GT(seen[Verdict::Band], 20);
    }
    EXPECT_GT(seen[Verdict::Free], 100);
    EXPECT_LT(ambiguous, 10);
    // Nothing appeared where nothing was.
    for (int z = 0; z < int(kN); ++z)
        for (int x = 0; x < int(kN); ++x)
            for (int y = 0; y < int(kN); ++y)
                if (x % 2 || z % 2) {
                    ASSERT_EQ(after.at(x, y, z, sh::CH_COUNT), 0.0f);
                }
}

INSTANTIATE_TEST_SUITE_P(DepthViews, PvCleanup, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& info) { return info.param ? "ShadowMap" : "Camera"; });

render::RenderSettings pvSettings(vxgi::VoxelizerKind kind) {
    render::RenderSettings rs;
    rs.width = rs.height = 128;
    rs.voxels = kN;
    rs.hasVoxelBox = true;
    rs.voxelBoxMin = glm::vec3(-1.0f);
    rs.voxelBoxMax = glm::vec3(1.0f);
    rs.voxelizer = kind;
    rs.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    rs.voxelLight.bounces = 0;
    rs.temporal.enabled = false;
    return rs;
}

std::vector<float> channel(const vxgi::DenseAttributes& a, uint32_t ch) {
    const size_t n3 = size_t(a.n) * a.n * a.n;
    return std::vector<float>(a.data.begin() + n3 * ch, a.data.begin() + n3 * (ch + 1));
}

class PvVoxelize : public GpuTest {};

// Renders one frame with `settings` (pv) and with the exact compute
// voxelizer: the same `voxels` voxels, none missed or extra, with the same
// albedo and +Y normal weight.
void expectExactVoxels(const scene::Scene& s, const render::RenderSettings& settings, size_t voxels) {
    render::Renderer pv(context(), s, settings);
    pv.renderFrame();
    render::Renderer exact(context(), s, pvSettings(vxgi::VoxelizerKind::Compute));
    exact.renderFrame();
    const vxgi::DenseAttributes a = vxgi::readAttributes(context(), *pv.volumes());
    const vxgi::DenseAttributes b = vxgi::readAttributes(context(), *exact.volumes());
    const std::vector<float> countA = channel(a, sh::CH_COUNT), countB = channel(b, sh::CH_COUNT);
    size_t occupied = 0, missed = 0, extra = 0;
    for (size_t i = 0; i < countA.size(); ++i) {
        occupied += countB[i] > 0.0f;
        missed += countB[i] > 0.0f && countA[i] == 0.0f;
        extra += countA[i] > 0.0f && countB[i] == 0.0f;
    }
    std::printf("  geometric voxels %zu, missed by pv %zu, extra in pv %zu\n", occupied, missed, extra);
    EXPECT_EQ(occupied, voxels);
    EXPECT_EQ(missed, 0u);
    EXPECT_EQ(extra, 0u);
    for (size_t i = 0; i < countA.size(); ++i) {
        if (countA[i] == 0.0f) continue;
        for (uint32_t ch : {sh::CH_ALBEDO_R, sh::CH_ALBEDO_G, sh::CH_ALBEDO_B, sh::CH_NORMAL_POS_Y})
            ASSERT_NEAR(a.data[ch * countA.size() + i] / countA[i], b.data[ch * countB.size() + i] / countB[i], 1e-3f)
                << "channel " << ch << " at index " << i;
    }
}

// A square seen whole by the camera (edges and plane on voxel centres, about
// three pixels per voxel): progressive voxelization finds exactly the voxels
// the exact geometric voxelizer marks, with the same material and normal.
TEST_F(PvVoxelize, PlaneSeenByTheCameraEqualsItsGeometricVoxelization) {
    scene::Scene s;
    addQuad(s, addMaterial(s, glm::vec3(0.6f, 0.3f, 0.2f)), glm::vec3(0.0f, layerCentre(16), 0.0f), 6.5f / 16.0f);
    addTopDownCamera(s, 2.0f, glm::radians(60.0f));
    expectExactVoxels(s, pvSettings(vxgi::VoxelizerKind::Pv), 14 * 14);
}

// The single-pass variant on the same square: a voxel is on when the surface
// seen through its centre lies within its half-diagonal, so it finds the
// square's voxels whose centres the square covers, one layer, and nothing
// else (the border voxels, whose centres lie on the square's edges, may go
// either way).
TEST_F(PvVoxelize, SinglePassFindsTheVoxelsWhoseCentresTheSurfaceCovers) {
    scene::Scene s;
    addQuad(s, addMaterial(s, glm::vec3(0.6f, 0.3f, 0.2f)), glm::vec3(0.0f, layerCentre(16), 0.0f), 6.5f / 16.0f);
    addTopDownCamera(s, 2.0f, glm::radians(60.0f));
    render::RenderSettings rs = pvSettings(vxgi::VoxelizerKind::Pv);
    rs.pv.singlePass = true;
    render::Renderer pv(context(), s, rs);
    pv.renderFrame();
    const std::vector<float> count = channel(vxgi::readAttributes(context(), *pv.volumes()), sh::CH_COUNT);
    size_t interior = 0, border = 0, outside = 0;
    for (int z = 0; z < int(kN); ++z)
        for (int y = 0; y < int(kN); ++y)
            for (int x = 0; x < int(kN); ++x) {
                const bool on = count[(size_t(z) * kN + y) * kN + x] > 0.0f;
                const bool inX = x >= 9 && x <= 22, inZ = z >= 9 && z <= 22;
                const bool edge = x == 9 || x == 22 || z == 9 || z == 22;
                if (y == 16 && inX && inZ && !edge) {
                    interior += on;
                } else if (y == 16 && inX && inZ) {
                    border += on;
                } else {
                    outside += on;
                }
            }
    std::printf("  interior voxels on %zu of 144, border %zu of 52, elsewhere %zu\n", interior, border, outside);
    EXPECT_EQ(interior, 12u * 12u);
    EXPECT_EQ(outside, 0u);
}

// A floor of 30 x 30 voxels in layer 16 and, above its left half, a block of
// 6 x 6 voxels in layer 21 (at x = -0.5 m), seen from above; returns the
// block's node.
int floorAndBlock(scene::Scene& s) {
    const int white = addMaterial(s, glm::vec3(0.8f));
    addQuad(s, white, glm::vec3(0.0f, layerCentre(16), 0.0f), 14.5f / 16.0f);
    const int block = addQuad(s, white, glm::vec3(-0.5f, layerCentre(21), 0.0f), 2.5f / 16.0f);
    addTopDownCamera(s, 2.0f, glm::radians(60.0f));
    return block;
}

// A block above a floor moves: once the camera sees the floor where the block
// was, the block's old voxels are gone and the floor under it is found; the
// floor under the block's new place, seen before, is kept.
TEST_F(PvVoxelize, MovedObjectLeavesNoStaleVoxelsOnceTheSpaceItLeftIsSeen) {
    scene::Scene s;
    const int block = floorAndBlock(s);
    render::Renderer r(context(), s, pvSettings(vxgi::VoxelizerKind::Pv));
    r.renderFrame();
    auto layerVoxels = [&](int layer, bool left) {
        const std::vector<float> c = channel(vxgi::readAttributes(context(), *r.volumes()), sh::CH_COUNT);
        int found = 0;
        for (int z = 0; z < int(kN); ++z)
            for (int x = left ? 0 : 16; x < (left ? 16 : int(kN)); ++x)
                found += c[(size_t(z) * kN + layer) * kN + x] > 0.0f;
        return found;
    };
    const int blockVoxels = layerVoxels(21, true);
    EXPECT_EQ(blockVoxels, 6 * 6);
    const int floorLeft = layerVoxels(16, true);  // the block hides part of it

    r.scene().nodes[size_t(block)].translation.x = 0.5f;
    r.sceneChanged();
    r.renderFrame();
    std::printf("  block voxels %d; left floor voxels %d before the move, %d after\n", blockVoxels, floorLeft,
                layerVoxels(16, true));
    EXPECT_EQ(layerVoxels(21, true), 0) << "stale block voxels where the block was";
    EXPECT_EQ(layerVoxels(21, false), blockVoxels);
    EXPECT_EQ(layerVoxels(16, true), 30 * 15) << "the floor where the block was should be found";
    EXPECT_EQ(layerVoxels(16, false), 30 * 15) << "the floor under the block's new place, seen before, is kept";
    for (int layer = 0; layer < int(kN); ++layer)
        if (layer != 16 && layer != 21) {
            EXPECT_EQ(layerVoxels(layer, true) + layerVoxels(layer, false), 0);
        }
}

// The chapter's convergence: the camera orbits a sphere once around Y and
// once around X; every voxel the exact geometric voxelizer marks should then
// be found, and nothing far from the surface.
class PvOrbit : public GpuTest, public ::testing::WithParamInterface<bool> {};

TEST_P(PvOrbit, AroundASphereConvergesToItsGeometricVoxelization) {
    const bool singlePass = GetParam();
    scene::Scene s;
    addMeshNode(s, icosphere(3), addMaterial(s, glm::vec3(0.7f)), glm::vec3(0.03f, -0.02f, 0.01f),
                glm::quat(1, 0, 0, 0), glm::vec3(0.55f));
    addTopDownCamera(s, 2.5f, glm::radians(60.0f));
    scene::CameraPath path;
    path.catmullRom = false;
    constexpr int kSteps = 8;  // per orbit
    for (int axis = 0; axis < 2; ++axis)
        for (int k = 0; k < kSteps; ++k) {
            const float a = 2.0f * glm::pi<float>() * float(k) / kSteps;
            // Around Y in the xz plane, then around X in the yz plane (up = +X there).
            const glm::vec3 dir = axis == 0 ? glm::vec3(std::sin(a), 0.0f, std::cos(a))
                                            : glm::vec3(0.0f, std::sin(a), std::cos(a));
            const glm::vec3 up = axis == 0 ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
            scene::CameraKey key;
            key.time = float(axis * kSteps + k);
            key.position = 2.5f * dir;
            key.orientation = glm::quatLookAt(-dir, up);
            path.keys.push_back(key);
        }
    render::RenderSettings rs = pvSettings(vxgi::VoxelizerKind::Pv);
    rs.width = rs.height = 256;  // about 5.6 pixels per voxel across the sphere
    rs.pv.singlePass = singlePass;
    render::Renderer pv(context(), s, rs);
    pv.setCameraPath(path);
    render::Renderer exact(context(), s, pvSettings(vxgi::VoxelizerKind::Compute));
    exact.renderFrame();
    // The sphere stays put, so no voxel of its surface found once may be freed
    // later (the single pass also turns on band voxels just off the surface,
    // which later views rightly free).
    const std::vector<float> b = channel(vxgi::readAttributes(context(), *exact.volumes()), sh::CH_COUNT);
    std::vector<float> everFound(b.size(), 0.0f);
    for (const scene::CameraKey& key : path.keys) {
        pv.setTime(key.time);
        pv.renderFrame();
        const std::vector<float> c = channel(vxgi::readAttributes(context(), *pv.volumes()), sh::CH_COUNT);
        size_t lost = 0;
        for (size_t i = 0; i < c.size(); ++i) {
            lost += everFound[i] > 0.0f && c[i] == 0.0f && b[i] > 0.0f;
            if (c[i] > 0.0f) everFound[i] = 1.0f;
        }
        EXPECT_EQ(lost, 0u) << "voxels found earlier were freed at time " << key.time;
    }
    const std::vector<float> a = channel(vxgi::readAttributes(context(), *pv.volumes()), sh::CH_COUNT);
    auto at = [](const std::vector<float>& c, int x, int y, int z) {
        if (x < 0 || y < 0 || z < 0 || x >= int(kN) || y >= int(kN) || z >= int(kN)) return 0.0f;
        return c[(size_t(z) * kN + y) * kN + x];
    };
    size_t geometric = 0, found = 0, pvVoxels = 0, far = 0;
    for (int z = 0; z < int(kN); ++z)
        for (int y = 0; y < int(kN); ++y)
            for (int x = 0; x < int(kN); ++x) {
                if (at(b, x, y, z) > 0.0f) {
                    ++geometric;
                    found += at(a, x, y, z) > 0.0f;
                }
                if (at(a, x, y, z) == 0.0f) continue;
                ++pvVoxels;
                bool near = false;
                for (int k = 0; k < 27 && !near; ++k) near = at(b, x + k % 3 - 1, y + k / 3 % 3 - 1, z + k / 9 - 1) > 0.0f;
                far += !near;
            }
    std::printf("  geometric voxels %zu, found by pv %zu (%.2f %%); pv voxels %zu, farther than one voxel %zu\n",
                geometric, found, 100.0 * double(found) / double(geometric), pvVoxels, far);
    // Measured 100 % (98.42 % when a sample reached only the voxels its cell's
    // corners lie in, 92.45 % with only its own voxel); 13 extra voxels, next
    // to the surface, where the tangent-plane footprints leave the curved
    // surface. Single pass: 91.55 %; a voxel counts only when the ray through
    // its centre meets the surface within its half-diagonal.
    EXPECT_GE(double(found), (singlePass ? 0.91 : 0.998) * double(geometric));
    EXPECT_EQ(far, 0u);
}

INSTANTIATE_TEST_SUITE_P(Injection, PvOrbit, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& info) { return info.param ? "SinglePass" : "Splats"; });

sh::VoxelListHeader listHeader(const render::Renderer& r) {
    const std::vector<uint8_t> bytes = gpu::readbackBuffer(context(), r.volumes()->list, sizeof(sh::VoxelListHeader));
    sh::VoxelListHeader h;
    std::memcpy(&h, bytes.data(), sizeof(h));
    return h;
}

// The list keeps last frame's survivors first (counts.y) and this frame's new
// voxels after them; --view voxels:age draws the new ones orange.
TEST_F(PvVoxelize, AgeViewShowsWhatEachFrameFound) {
    scene::Scene s;
    const int block = floorAndBlock(s);
    render::RenderSettings rs = pvSettings(vxgi::VoxelizerKind::Pv);
    rs.width = rs.height = 64;
    render::Renderer r(context(), s, rs);
    r.renderFrame();
    sh::VoxelListHeader h = listHeader(r);
    EXPECT_EQ(h.counts.y, 0u);
    EXPECT_GT(h.counts.x, 0u);
    const uint32_t first = h.counts.x;
    r.renderFrame();
    h = listHeader(r);
    EXPECT_EQ(h.counts.y, first) << "every voxel survives an unchanged frame";
    EXPECT_EQ(h.counts.x, first) << "and nothing new is found";

    r.scene().nodes[size_t(block)].translation.x = 0.5f;
    r.sceneChanged();
    rs.view.mode = render::ViewMode::VoxelAge;
    ASSERT_TRUE(r.applySettings(rs));
    r.renderFrame();
    h = listHeader(r);
    std::printf("  first frame %u voxels; after the move %u kept, %u new\n", first, h.counts.y, h.counts.x - h.counts.y);
    EXPECT_EQ(h.counts.y, first - 36u) << "all but the block's old voxels kept";
    // The block's 36 voxels at its new place and the floor it hid before (20
    // voxels at 64^2, of which the camera saw a sliver when the block was there).
    EXPECT_EQ(h.counts.x - h.counts.y, 56u) << "new voxels";
    const image::ImageRGBA32F img = r.readOutput();
    size_t orange = 0, blue = 0;
    for (size_t i = 0; i + 3 < img.rgba.size(); i += 4) {
        orange += img.rgba[i] > 0.6f && img.rgba[i + 2] < 0.2f;
        blue += img.rgba[i + 2] > 0.5f && img.rgba[i] < 0.5f;
    }
    std::printf("  age view: %zu orange pixels, %zu blue\n", orange, blue);
    EXPECT_GT(orange, 20u);
    EXPECT_GT(blue, 1000u);
}

class PvLights : public GpuTest, public ::testing::WithParamInterface<scene::LightType> {};

// A floor that only a light sees (the camera looks up into empty space): the
// light's reflective shadow map voxelizes it as the exact voxelizer does, with
// the normal facing the light.
TEST_P(PvLights, ReflectiveShadowMapsVoxelizeWhatOnlyALightSees) {
    scene::Scene s;
    addQuad(s, addMaterial(s, glm::vec3(0.6f, 0.5f, 0.4f)), glm::vec3(0.0f, layerCentre(16), 0.0f), 6.5f / 16.0f);
    addTopDownCamera(s, 0.5f, glm::radians(60.0f));
    s.nodes.back().rotation = glm::angleAxis(glm::half_pi<float>(), glm::vec3(1, 0, 0));  // looks up
    scene::Light light;
    light.name = "light";
    light.type = GetParam();
    light.outerConeAngle = 1.2f;
    addLight(s, light, glm::vec3(0.1f, 0.7f, -0.05f), glm::vec3(0.3f, -1.0f, 0.2f));
    render::RenderSettings rs = pvSettings(vxgi::VoxelizerKind::Pv);
    rs.pv.rsm = 128;
    expectExactVoxels(s, rs, 14 * 14);  // the normal weight included: all +Y, facing the light
}

// The extra viewpoints: the camera looks up into empty space, and the view
// around it that looks down finds the floor (about 4 texels per voxel at 64^2).
TEST_F(PvVoxelize, ViewsAroundTheCameraFindWhatItDoesNotFace) {
    scene::Scene s;
    addQuad(s, addMaterial(s, glm::vec3(0.6f, 0.5f, 0.4f)), glm::vec3(0.0f, layerCentre(16), 0.0f), 6.5f / 16.0f);
    addTopDownCamera(s, 0.5f, glm::radians(60.0f));
    s.nodes.back().rotation = glm::angleAxis(glm::half_pi<float>(), glm::vec3(1, 0, 0));  // looks up
    render::RenderSettings rs = pvSettings(vxgi::VoxelizerKind::Pv);
    rs.pv.views = 64;
    expectExactVoxels(s, rs, 14 * 14);
}

INSTANTIATE_TEST_SUITE_P(LightTypes, PvLights,
                         ::testing::Values(scene::LightType::Directional, scene::LightType::Point, scene::LightType::Spot),
                         [](const ::testing::TestParamInfo<scene::LightType>& info) {
                             return std::string(info.param == scene::LightType::Directional ? "Directional"
                                                : info.param == scene::LightType::Point    ? "Point"
                                                                                           : "Spot");
                         });

}  // namespace
}  // namespace dvsgi::test
