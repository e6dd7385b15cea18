// Anisotropic filtering (AnisoFilterPass): the six directional volumes and
// their mips against a host implementation of the compositing rule.
#include <cmath>
#include <cstdio>
#include <random>

#include <glm/gtc/packing.hpp>

#include "gpu/context.h"
#include "gpu/transfer.h"
#include "gpu_fixture.h"
#include "light_helpers.h"
#include "shared/aniso_filter_pass.h"
#include "vxgi/aniso_filter.h"
#include "vxgi/voxel_storage_io.h"

namespace dvsgi::test {
namespace {

vxgi::GridSpec grid(uint32_t n) {
    vxgi::GridSpec g;
    g.origin = glm::vec3(-1.0f);
    g.voxelSize = 2.0f / float(n);
    g.n = n;
    return g;
}

Rgba16Volume randomRadiance(uint32_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> rgb(0.0f, 8.0f), u01(0.0f, 1.0f);
    std::uniform_int_distribution<int> kind(0, 2);
    Rgba16Volume v;
    v.n = n;
    v.texels.resize(size_t(n) * n * n);
    for (glm::vec4& t : v.texels) {
        const int k = kind(rng);
        const float a = k == 0 ? 0.0f : (k == 1 ? u01(rng) : 1.0f);
        const glm::vec4 c = toHalf(glm::vec4(rgb(rng), rgb(rng), rgb(rng), a));
        // Premultiplied: an empty voxel (opacity 0 once in fp16) holds no light.
        t = c.a > 0.0f ? c : glm::vec4(0.0f);
    }
    return v;
}

Rgba16Volume emptyRadiance(uint32_t n) {
    Rgba16Volume v;
    v.n = n;
    v.texels.assign(size_t(n) * n * n, glm::vec4(0.0f));
    return v;
}

// Volumes with a slot for every voxel, so any radiance can be listed.
vxgi::VoxelVolumes volumesFor(uint32_t n) { return vxgi::VoxelVolumes(context(), grid(n), n * n * n); }

// A voxel's mean normal, as voxelization accumulates it (one fragment).
struct VoxelNormal {
    glm::ivec3 voxel;
    glm::vec3 n;
};

// What voxelization leaves for `radiance`: every voxel with opacity occupied
// and in the list (the filter's base level runs over it), each one-sided in
// its direct light's side code, so the two-sided pass leaves it alone. Their
// normals cancel (shown every way) but those `normals` gives.
void uploadOccupancy(const vxgi::VoxelVolumes& volumes, const Rgba16Volume& radiance,
                     const std::vector<VoxelNormal>& normals = {}) {
    vxgi::DenseAttributes a(radiance.n);
    for (int z = 0; z < int(radiance.n); ++z)
        for (int y = 0; y < int(radiance.n); ++y)
            for (int x = 0; x < int(radiance.n); ++x)
                if (radiance.at(x, y, z).a > 0.0f) a.at(x, y, z, shader::CH_COUNT) = 1.0f;
    for (const VoxelNormal& v : normals)
        for (int axis = 0; axis < 3; ++axis) {
            const float c = v.n[axis];
            a.at(v.voxel.x, v.voxel.y, v.voxel.z, shader::CH_NORMAL_POS_X + 2 * axis + (c < 0.0f ? 1 : 0)) = c * c;
        }
    vxgi::uploadAttributes(context(), volumes, a);
    const std::vector<uint64_t> oneSided(volumes.slots, glm::packHalf4x16(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)));
    gpu::uploadImage(context(), volumes.direct, oneSided.data(), oneSided.size() * sizeof(uint64_t),
                     gpu::use::ComputeReadWrite);
}

void filter(const vxgi::VoxelVolumes& volumes, const Rgba16Volume& radiance,
            const std::vector<VoxelNormal>& normals = {}, bool backsDark = true) {
    uploadRgba16(volumes.radiance, radiance);
    uploadOccupancy(volumes, radiance, normals);
    const vxgi::AnisoFilterPass pass(context());
    gpu::Tracker tracker = volumeTracker(volumes);
    context().submitAndWait([&](VkCommandBuffer cmd) { pass.record(cmd, tracker, volumes, backsDark, nullptr, "test filter"); });
}

// The GPU computes in fp32 from fp16 inputs and stores fp16, which on lavapipe
// can be off by up to one fp16 ulp (2^-10 relative).
int compareLevel(const Rgba16Volume& got, const Rgba16Volume& want, int dir, uint32_t level, double& worst) {
    int failed = 0;
    EXPECT_EQ(got.n, want.n);
    for (int z = 0; z < int(want.n); ++z)
        for (int y = 0; y < int(want.n); ++y)
            for (int x = 0; x < int(want.n); ++x)
                for (int c = 0; c < 4; ++c) {
                    const float g = got.at(x, y, z)[c], w = want.at(x, y, z)[c];
                    const float err = std::abs(g - w);
                    if (w > 1e-3f) worst = std::max(worst, double(err / w));
                    // One fp16 rounding: up to 9.8e-4 (measured worst 9.73e-4).
                    if (err > 1.5e-3f * std::abs(w) + 1e-6f && failed++ < 3)
                        ADD_FAILURE() << "direction " << dir << " level " << level << " voxel (" << x << "," << y
                                      << "," << z << ") channel " << c << ": GPU " << g << ", host " << w;
                }
    return failed;
}

class AnisoFilter : public GpuTest {};

// Filters `radiance` (32^3) and checks every direction and level against the host.
void expectEveryLevelMatchesTheRule(const Rgba16Volume& radiance) {
    constexpr uint32_t kN = 32;
    const vxgi::VoxelVolumes volumes = volumesFor(kN);
    ASSERT_EQ(volumes.directionalMips, 5u);  // 16^3 .. 1^3
    filter(volumes, radiance);
    int failed = 0;
    for (int dir = 0; dir < 6; ++dir) {
        double worstGpuChain = 0.0, worstHostChain = 0.0;
        Rgba16Volume previousGpu = radiance, hostChain = radiance;
        for (uint32_t level = 0; level < volumes.directionalMips; ++level) {
            const Rgba16Volume got = readDirectional(volumes, uint32_t(dir), level);
            ASSERT_EQ(got.n, (kN / 2) >> level);
            // Level by level from the GPU's own previous level: isolates each dispatch.
            failed += compareLevel(got, filterDirectionalLevel(previousGpu, dir), dir, level, worstGpuChain);
            // The whole chain on the host with fp16 rounding after each level:
            // catches a level reading the wrong source.
            Rgba16Volume next = filterDirectionalLevel(hostChain, dir);
            for (glm::vec4& t : next.texels) t = toHalf(t);
            hostChain = next;
            for (int z = 0; z < int(got.n); ++z)
                for (int y = 0; y < int(got.n); ++y)
                    for (int x = 0; x < int(got.n); ++x)
                        for (int c = 0; c < 4; ++c) {
                            const float w = hostChain.at(x, y, z)[c];
                            if (w > 1e-3f)
                                worstHostChain = std::max(worstHostChain, double(std::abs(got.at(x, y, z)[c] - w) / w));
                        }
            previousGpu = got;
        }
        std::printf("  direction %d: worst relative error %.2e per level, %.2e over the host chain\n", dir,
                    worstGpuChain, worstHostChain);
        // fp16 errors compound over at most 5 levels of averaging: measured
        // worst 1.94e-3 on lavapipe, bound 1.5x.
        EXPECT_LT(worstHostChain, 3e-3) << "direction " << dir;
    }
    EXPECT_EQ(failed, 0);
}

TEST_F(AnisoFilter, EveryDirectionAndLevelMatchesTheRule) { expectEveryLevelMatchesTheRule(randomRadiance(32, 3)); }

// A sparse grid, as scenes are: most 2^3 blocks are all zero. The base level
// composites only the cells its list names and leaves the rest cleared, and
// the upper levels take the shader's early exit; both must give what the rule
// gives, next to occupied cells.
TEST_F(AnisoFilter, SparseGridMatchesTheRuleInEmptyAndOccupiedCells) {
    const Rgba16Volume dense = randomRadiance(32, 5);
    Rgba16Volume sparse = dense;
    int kept = 0;
    for (int z = 0; z < 32; ++z)
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) {
                const bool wall = x == 9 || (y == 20 && z < 16);  // a plane and a half-plane
                if (!wall) sparse.at(x, y, z) = glm::vec4(0.0f);
                kept += wall;
            }
    ASSERT_GT(kept, 32 * 32);
    expectEveryLevelMatchesTheRule(sparse);
}

// The base level runs only over the listed voxels: cells that held voxels in
// the last filtering and hold none now must come out empty, not stale.
TEST_F(AnisoFilter, FilteringAgainEmptiesCellsThatLostTheirVoxels) {
    constexpr uint32_t kN = 16;
    const vxgi::VoxelVolumes volumes = volumesFor(kN);
    filter(volumes, randomRadiance(kN, 7));
    Rgba16Volume one = emptyRadiance(kN);
    one.at(5, 6, 7) = glm::vec4(0.25f, 0.5f, 0.75f, 1.0f);
    filter(volumes, one);
    int nonEmpty = 0;
    for (int dir = 0; dir < 6; ++dir) {
        const Rgba16Volume got = readDirectional(volumes, uint32_t(dir), 0);
        for (int z = 0; z < int(got.n); ++z)
            for (int y = 0; y < int(got.n); ++y)
                for (int x = 0; x < int(got.n); ++x)
                    if (got.at(x, y, z) != glm::vec4(0.0f)) {
                        ++nonEmpty;
                        EXPECT_EQ(glm::ivec3(x, y, z), glm::ivec3(2, 3, 3)) << "direction " << dir;
                    }
    }
    EXPECT_EQ(nonEmpty, 6);  // the one cell, in each direction
}

// The direction convention, by hand: two voxels side by side along x, a half-
// transparent red one at x = 0 and an opaque green one at x = 1.
TEST_F(AnisoFilter, TravelDirectionDecidesWhichChildIsInFront) {
    constexpr uint32_t kN = 16;
    const vxgi::VoxelVolumes volumes = volumesFor(kN);
    Rgba16Volume radiance = emptyRadiance(kN);
    radiance.at(0, 0, 0) = glm::vec4(0.5f, 0.0f, 0.0f, 0.5f);  // premultiplied
    radiance.at(1, 0, 0) = glm::vec4(0.0f, 1.0f, 0.0f, 1.0f);
    filter(volumes, radiance);
    auto level0 = [&](int dir) { return readDirectional(volumes, uint32_t(dir), 0).at(0, 0, 0); };
    auto expectVec = [](glm::vec4 got, glm::vec4 want, const char* what) {
        for (int c = 0; c < 4; ++c) EXPECT_FLOAT_EQ(got[c], want[c]) << what << " channel " << c;
    };
    // Travelling +X the ray meets red first and sees green through it; one of
    // the four columns is filled.
    expectVec(level0(1), glm::vec4(0.5f, 0.5f, 0.0f, 1.0f) * 0.25f, "+X");
    // Travelling -X the opaque green hides red.
    expectVec(level0(0), glm::vec4(0.0f, 1.0f, 0.0f, 1.0f) * 0.25f, "-X");
    // Along y and z each voxel is alone in its column (two of four filled).
    for (int dir = 2; dir < 6; ++dir)
        expectVec(level0(dir), glm::vec4(0.5f, 1.0f, 0.0f, 1.5f) * 0.25f, "y/z");
    // Level 1 of +X reads level 0 of +X (one filled column of four, in front).
    const glm::vec4 l1 = readDirectional(volumes, 1, 1).at(0, 0, 0);
    expectVec(l1, glm::vec4(0.5f, 0.5f, 0.0f, 1.0f) * 0.0625f, "+X level 1");
}

// A one-sided voxel seen from behind blocks but shows no light: a wall in two
// voxel layers, its dark face's voxel at x = 0 (normal -x) and its lit face's
// at x = 1 (normal +x), each alone in its column along y and z, and a tilted
// voxel at x = 2 whose normal is half way through the fade for rays
// travelling +x (shader::VOXEL_BACK_FADE_*).
TEST_F(AnisoFilter, AVoxelSeenFromBehindBlocksButShowsNoLight) {
    constexpr uint32_t kN = 16;
    const vxgi::VoxelVolumes volumes = volumesFor(kN);
    Rgba16Volume radiance = emptyRadiance(kN);
    radiance.at(0, 0, 0) = glm::vec4(0.125f, 0.0f, 0.0f, 1.0f);
    radiance.at(1, 0, 0) = glm::vec4(0.0f, 1.0f, 0.0f, 1.0f);
    radiance.at(2, 0, 0) = glm::vec4(0.0f, 0.0f, 1.0f, 1.0f);
    const float half = 0.5f * (shader::VOXEL_BACK_FADE_START + shader::VOXEL_BACK_FADE_END);
    const glm::vec3 tilted(half, std::sqrt(1.0f - half * half), 0.0f);
    filter(volumes, radiance, {{{0, 0, 0}, {-1, 0, 0}}, {{1, 0, 0}, {1, 0, 0}}, {{2, 0, 0}, tilted}});
    auto level0 = [&](int dir, int cell) { return readDirectional(volumes, uint32_t(dir), 0).at(cell, 0, 0); };
    auto expectVec = [](glm::vec4 got, glm::vec4 want, const char* what) {
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], 1e-3f) << what << " channel " << c;
    };
    // Travelling +X the ray meets the dark face; the lit one behind it is
    // hidden whichever way it shows.
    expectVec(level0(1, 0), glm::vec4(0.125f, 0.0f, 0.0f, 1.0f) * 0.25f, "+X, the wall");
    // Travelling -X the ray meets the lit face.
    expectVec(level0(0, 0), glm::vec4(0.0f, 1.0f, 0.0f, 1.0f) * 0.25f, "-X, the wall");
    // Along y and z both faces are seen edge on and show their light.
    for (int dir = 2; dir < 6; ++dir) expectVec(level0(dir, 0), glm::vec4(0.125f, 1.0f, 0.0f, 2.0f) * 0.25f, "y/z");
    // The tilted voxel: half its light travelling +X, all of it travelling -X
    // and -Y, none travelling +Y (dot(n, +y) = 0.97).
    expectVec(level0(1, 1), glm::vec4(0.0f, 0.0f, 0.5f, 1.0f) * 0.25f, "+X, tilted");
    expectVec(level0(0, 1), glm::vec4(0.0f, 0.0f, 1.0f, 1.0f) * 0.25f, "-X, tilted");
    expectVec(level0(2, 1), glm::vec4(0.0f, 0.0f, 1.0f, 1.0f) * 0.25f, "-Y, tilted");
    expectVec(level0(3, 1), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) * 0.25f, "+Y, tilted");
    // --voxel-backs-dark off (the paper's filter): every voxel shows its light every way.
    filter(volumes, radiance, {{{0, 0, 0}, {-1, 0, 0}}, {{1, 0, 0}, {1, 0, 0}}, {{2, 0, 0}, tilted}}, false);
    expectVec(level0(3, 1), glm::vec4(0.0f, 0.0f, 1.0f, 1.0f) * 0.25f, "+Y, tilted, backs lit");
    expectVec(level0(1, 1), glm::vec4(0.0f, 0.0f, 1.0f, 1.0f) * 0.25f, "+X, tilted, backs lit");
}

}  // namespace
}  // namespace dvsgi::test
