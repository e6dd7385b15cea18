// gpu::Tracker: the barriers it plans from declared uses (read back from
// pendingImageBarriers before they are recorded), and a real submission of
// a write -> read -> write chain that must raise no validation error.
#include "gpu/resources.h"
#include "gpu/tracker.h"
#include "gpu_fixture.h"

namespace dvsgi::test {
namespace {

gpu::Image storageImage(uint32_t mips = 1) {
    gpu::ImageDesc d;
    d.type = VK_IMAGE_TYPE_3D;
    d.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    d.extent = {8, 8, 8};
    d.mipLevels = mips;
    d.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    d.name = "tracker test";
    return gpu::Image(context(), d);
}

// Takes the planned barriers without recording them.
std::vector<VkImageMemoryBarrier2> take(gpu::Tracker& t) {
    std::vector<VkImageMemoryBarrier2> b = t.pendingImageBarriers();
    context().submitAndWait([&](VkCommandBuffer cmd) { t.flush(cmd); });
    return b;
}

class Tracker : public GpuTest {};

TEST_F(Tracker, WriteReadReadWritePlansTransitionRawAndWar) {
    const gpu::Image img = storageImage();
    gpu::Tracker t;
    t.image(img, gpu::use::ComputeWrite, true);
    auto b = take(t);
    ASSERT_EQ(b.size(), 1u);  // first use: UNDEFINED -> GENERAL, nothing to wait for
    EXPECT_EQ(b[0].oldLayout, VK_IMAGE_LAYOUT_UNDEFINED);
    EXPECT_EQ(b[0].newLayout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_EQ(b[0].srcStageMask, VK_PIPELINE_STAGE_2_NONE);

    t.image(img, gpu::use::ComputeRead);
    b = take(t);
    ASSERT_EQ(b.size(), 1u);  // read after write: the write made visible
    EXPECT_EQ(b[0].oldLayout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_EQ(b[0].newLayout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_EQ(b[0].srcStageMask, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    EXPECT_EQ(b[0].srcAccessMask, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    EXPECT_EQ(b[0].dstAccessMask, gpu::use::ComputeRead.access);

    t.image(img, gpu::use::ComputeRead);
    EXPECT_TRUE(t.pendingImageBarriers().empty()) << "a second read of visible data needs no barrier";

    t.image(img, gpu::use::ComputeReadWrite);
    b = take(t);
    ASSERT_EQ(b.size(), 1u);  // write after read: waits for the readers
    EXPECT_EQ(b[0].srcStageMask, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    EXPECT_EQ(b[0].dstAccessMask, gpu::use::ComputeReadWrite.access);

    t.image(img, gpu::use::ComputeReadWrite);
    b = take(t);
    ASSERT_EQ(b.size(), 1u) << "write after write (accumulating dispatches) needs a barrier";
    EXPECT_EQ(b[0].srcAccessMask, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

TEST_F(Tracker, ReadInAnotherStageNeedsItsOwnVisibility) {
    const gpu::Image img = storageImage();
    gpu::Tracker t;
    t.image(img, gpu::use::ComputeWrite, true);
    take(t);
    t.image(img, gpu::use::ComputeRead);
    take(t);
    t.image(img, gpu::use::ShaderRead);  // another layout: a transition after both the write and the reads
    const auto b = take(t);
    ASSERT_EQ(b.size(), 1u);
    EXPECT_EQ(b[0].oldLayout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_EQ(b[0].newLayout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    EXPECT_EQ(t.layout(img), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

TEST_F(Tracker, MipChainsBarrierOnlyTheLevelsInvolvedAndMergeNeighbours) {
    const gpu::Image img = storageImage(4);
    gpu::Tracker t;
    t.image(img, gpu::use::ComputeWrite, true);
    auto b = take(t);
    ASSERT_EQ(b.size(), 1u) << "four mips with one history: one barrier";
    EXPECT_EQ(b[0].subresourceRange.levelCount, 4u);

    // Building level 1 from level 0.
    t.imageMip(img, 0, gpu::use::ComputeRead).imageMip(img, 1, gpu::use::ComputeWrite, true);
    b = take(t);
    ASSERT_EQ(b.size(), 2u);
    EXPECT_EQ(b[0].subresourceRange.baseMipLevel, 0u);
    EXPECT_EQ(b[1].subresourceRange.baseMipLevel, 1u);
    EXPECT_EQ(b[1].srcStageMask, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);  // WAW with the first write

    // Reading the whole chain: level 0 is already visible to compute reads.
    t.image(img, gpu::use::ComputeRead);
    b = take(t);
    ASSERT_EQ(b.size(), 1u) << "levels 1..3 share their history and one barrier";
    EXPECT_EQ(b[0].subresourceRange.baseMipLevel, 1u);
    EXPECT_EQ(b[0].subresourceRange.levelCount, 3u);
}

// Drivers reuse handle values of destroyed objects (NVIDIA's did at once when
// the voxel storage grew, and the tracker applied a one-mip image's history to
// the new mip chain). A resource created later is new to the tracker whatever
// its handle: its first use is a transition from UNDEFINED over all its mips.
TEST_F(Tracker, AResourceCreatedLaterIsNewEvenWithAReusedHandle) {
    gpu::Tracker t;
    VkImage firstHandle = VK_NULL_HANDLE;
    {
        const gpu::Image first = storageImage(1);
        firstHandle = first.handle();
        t.image(first, gpu::use::ComputeWrite, true);
        take(t);
        t.image(first, gpu::use::ShaderRead);
        take(t);
    }
    const gpu::Image second = storageImage(4);
    std::printf("  handle %s\n", second.handle() == firstHandle ? "reused (the case this test is for)" : "not reused");
    EXPECT_EQ(t.layout(second), VK_IMAGE_LAYOUT_UNDEFINED);
    t.imageMip(second, 3, gpu::use::ComputeWrite, true);
    auto b = take(t);
    ASSERT_EQ(b.size(), 1u);
    EXPECT_EQ(b[0].subresourceRange.baseMipLevel, 3u);
    t.imageMip(second, 1, gpu::use::ComputeRead);
    b = take(t);
    ASSERT_EQ(b.size(), 1u);
    EXPECT_EQ(b[0].oldLayout, VK_IMAGE_LAYOUT_UNDEFINED) << "mip 1 was never used";
    EXPECT_EQ(b[0].subresourceRange.baseMipLevel, 1u);
}

TEST_F(Tracker, BuffersGetWriteToHostReadBarriers) {
    const gpu::Buffer buf(context(), 64, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUse::Readback, "stats");
    gpu::Tracker t;
    t.buffer(buf, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    EXPECT_TRUE(t.pendingBufferBarriers().empty()) << "a buffer's first write waits for nothing";
    t.buffer(buf, VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    ASSERT_EQ(t.pendingBufferBarriers().size(), 1u);
    EXPECT_EQ(t.pendingBufferBarriers()[0].dstStageMask, VK_PIPELINE_STAGE_2_HOST_BIT);
    context().submitAndWait([&](VkCommandBuffer cmd) { t.flush(cmd); });
}

}  // namespace
}  // namespace dvsgi::test
