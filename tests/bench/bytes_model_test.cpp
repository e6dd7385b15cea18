// The bench's bytes model (src/bench/bytes_model.h) against a case computed
// by hand, and against the volumes' own sizes.
#include <gtest/gtest.h>

#include "bench/bytes_model.h"
#include "vxgi/volumes.h"

namespace dvsgi::bench {
namespace {

// 32^3 with 16384 voxel slots, 1000 occupied voxels of which 100 dynamic, 160x90 without
// supersampling or reduced tracing, one 512^2 shadow view, 1000 static and
// 500 dynamic geometry bytes, one bounce.
ModelInputs handCase() {
    ModelInputs in;
    in.voxels = 32;
    in.slots = 16384;
    in.occupiedVoxels = 1000;
    in.dynamicVoxels = 100;
    in.outputWidth = in.internalWidth = in.traceWidth = 160;
    in.outputHeight = in.internalHeight = in.traceHeight = 90;
    in.shadowMapSize = 512;
    in.shadowViews = 1;
    in.staticGeometryBytes = 1000;
    in.dynamicGeometryBytes = 500;
    in.bounces = 1;
    return in;
}

void expectPass(const std::vector<PassTraffic>& passes, const char* name, uint64_t read, uint64_t written) {
    const PassTraffic* p = findPass(passes, name);
    ASSERT_NE(p, nullptr) << name;
    EXPECT_EQ(p->readBytes, read) << name;
    EXPECT_EQ(p->writtenBytes, written) << name;
    EXPECT_EQ(p->bytes(), read + written) << name;
}

TEST(BytesModel, HandComputedCase) {
    const std::vector<PassTraffic> p = passTraffic(handCase());
    // 32^3 = 32768 voxels with a 4-byte index and RGBA16F radiance each;
    // 16384 slots with 64 attribute bytes (16 x R32F), 4 of extents and RGBA16F direct light each.
    expectPass(p, "clear all voxels", 0, 32768 * (4 + 8) + 16384 * (64 + 4 + 8));
    // Re-voxelizing: the 1000 listed voxels' entries read; their attributes,
    // extents, direct light, radiance and index zeroed.
    expectPass(p, "clear occupied voxels", 1000 * 4, 1000 * (64 + 4 + 8 + 8 + 4));
    // 900 static voxels; 100 dynamic ones; attributes, extents, index and a 4-byte list entry each.
    expectPass(p, "voxelize static", 1000, 900 * (64 + 4 + 4 + 4));
    // Attributes, extents, direct light, radiance and index of last frame's dynamic voxels.
    expectPass(p, "clear dynamic voxels", 100 * 4, 100 * (64 + 4 + 8 + 8 + 4));
    expectPass(p, "voxelize dynamic", 500 + 100 * 4, 100 * (64 + 4 + 4 + 4));
    // A D32 depth and an RG16F caster gradient per texel.
    expectPass(p, "shadow maps", 1500, 512 * 512 * (4 + 4));
    // List entry, attributes and extents read; direct light into the slot and the radiance volume.
    expectPass(p, "voxel direct light", 1000 * (4 + 64 + 4), 1000 * 16);
    // Directional levels 16^3 .. 1^3 (5 levels), RGBA16F, 6 volumes: reads
    // the 1000 listed voxels' entries and radiance + levels 16^3..2^3, writes
    // all five levels.
    const uint64_t filterRead = 1000 * (4 + 8) + 6 * 8 * (4096 + 512 + 64 + 8);
    const uint64_t filterWritten = 6 * 8 * (4096 + 512 + 64 + 8 + 1);
    expectPass(p, "voxel filtering", filterRead, filterWritten);
    expectPass(p, "voxel bounce", 1000 * (4 + 40 + 8), 1000 * 8);
    expectPass(p, "voxel filtering (bounce)", filterRead, filterWritten);
    // 14400 pixels: G-buffer 3 x RGBA16F + D32 = 28 bytes.
    expectPass(p, "gbuffer", 1500, 14400 * 28);
    expectPass(p, "direct lighting", 14400 * 28, 14400 * (16 + 2));
    expectPass(p, "cone tracing", 14400 * 20, 14400 * 16);
    expectPass(p, "composite", 14400 * 32, 14400 * 16);
    EXPECT_EQ(findPass(p, "upsample"), nullptr) << "no upsample at full trace size";
    EXPECT_EQ(p.size(), 14u);
}

TEST(BytesModel, BouncesScaleTheBouncePassesOnly) {
    ModelInputs in = handCase();
    in.bounces = 3;
    const std::vector<PassTraffic> one = passTraffic(handCase()), three = passTraffic(in);
    for (const char* name : {"voxel bounce", "voxel filtering (bounce)"})
        EXPECT_EQ(findPass(three, name)->bytes(), 3 * findPass(one, name)->bytes()) << name;
    EXPECT_EQ(findPass(three, "voxel filtering")->bytes(), findPass(one, "voxel filtering")->bytes());
}

TEST(BytesModel, ReducedTraceAddsTheUpsample) {
    ModelInputs in = handCase();
    in.traceWidth = 80;
    in.traceHeight = 45;
    const std::vector<PassTraffic> p = passTraffic(in);
    expectPass(p, "cone tracing", 3600 * 20, 3600 * 16);
    // Trace-size terms + full-size normal and depth in, full-size terms out.
    expectPass(p, "upsample", 3600 * 16 + 14400 * 12, 14400 * 16);
}

TEST(BytesModel, TemporalIndirectRunsOnlyWhenOnAndReadsItsHistory) {
    ModelInputs in = handCase();
    EXPECT_EQ(findPass(passTraffic(in), "temporal indirect"), nullptr);
    in.temporal = true;
    // 160x90 pixels: depth 4, normal 8, indirect 8 and history 16 + 8 bytes in;
    // indirect 8 and history 16 + 8 out.
    expectPass(passTraffic(in), "temporal indirect", 14400 * (4 + 8 + 8 + 24), 14400 * (8 + 24));
    in.voxels = 0;
    EXPECT_EQ(findPass(passTraffic(in), "temporal indirect"), nullptr);
}

// Issue #14's storage goal: at most 24 bytes per grid voxel at 256^3, mips
// included, with the default slots and the voxel bounce's rays (the default;
// their per-slot result counted).
TEST(BytesModel, TurnedConesAddTheirResolve) {
    ModelInputs in = handCase();
    EXPECT_EQ(findPass(passTraffic(in), "cone set resolve"), nullptr);
    in.resolvePasses = 1;
    // 160x90 trace pixels: the turned term (8), normal (8) and depth (4) in, the resolved term (8) out.
    expectPass(passTraffic(in), "cone set resolve", 14400 * (8 + 8 + 4), 14400 * 8);
    // The rays' filter: three passes, each the same traffic.
    in.resolvePasses = 3;
    expectPass(passTraffic(in), "cone set resolve", 3 * 14400 * (8 + 8 + 4), 3 * 14400 * 8);
}

TEST(BytesModel, DarkBacksReadTheVoxelsNormalsInTheFilter) {
    ModelInputs in = handCase();
    const PassTraffic lit = *findPass(passTraffic(in), "voxel filtering (bounce)");
    in.backsDark = true;
    const PassTraffic dark = *findPass(passTraffic(in), "voxel filtering (bounce)");
    // Per listed voxel: its index word and six normal weights.
    EXPECT_EQ(dark.readBytes - lit.readBytes, in.occupiedVoxels * (4 + 24));
    EXPECT_EQ(dark.writtenBytes, lit.writtenBytes);
}

TEST(BytesModel, RaysLeaveOutTheFilteringBeforeTheirBounce) {
    ModelInputs in = handCase();
    in.bounceRays = true;
    EXPECT_EQ(findPass(passTraffic(in), "voxel filtering"), nullptr);
    EXPECT_NE(findPass(passTraffic(in), "voxel filtering (bounce)"), nullptr);
    // The rays' dispatches on top of the cones' bounce: a second read of the
    // list and attributes, the per-slot result, the normals and the
    // occupancy bits (4 levels of 32^3 over 2^3 .. 16^3 cells: 4096, 512, 64
    // and 8 bits in 128 + 16 + 2 + 1 words, cleared; one word per level per voxel).
    const uint64_t occupied = in.occupiedVoxels;
    ModelInputs cones = in;
    cones.bounceRays = false;
    const PassTraffic rays = *findPass(passTraffic(in), "voxel bounce"), cone = *findPass(passTraffic(cones), "voxel bounce");
    EXPECT_EQ(rays.readBytes - cone.readBytes, occupied * (2 * 4 + 40 + 8 + 28 + 16));
    EXPECT_EQ(rays.writtenBytes - cone.writtenBytes, occupied * (8 + 4 + 16) + 147 * 4);
    in.bounces = 0;
    EXPECT_NE(findPass(passTraffic(in), "voxel filtering"), nullptr);
}

TEST(BytesModel, DefaultVoxelStorageAt256IsAtMost24BytesPerGridVoxel) {
    const uint32_t slots = vxgi::defaultSlotCapacity(256);
    const double rays = vxgi::voxelBytesPerGridVoxel(256, slots, true);
    const double cones = vxgi::voxelBytesPerGridVoxel(256, slots, false);
    EXPECT_LE(rays, 24.0);
    // The rays' light (8 bytes) and their voxels' packed normals (4) per
    // slot, and the occupancy bits of 128^3 .. 16^3 cells (74880 words).
    EXPECT_NEAR(rays - cones, (double(slots) * 12.0 + 74880.0 * 4.0) / (256.0 * 256.0 * 256.0), 1e-9);
    EXPECT_NEAR(rays, 23.94, 0.01);
}

TEST(BytesModel, DenseVoxelPassesMatchTheVolumeSizes) {
    for (uint32_t n : {16u, 64u, 256u}) {
        ModelInputs in = handCase();
        in.voxels = n;
        in.slots = vxgi::defaultSlotCapacity(n);
        const std::vector<PassTraffic> p = passTraffic(in);
        uint64_t cleared = 0, directional = 0;
        for (const vxgi::VolumeMemory& v : vxgi::volumeMemory(n, in.slots)) {
            if (v.name.starts_with("voxel attributes") || v.name.starts_with("voxel extents") ||
                v.name == "voxel slot index" ||
                v.name.starts_with("voxel direct light") || v.name == "radiance")
                cleared += v.bytes;
            if (v.name.starts_with("directional")) directional = v.bytes;
        }
        EXPECT_EQ(findPass(p, "clear all voxels")->writtenBytes, cleared) << n;
        EXPECT_EQ(findPass(p, "voxel filtering")->writtenBytes, directional) << n;
    }
}

TEST(BytesModel, GigabytesPerSecond) {
    EXPECT_DOUBLE_EQ(gigabytesPerSecond(2'000'000'000, 1000.0), 2.0);
    EXPECT_DOUBLE_EQ(gigabytesPerSecond(1'000'000, 0.5), 2.0);
    EXPECT_EQ(gigabytesPerSecond(1000, 0.0), 0.0);
}

}  // namespace
}  // namespace dvsgi::bench
