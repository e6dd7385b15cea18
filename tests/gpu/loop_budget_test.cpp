// llvmpipe ends every loop of a shader invocation once its loops, all of them
// together, have looped 65535 times (Mesa's LP_MAX_TGSI_LOOP_ITERATIONS,
// shared by every loop of a shader): the rest of the work is dropped without
// an error. Passes that loop long per invocation (the compute voxelizer's
// lone walks, VOXC_WALK_COLUMNS_CPU) are sized to stay under it; this test
// pins the budget down so a driver that changes it shows here first.
#include <cstring>

#include <gtest/gtest.h>

#include "gpu/barriers.h"
#include "gpu/pipeline.h"
#include "gpu/transfer.h"
#include "gpu_fixture.h"
#include "shared/voxelize_compute_pass.h"

namespace dvsgi::test {
namespace {

const uint32_t kLoops[] = {
#include "shaders/loop_budget.comp.inc"
};

class LavapipeLimits : public GpuTest {};

TEST_F(LavapipeLimits, LoopsShareOneIterationBudget) {
    const gpu::Context& ctx = context();
    const uint32_t init[3] = {0, 0, 1};
    const gpu::Buffer counts =
        gpu::createBuffer(ctx, init, sizeof(init),
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "loop counts");
    gpu::LayoutDesc layout;
    layout.bindings = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT}};
    layout.pushConstantBytes = 16;
    layout.pushConstantStages = VK_SHADER_STAGE_COMPUTE_BIT;
    const gpu::Pipeline pipeline(ctx, gpu::Spirv(kLoops), layout, "loop budget");
    const uint32_t iterations = 40000;  // each loop alone fits the budget, the two together do not
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        gpu::bind(cmd, pipeline);
        gpu::Descriptors().storageBuffer(0, counts.handle()).push(ctx, cmd, pipeline);
        const glm::uvec4 push(iterations, 0, 0, 0);
        gpu::pushConstants(cmd, pipeline, VK_SHADER_STAGE_COMPUTE_BIT, push);
        vkCmdDispatch(cmd, 1, 1, 1);
        gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    });
    const std::vector<uint8_t> bytes = gpu::readbackBuffer(ctx, counts);
    uint32_t out[3];
    std::memcpy(out, bytes.data(), sizeof(out));
    std::printf("%s: first loop %u, second loop %u of %u iterations each\n", ctx.deviceName.c_str(), out[0], out[1],
                iterations);
    EXPECT_EQ(out[0], iterations);
    if (ctx.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) {
        // The back edge that takes the budget to zero still runs its body.
        EXPECT_GE(out[0] + out[1], shader::LLVMPIPE_LOOP_BUDGET - 2);
        EXPECT_LE(out[0] + out[1], shader::LLVMPIPE_LOOP_BUDGET + 2);
    } else {
        EXPECT_EQ(out[1], iterations);
    }
}

}  // namespace
}  // namespace dvsgi::test
