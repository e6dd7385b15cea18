// Synchronization validation is on in every validated Context (GPU tests,
// `dvsgi render --validate`): a missing barrier must show up as a SYNC-HAZARD
// error that names the resource, and a correct barrier must not.
#include <algorithm>

#include <gtest/gtest.h>

#include "gpu/context.h"
#include "gpu/resources.h"

namespace dvsgi::test {
namespace {

gpu::ContextOptions validated(bool sync) {
    gpu::ContextOptions o;
    o.validation = true;
    o.syncValidation = sync;
    return o;
}

// Two fills of one buffer; with `barrier`, the second waits for the first.
void fillTwice(const gpu::Context& ctx, const gpu::Buffer& b, bool barrier) {
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        vkCmdFillBuffer(cmd, b.handle(), 0, b.size(), 1u);
        if (barrier) {
            VkMemoryBarrier2 m{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
            // The spec puts fills in the clear stage, layer 1.3.239 in copy:
            // the transfer stage covers both.
            m.srcStageMask = m.dstStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
            m.srcAccessMask = m.dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
            VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
            dep.memoryBarrierCount = 1;
            dep.pMemoryBarriers = &m;
            vkCmdPipelineBarrier2(cmd, &dep);
        }
        vkCmdFillBuffer(cmd, b.handle(), 0, b.size(), 2u);
    });
}

bool anyMessageHas(const gpu::Context& ctx, const std::string& a, const std::string& b) {
    const auto& m = ctx.validationMessages();
    return std::any_of(m.begin(), m.end(), [&](const std::string& s) {
        return s.find(a) != std::string::npos && s.find(b) != std::string::npos;
    });
}

TEST(SyncValidation, MissingBarrierIsAHazardNamingTheBuffer) {
    gpu::Context ctx(validated(true));
    ASSERT_TRUE(ctx.syncValidationEnabled()) << "the validation layer lacks VK_EXT_validation_features";
    gpu::Buffer b(ctx, 4096, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Device, "twice-filled buffer");
    fillTwice(ctx, b, true);
    EXPECT_EQ(ctx.validationErrors(), 0u);
    EXPECT_EQ(ctx.syncHazards(), 0u);
    fillTwice(ctx, b, false);
    EXPECT_EQ(ctx.syncHazards(), 1u);
    EXPECT_EQ(ctx.validationErrors(), ctx.syncHazards());
    EXPECT_TRUE(anyMessageHas(ctx, "SYNC-HAZARD-WRITE-AFTER-WRITE", "twice-filled buffer"))
        << (ctx.validationMessages().empty() ? "no message" : ctx.validationMessages().back());
}

TEST(SyncValidation, OffWhenNotAsked) {
    gpu::Context ctx(validated(false));
    EXPECT_FALSE(ctx.syncValidationEnabled());
    gpu::Buffer b(ctx, 4096, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Device, "twice-filled buffer");
    fillTwice(ctx, b, false);
    EXPECT_EQ(ctx.validationErrors(), 0u);
    EXPECT_EQ(ctx.syncHazards(), 0u);
}

}  // namespace
}  // namespace dvsgi::test
