// Camera-following clipmaps (--clipmap, vxgi/clipmap.h; the window arithmetic
// on the host is clipmap_window_test.cpp's): a scrolled level equal, voxel for
// voxel, to one voxelized from scratch at the new position; every level equal
// to a fitted grid on its window once the toroidal roll is undone on the CPU
// (nothing lost or doubled at the windows' borders); the indirect light
// continuous across a level border; convergence when level 0 holds nothing;
// and a light switched off leaving no ghost.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <set>
#include <vector>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/packing.hpp>

#include "gpu/transfer.h"
#include "gpu_fixture.h"
#include "shared/composite_pass.h"
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"
#include "vxgi/clipmap.h"
#include "vxgi/voxel_storage_io.h"

namespace dvsgi::test {
namespace {

namespace sh = dvsgi::shader;

constexpr uint32_t kN = 32;
constexpr float kVoxel = 1.0f / 16.0f;  // level 0: a 2 m window; level 1: 4 m

// A directional light of 3 W/m^2 travelling along `direction`.
void addSun(scene::Scene& s, glm::vec3 direction) {
    scene::Light sun;
    sun.name = "sun";
    sun.type = scene::LightType::Directional;
    sun.intensity = 3.0f;
    addLight(s, sun, glm::vec3(0.0f, 5.0f, 0.0f), glm::normalize(direction));
}

// A floor, a wall and a sphere spread over more than one level-0 window.
scene::Scene spreadScene(bool emissive = true) {
    scene::Scene s;
    const int grey = addMaterial(s, glm::vec3(0.6f));
    const int red = addMaterial(s, glm::vec3(0.8f, 0.2f, 0.1f), glm::vec3(0.0f, 0.0f, emissive ? 0.5f : 0.0f));
    const float q = glm::half_pi<float>();
    addQuad(s, grey, glm::vec3(0.0f, -0.45f, 0.0f), 2.5f);
    addQuad(s, red, glm::vec3(1.3f, 0.2f, 0.0f), 0.6f, glm::angleAxis(q, glm::vec3(0, 0, 1)));
    addMeshNode(s, icosphere(2), red, glm::vec3(-0.8f, -0.1f, 0.6f), glm::quat(1, 0, 0, 0), glm::vec3(0.35f));
    addTopDownCamera(s, 0.3f, glm::radians(70.0f));
    addSun(s, glm::vec3(-0.5f, -1.0f, -0.3f));
    return s;
}

render::RenderSettings clipSettings(uint32_t levels, vxgi::VoxelizerKind voxelizer = vxgi::VoxelizerKind::Compute) {
    render::RenderSettings rs;
    rs.width = rs.height = 32;
    rs.shadowMapSize = 256;
    rs.voxels = kN;
    rs.voxelizer = voxelizer;
    rs.clipmap.levels = levels;
    rs.clipmap.voxelSize = kVoxel;
    rs.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    rs.voxelLight.bounces = 1;
    return rs;
}

void moveCamera(render::Renderer& r, glm::vec3 position) {
    for (scene::Node& n : r.scene().nodes)
        if (n.camera >= 0) n.translation = position;
    r.sceneChanged();
}

sh::VoxelListHeader listHeader(const vxgi::VoxelVolumes& v) {
    const std::vector<uint8_t> bytes = gpu::readbackBuffer(context(), v.list);
    sh::VoxelListHeader h;
    std::memcpy(&h, bytes.data(), sizeof(h));
    return h;
}

// Compares two levels' storage voxel for voxel: occupancy, and every channel's
// sum within 1e-4 relative. Returns the number of sums that differ more and
// the largest relative difference.
struct StorageDiff {
    size_t occupied = 0, occupancyDiffers = 0, sumsDiffer = 0;
    double largest = 0.0;
};
StorageDiff compareStorage(const vxgi::VoxelVolumes& a, const vxgi::VoxelVolumes& b) {
    const std::vector<uint32_t> ia = vxgi::readVoxelIndex(context(), a), ib = vxgi::readVoxelIndex(context(), b);
    const vxgi::DenseAttributes da = vxgi::readAttributes(context(), a), db = vxgi::readAttributes(context(), b);
    StorageDiff d;
    const int n = int(a.grid.n);
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const size_t o = size_t(x) + size_t(n) * (size_t(y) + size_t(n) * size_t(z));
                const bool oa = sh::indexSlot(ia[o]) != 0, ob = sh::indexSlot(ib[o]) != 0;
                d.occupied += oa;
                if (oa != ob) {
                    ++d.occupancyDiffers;
                    continue;
                }
                for (uint32_t c = 0; c < sh::VOXEL_CHANNELS; ++c) {
                    const double va = da.at(x, y, z, c), vb = db.at(x, y, z, c);
                    const double rel = std::abs(va - vb) / std::max(1.0, std::abs(vb));
                    d.largest = std::max(d.largest, rel);
                    d.sumsDiffer += rel > 1e-4;
                }
            }
    return d;
}

class Clipmap : public GpuTest {};
class ClipmapScroll : public GpuTest, public ::testing::WithParamInterface<vxgi::VoxelizerKind> {};

// The camera moves by a few voxels (the windows scroll: the scroll pass frees
// what left, static voxelization fills only the exposed slabs), then by more
// than a window (everything is freed and refilled). After each move every
// level holds exactly what a clipmap built at the new position from scratch
// holds: same window, so the same toroidal layout, voxel for voxel. Both
// voxelizers (each skips triangles inside the kept part before any voxel work).
TEST_P(ClipmapScroll, ScrolledLevelsEqualLevelsVoxelizedAtTheNewPosition) {
    const scene::Scene s = spreadScene();
    render::Renderer moving(context(), s, clipSettings(2, GetParam()));
    moving.renderFrame();
    uint32_t freedBefore = 0;
    int move = 0;
    for (const glm::vec3 to : {glm::vec3(0.55f, 0.3f, -0.4f), glm::vec3(-0.9f, 0.2f, 0.8f), glm::vec3(2.6f, 0.3f, 0.3f)}) {
        moveCamera(moving, to);
        const render::FrameStats stats = moving.renderFrame();
        const bool scrolled = std::any_of(stats.passes.begin(), stats.passes.end(),
                                          [](const gpu::TimerResult& p) { return p.name == "clipmap scroll"; });
        EXPECT_TRUE(scrolled) << "no scroll pass ran";
        render::Renderer fresh(context(), s, clipSettings(2, GetParam()));
        moveCamera(fresh, to);
        fresh.renderFrame();
        const std::vector<const vxgi::VoxelVolumes*> a = moving.levelVolumes(), b = fresh.levelVolumes();
        ASSERT_EQ(a.size(), 2u);
        for (size_t l = 0; l < a.size(); ++l) {
            ASSERT_EQ(a[l]->grid.origin, b[l]->grid.origin);
            ASSERT_EQ(a[l]->grid.wrap, b[l]->grid.wrap);
            const StorageDiff d = compareStorage(*a[l], *b[l]);
            const sh::VoxelListHeader h = listHeader(*a[l]);
            std::printf("  camera (%.2f, %.2f, %.2f), level %zu: window at (%.3f, %.3f, %.3f), wrap (%d, %d, %d), "
                        "%zu voxels, %u list entries freed by scrolls; %zu sums differ (largest %.1e)\n",
                        to.x, to.y, to.z, l, a[l]->grid.origin.x, a[l]->grid.origin.y, a[l]->grid.origin.z,
                        a[l]->grid.wrap.x, a[l]->grid.wrap.y, a[l]->grid.wrap.z, d.occupied, h.allGroups.w,
                        d.sumsDiffer, d.largest);
            EXPECT_GT(d.occupied, 100u);
            EXPECT_EQ(d.occupancyDiffers, 0u) << "voxels occupied in one and not the other";
            // The compute voxelizer's test is exact (doubles), so the kept
            // voxels, voxelized against the old window, match to the bit. The
            // rasterizer sees voxel coordinates relative to the window in
            // float, so a fragment on a pixel's edge may land differently.
            if (GetParam() == vxgi::VoxelizerKind::Compute)
                EXPECT_EQ(d.sumsDiffer, 0u);
            else
                EXPECT_LE(double(d.sumsDiffer), 0.01 * double(d.occupied * sh::VOXEL_CHANNELS));
        }
        // The first two moves scroll level 0 (entries freed add up); by the
        // third, freed entries are over half its list, so the frame after the
        // second voxelized it afresh, which compacts it (freed count back to 0).
        const uint32_t freed = listHeader(*a[0]).allGroups.w;
        if (move < 2)
            EXPECT_GT(freed, freedBefore);
        else
            EXPECT_EQ(freed, 0u);
        freedBefore = freed;
        ++move;
    }
}

// A move along one axis: every triangle that crosses into the exposed slab
// lies inside the kept box on the other two axes, so the compute voxelizer
// tests only the slab's voxels of it (clipRangeToExposed). The level must
// still equal one voxelized afresh there, to the bit: narrowing a range too
// far would lose voxels (this does not check that the range was narrowed;
// docs/clipmap.md has the time it saves).
TEST_F(Clipmap, OneAxisScrollMatchesAFreshLevelToTheBit) {
    const scene::Scene s = spreadScene();
    render::Renderer moving(context(), s, clipSettings(2));
    moving.renderFrame();
    glm::vec3 start(0.0f);
    for (const scene::Node& n : moving.scene().nodes)
        if (n.camera >= 0) start = n.translation;
    const glm::vec3 before = moving.levelVolumes()[0]->grid.origin;
    const glm::vec3 end = start + glm::vec3(0.8f, 0.0f, 0.0f);
    moveCamera(moving, end);
    moving.renderFrame();
    const glm::ivec3 step = glm::ivec3(glm::round((moving.levelVolumes()[0]->grid.origin - before) / kVoxel));
    ASSERT_NE(step.x, 0) << "level 0 did not scroll";
    ASSERT_EQ(step.y, 0);
    ASSERT_EQ(step.z, 0);
    render::Renderer fresh(context(), s, clipSettings(2));
    moveCamera(fresh, end);
    fresh.renderFrame();
    const StorageDiff d = compareStorage(*moving.levelVolumes()[0], *fresh.levelVolumes()[0]);
    std::printf("  level 0 scrolled %d voxels along x: %zu voxels, %zu sums differ\n", step.x,
                d.occupied, d.sumsDiffer);
    EXPECT_GT(d.occupied, 100u);
    EXPECT_EQ(d.occupancyDiffers, 0u);
    EXPECT_EQ(d.sumsDiffer, 0u);
}

INSTANTIATE_TEST_SUITE_P(Voxelizers, ClipmapScroll,
                         ::testing::Values(vxgi::VoxelizerKind::Compute, vxgi::VoxelizerKind::Geometry),
                         [](const ::testing::TestParamInfo<vxgi::VoxelizerKind>& i) {
                             return i.param == vxgi::VoxelizerKind::Compute ? std::string("Compute")
                                                                            : std::string("Geometry");
                         });

// Each level, with the toroidal roll undone on the CPU (grid voxel v lives in
// storage (v + wrap) mod N), equals a fitted grid on the level's window: no
// voxel lost or doubled at the window's faces, where the level borders the
// next; and its list names every occupied voxel once.
TEST_F(Clipmap, EveryLevelIsTheFittedGridOfItsWindowRolled) {
    const scene::Scene s = spreadScene();
    render::Renderer clip(context(), s, clipSettings(3));
    clip.renderFrame();
    moveCamera(clip, glm::vec3(0.7f, 0.3f, -0.3f));  // scrolled, so wrap != 0 on some axes
    clip.renderFrame();
    const std::vector<const vxgi::VoxelVolumes*> levels = clip.levelVolumes();
    ASSERT_EQ(levels.size(), 3u);
    for (size_t l = 0; l < levels.size(); ++l) {
        const vxgi::VoxelVolumes& c = *levels[l];
        render::RenderSettings fs = clipSettings(0);
        fs.hasVoxelBox = true;
        fs.voxelBoxMin = c.grid.origin;
        fs.voxelBoxMax = c.grid.origin + c.grid.voxelSize * float(kN);
        render::Renderer fitted(context(), s, fs);
        fitted.renderFrame();
        ASSERT_EQ(fitted.volumes()->grid.voxelSize, c.grid.voxelSize);
        const std::vector<uint32_t> ic = vxgi::readVoxelIndex(context(), c);
        const std::vector<uint32_t> iff = vxgi::readVoxelIndex(context(), *fitted.volumes());
        const vxgi::DenseAttributes dc = vxgi::readAttributes(context(), c);
        const vxgi::DenseAttributes df = vxgi::readAttributes(context(), *fitted.volumes());
        const int n = int(kN);
        size_t occupied = 0, differ = 0, sums = 0, atFaces = 0;
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const glm::ivec3 st = (glm::ivec3(x, y, z) + c.grid.wrap) % n;
                    const size_t of = size_t(x) + size_t(n) * (size_t(y) + size_t(n) * size_t(z));
                    const size_t oc = size_t(st.x) + size_t(n) * (size_t(st.y) + size_t(n) * size_t(st.z));
                    const bool a = sh::indexSlot(ic[oc]) != 0, b = sh::indexSlot(iff[of]) != 0;
                    occupied += a;
                    differ += a != b;
                    const bool face = x == 0 || y == 0 || z == 0 || x == n - 1 || y == n - 1 || z == n - 1;
                    atFaces += a && face;
                    for (uint32_t ch = 0; ch < sh::VOXEL_CHANNELS; ++ch) {
                        const float va = dc.at(st.x, st.y, st.z, ch), vb = df.at(x, y, z, ch);
                        sums += std::abs(va - vb) > 1e-4f * std::max(1.0f, std::abs(vb));
                    }
                }
        // The list: every live entry unique, one per occupied voxel.
        const std::vector<uint8_t> bytes = gpu::readbackBuffer(context(), c.list);
        sh::VoxelListHeader h;
        std::memcpy(&h, bytes.data(), sizeof(h));
        const uint32_t* entries = reinterpret_cast<const uint32_t*>(bytes.data() + sizeof(h));
        std::set<uint32_t> seen;
        size_t live = 0;
        for (uint32_t i = 0; i < h.counts.x; ++i)
            if (entries[i] != sh::VOXEL_LIST_FREE) {
                ++live;
                seen.insert(entries[i]);
            }
        std::printf("  level %zu: %zu voxels (%zu on the window's faces), wrap (%d, %d, %d), %zu list entries\n", l,
                    occupied, atFaces, c.grid.wrap.x, c.grid.wrap.y, c.grid.wrap.z, live);
        EXPECT_GT(occupied, 100u);
        EXPECT_EQ(differ, 0u);
        EXPECT_EQ(sums, 0u);
        EXPECT_EQ(live, occupied);
        EXPECT_EQ(seen.size(), live);
    }
}

// Each bounce over a clipmap records a few timing scopes per level: sixteen
// bounces over four levels must fit the renderer's timers (they did not
// when the timers were sized for a fitted grid: "more than 256 scopes").
TEST_F(Clipmap, ManyBouncesOverManyLevelsFitTheTimers) {
    render::RenderSettings rs = clipSettings(4);
    rs.voxelLight.bounces = 16;
    render::Renderer r(context(), spreadScene(), rs);
    render::FrameStats st;
    ASSERT_NO_THROW(st = r.renderFrame());
    EXPECT_EQ(st.bounces, 16u);
    EXPECT_FALSE(st.passes.empty());
}

// Levels 1.. light, filter and copy their voxels one after the other through
// one shared set of dense volumes (vxgi::DenseVolumes). With the direct light
// only, every level's slab of the radiance atlas equals the radiance volume of
// a fitted grid on its window, voxel for voxel: nothing of one level's light
// reaches another's slab, nothing is lost to the shared scratch's clears.
TEST_F(Clipmap, LevelsShareOneScratchYetEachSlabHoldsItsOwnLight) {
    const scene::Scene s = spreadScene();
    render::RenderSettings cs = clipSettings(3);
    cs.voxelLight.bounces = 0;
    cs.shadowFocus = false;  // the fitted grids below see only the scene-wide shadow map
    render::Renderer clip(context(), s, cs);
    clip.renderFrame();
    moveCamera(clip, glm::vec3(0.7f, 0.3f, -0.3f));
    clip.renderFrame();
    const std::vector<const vxgi::VoxelVolumes*> levels = clip.levelVolumes();
    ASSERT_EQ(levels.size(), 3u);
    EXPECT_EQ(levels[1]->dense(), levels[2]->dense());
    EXPECT_NE(levels[0]->dense(), levels[1]->dense());
    const std::vector<uint8_t> atlas =
        gpu::readbackImage(context(), clip.clipAtlases()->radiance, gpu::use::ComputeRead, 0);
    const int n = int(kN);
    auto rgba = [](const uint8_t* p) {
        uint16_t h[4];
        std::memcpy(h, p, sizeof(h));
        return glm::vec4(glm::unpackHalf1x16(h[0]), glm::unpackHalf1x16(h[1]), glm::unpackHalf1x16(h[2]),
                         glm::unpackHalf1x16(h[3]));
    };
    for (size_t l = 0; l < levels.size(); ++l) {
        const vxgi::VoxelVolumes& c = *levels[l];
        render::RenderSettings fs = clipSettings(0);
        fs.voxelLight.bounces = 0;
        fs.hasVoxelBox = true;
        fs.voxelBoxMin = c.grid.origin;
        fs.voxelBoxMax = c.grid.origin + c.grid.voxelSize * float(kN);
        render::Renderer fitted(context(), s, fs);
        fitted.renderFrame();
        const std::vector<uint8_t> ref =
            gpu::readbackImage(context(), fitted.volumes()->radiance, gpu::use::ComputeRead, 0);
        size_t lit = 0, differ = 0;
        double largest = 0.0;
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const size_t o = size_t(x) + size_t(n) * (size_t(y) + size_t(n) * size_t(z));
                    const glm::vec4 a = rgba(atlas.data() + 8 * (o + l * size_t(n) * n * n));
                    const glm::vec4 b = rgba(ref.data() + 8 * o);
                    lit += b.r + b.g + b.b > 0.0f;
                    const float d = glm::length(a - b) / std::max(1e-3f, glm::length(b));
                    largest = std::max(largest, double(d));
                    differ += d > 1e-3f;
                }
        std::printf("  level %zu: %zu lit voxels, %zu differ from the fitted grid's (largest %.1e)\n", l, lit, differ,
                    largest);
        EXPECT_GT(lit, 100u);
        EXPECT_EQ(differ, 0u);
    }
}

// After a frame, level 1's directional mip 0 in the atlas, where level 0's
// window covers it, holds level 0's mip 1 (the same cells, filtered from
// level 0's finer voxels), texel for texel; elsewhere its own.
TEST_F(Clipmap, CoarseLevelCarriesTheFinerLevelsFilteredLight) {
    render::Renderer r(context(), spreadScene(), clipSettings(2));
    r.renderFrame();
    const vxgi::ClipAtlases* atlases = r.clipAtlases();
    ASSERT_NE(atlases, nullptr);
    const std::vector<const vxgi::VoxelVolumes*> levels = r.levelVolumes();
    const std::vector<uint8_t> mip0 = gpu::readbackImage(context(), atlases->directional, gpu::use::ComputeRead, 0);
    const std::vector<uint8_t> mip1 = gpu::readbackImage(context(), atlases->directional, gpu::use::ComputeRead, 1);
    // Level 0's window corner in cells (2 voxels) of level 1's mip 0.
    const glm::ivec3 at =
        glm::ivec3(glm::round((levels[0]->grid.origin - levels[1]->grid.origin) / levels[1]->grid.voxelSize)) / 2;
    const int side0 = int(kN / 2), side1 = int(kN / 4);
    auto texel = [](const std::vector<uint8_t>& img, int w, int h, glm::ivec3 p) {
        uint64_t v;
        std::memcpy(&v, img.data() + 8 * ((size_t(p.z) * h + p.y) * w + p.x), 8);
        return v;
    };
    size_t same = 0, lit = 0;
    const int w0 = 6 * side0, w1 = 6 * side1;
    for (int d = 0; d < 6; ++d)
        for (int z = 0; z < side1; ++z)
            for (int y = 0; y < side1; ++y)
                for (int x = 0; x < side1; ++x) {
                    const uint64_t fine = texel(mip1, w1, side1, glm::ivec3(d * side1 + x, y, z));
                    const uint64_t coarse =
                        texel(mip0, w0, side0, glm::ivec3(d * side0 + at.x + x, at.y + y, side0 + at.z + z));
                    same += fine == coarse;
                    lit += fine != 0;
                }
    std::printf("  level 0's window at cell (%d, %d, %d) of level 1's mip 0: %zu of %d texels equal, %zu not empty\n",
                at.x, at.y, at.z, same, 6 * side1 * side1 * side1, lit);
    EXPECT_EQ(same, size_t(6 * side1 * side1 * side1));
    EXPECT_GT(lit, 100u);
}

double luminance(const float* c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

// The largest change of the indirect term between neighbouring pixels of the
// image's middle rows, relative to the mean there.
double largestStep(const image::ImageRGBA32F& img) {
    double sum = 0.0, worst = 0.0;
    size_t count = 0;
    for (uint32_t y = img.height / 4; y < 3 * img.height / 4; ++y)
        for (uint32_t x = 0; x < img.width; ++x) {
            const float* c = img.rgba.data() + 4 * (size_t(y) * img.width + x);
            sum += luminance(c);
            ++count;
            if (x > 0) worst = std::max(worst, std::abs(luminance(c) - luminance(c - 4)));
        }
    return worst / (sum / double(count));
}

// A small lit room seen from above with a wide lens: it lies inside level 1's
// window (2 m, voxels of 1/16 m) and crosses level 0's faces (1 m, 1/32 m) at
// x = +-0.5 m, so the rows of the indirect term go from level 0 through the
// blend band into level 1. The largest step between neighbouring pixels stays
// near what a fitted grid at level 1's voxel (which has no border) shows.
TEST_F(Clipmap, IndirectLightIsContinuousAcrossALevelBorder) {
    scene::Scene s;
    const int grey = addMaterial(s, glm::vec3(0.7f));
    const int wall = addMaterial(s, glm::vec3(0.9f, 0.5f, 0.3f));
    const float q = glm::half_pi<float>();
    addQuad(s, grey, glm::vec3(0.0f, 0.0f, 0.0f), 0.7f);
    addQuad(s, wall, glm::vec3(0.0f, 0.0f, -0.6f), 0.7f, glm::angleAxis(q, glm::vec3(1, 0, 0)));
    addTopDownCamera(s, 0.25f, glm::radians(140.0f));
    addSun(s, glm::vec3(0.2f, -1.0f, -0.6f));
    render::RenderSettings rs = clipSettings(2);
    rs.clipmap.voxelSize = kVoxel / 2.0f;
    rs.width = rs.height = 64;
    rs.outputTerm = sh::TERM_INDIRECT;
    const image::ImageRGBA32F clip = render(s, rs);
    render::RenderSettings fs = rs;
    fs.clipmap.levels = 0;
    fs.hasVoxelBox = true;
    fs.voxelBoxMin = glm::vec3(-1.0f);
    fs.voxelBoxMax = glm::vec3(1.0f);
    fs.voxels = 32;  // 1/16 m voxels: level 1's
    // The clipmap's gather traces cones (rays need one grid), so the fitted
    // grid's does too: the filtered rays' steps are far smaller (0.038).
    fs.gather.trace = render::GatherTrace::Cones;
    const image::ImageRGBA32F fitted = render(s, fs);
    if (const char* dump = std::getenv("DVSGI_CLIPMAP_DUMP")) {
        image::writeExr(std::string(dump) + "-clip.exr", clip);
        image::writeExr(std::string(dump) + "-fitted.exr", fitted);
    }
    const double stepClip = largestStep(clip), stepFitted = largestStep(fitted);
    std::printf("  largest step between neighbouring pixels / mean: clipmap %.3f, fitted grid %.3f\n", stepClip,
                stepFitted);
    EXPECT_LE(stepClip, 1.5 * stepFitted);
}

double meanIndirect(const render::Renderer& r) {
    const image::ImageRGBA32F img = r.readTerm(sh::TERM_INDIRECT);
    double sum = 0.0;
    for (size_t p = 0; p < img.pixelCount(); ++p) sum += luminance(img.rgba.data() + 4 * p);
    return sum / double(img.pixelCount());
}

// A room open at the top, seen from 2.2 m above it, outside the scene (as a
// Cornell box's camera stands in front of its open side). With the default
// level-0 voxel the coarsest window must still hold it, and level 0, around
// the camera, holds nothing; a converging render must then judge the change
// over every level (it stopped after one bounce when it counted level 0's
// alone) and end where a fixed run of many bounces does.
TEST_F(Clipmap, ConvergesWhenTheFinestLevelHoldsNothing) {
    scene::Scene s;
    const int grey = addMaterial(s, glm::vec3(0.8f));
    const float q = glm::half_pi<float>();
    addQuad(s, grey, glm::vec3(0.0f), 0.5f);
    addQuad(s, grey, glm::vec3(0.0f, 0.5f, -0.5f), 0.5f, glm::angleAxis(q, glm::vec3(1, 0, 0)));
    addQuad(s, grey, glm::vec3(-0.5f, 0.5f, 0.0f), 0.5f, glm::angleAxis(-q, glm::vec3(0, 0, 1)));
    addQuad(s, grey, glm::vec3(0.5f, 0.5f, 0.0f), 0.5f, glm::angleAxis(q, glm::vec3(0, 0, 1)));
    addTopDownCamera(s, 2.2f, glm::radians(35.0f));
    addSun(s, glm::vec3(0.4f, -1.0f, -0.3f));
    render::RenderSettings rs = clipSettings(3);
    rs.clipmap.voxelSize = 0.0f;
    rs.voxelLight.bounceMode = vxgi::BounceMode::Converge;
    render::Renderer converging(context(), s, rs);
    const render::FrameStats c = converging.renderFrame();
    EXPECT_EQ(listHeader(*converging.levelVolumes()[0]).counts.x, 0u) << "level 0 was to hold no voxel";
    EXPECT_GT(listHeader(*converging.levelVolumes()[2]).counts.x, 100u);
    render::RenderSettings fs = rs;
    fs.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    fs.voxelLight.bounces = 16;
    render::Renderer fixed(context(), s, fs);
    fixed.renderFrame();
    const double a = meanIndirect(converging), b = meanIndirect(fixed);
    std::printf("  converged after %u bounces (change %.2e): mean indirect %.5f; 16 bounces: %.5f (ratio %.4f)\n",
                c.bounces, c.bounceChange, a, b, a / b);
    EXPECT_TRUE(c.converged);
    EXPECT_GT(c.bounces, 2u);
    EXPECT_GT(b, 0.0);
    EXPECT_NEAR(a / b, 1.0, 0.02);
    // A given level-0 voxel whose coarsest window misses the room: one warning says so.
    render::RenderSettings small = rs;
    small.clipmap.voxelSize = 0.01f;
    const render::Renderer cut(context(), s, small);
    const auto& w = cut.warnings();
    EXPECT_EQ(std::count_if(w.begin(), w.end(),
                            [](const std::string& m) { return m.find("leaves part of the scene out") != m.npos; }),
              1);
}

// Shadow cones (--shadows cone) trace the levels too: with one level, the
// direct light equals a fitted grid's on the level's window (same voxels, the
// atlas sampled as the grid's own volumes are).
TEST_F(Clipmap, ShadowConesTraceTheLevels) {
    render::RenderSettings rs = clipSettings(1);
    rs.shadowCones.enabled = true;
    render::Renderer clip(context(), spreadScene(false), rs);
    clip.renderFrame();
    const vxgi::GridSpec g = clip.levelVolumes()[0]->grid;
    render::RenderSettings fs = rs;
    fs.clipmap.levels = 0;
    fs.hasVoxelBox = true;
    fs.voxelBoxMin = g.origin;
    fs.voxelBoxMax = g.origin + g.voxelSize * float(kN);
    render::Renderer fitted(context(), spreadScene(false), fs);
    fitted.renderFrame();
    const image::ImageRGBA32F a = clip.readTerm(sh::TERM_DIRECT), b = fitted.readTerm(sh::TERM_DIRECT);
    double diff = 0.0, ref = 0.0;
    for (size_t i = 0; i < a.rgba.size(); ++i) {
        diff += double(a.rgba[i] - b.rgba[i]) * double(a.rgba[i] - b.rgba[i]);
        ref += double(b.rgba[i]) * double(b.rgba[i]);
    }
    const double rel = std::sqrt(diff / ref);
    std::printf("  direct light with shadow cones, one level against the fitted grid of its window: relative RMSE %.2e\n",
                rel);
    EXPECT_GT(ref, 0.0);
    EXPECT_LT(rel, 1e-3);
}

// Switching the only light off with the clipmap (feedback bounces): the
// indirect light falls below 1 % of its lit value within kFrames frames.
TEST_F(Clipmap, SwitchedOffLightLeavesNoGhost) {
    constexpr int kFrames = 10;
    render::RenderSettings rs = clipSettings(2);
    rs.voxelLight.bounceMode = vxgi::BounceMode::Converge;
    render::Renderer r(context(), spreadScene(false), rs);
    for (int f = 0; f < 4; ++f) r.renderFrame();
    auto indirect = [&] {
        const image::ImageRGBA32F img = r.readTerm(sh::TERM_INDIRECT);
        double sum = 0.0;
        for (size_t p = 0; p < img.pixelCount(); ++p) sum += luminance(img.rgba.data() + 4 * p);
        return sum / double(img.pixelCount());
    };
    const double lit = indirect();
    ASSERT_GT(lit, 0.0);
    r.scene().lights[0].intensity = 0.0f;
    r.sceneChanged();
    int frames = 0;
    double left = lit;
    while (left >= 0.01 * lit && frames < 3 * kFrames) {
        r.renderFrame();
        ++frames;
        left = indirect();
    }
    std::printf("  indirect %.5f lit, below 1 %% after %d frame(s) off (%.2e left)\n", lit, frames, left);
    EXPECT_LE(frames, kFrames);
}

}  // namespace
}  // namespace dvsgi::test
