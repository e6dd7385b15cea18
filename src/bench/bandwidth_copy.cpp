#include "bench/bandwidth_copy.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "gpu/barriers.h"
#include "gpu/context.h"
#include "gpu/timers.h"
#include "shared/bandwidth_copy_pass.h"

namespace dvsgi::bench {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kCopy[] = {
#include "shaders/bandwidth_copy.comp.inc"
};

constexpr uint64_t kMiB = 1024ull * 1024ull;

// Each copy rewrites the destination the previous one wrote (write after write).
void copyAfterCopy(VkCommandBuffer cmd) {
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

}  // namespace

BandwidthCopyPass::BandwidthCopyPass(const gpu::Context& ctx) : ctx_(ctx) {
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_COPY_SRC, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_COPY_DST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs}};
    layout.pushConstantBytes = sizeof(sh::CopyPush);
    layout.pushConstantStages = cs;
    pipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kCopy), layout, "bandwidth copy");
}

void BandwidthCopyPass::record(VkCommandBuffer cmd, const gpu::Buffer& src, const gpu::Buffer& dst, VkDeviceSize bytes,
                               gpu::GpuTimers* timers, const char* timerName) const {
    if (bytes % 16 != 0 || bytes > src.size() || bytes > dst.size())
        throw std::runtime_error("bandwidth copy: " + std::to_string(bytes) +
                                 " bytes is not a multiple of 16 or exceeds a buffer");
    const uint64_t elements = bytes / 16;
    if (elements > UINT32_MAX) throw std::runtime_error("bandwidth copy: more than 2^32 elements");
    gpu::GpuTimerScope timer(timers, cmd, timerName);
    gpu::bind(cmd, pipeline_);
    gpu::Descriptors()
        .storageBuffer(sh::BIND_COPY_SRC, src.handle(), 0, bytes)
        .storageBuffer(sh::BIND_COPY_DST, dst.handle(), 0, bytes)
        .push(ctx_, cmd, pipeline_);
    const sh::CopyPush push{glm::uvec4(uint32_t(elements), 0u, 0u, 0u)};
    gpu::pushConstants(cmd, pipeline_, VK_SHADER_STAGE_COMPUTE_BIT, push);
    const uint32_t groups = std::min({gpu::groupCount(uint32_t(elements), sh::COPY_GROUP), sh::COPY_MAX_GROUPS,
                                      ctx_.properties.limits.maxComputeWorkGroupCount[0]});
    vkCmdDispatch(cmd, std::max(groups, 1u), 1, 1);
}

uint64_t copyBandwidthBytes(const gpu::Context& ctx) {
    uint64_t heap = 0;
    for (uint32_t i = 0; i < ctx.memory.memoryHeapCount; ++i)
        if (ctx.memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            heap = std::max<uint64_t>(heap, ctx.memory.memoryHeaps[i].size);
    uint64_t bytes = std::clamp<uint64_t>(heap / 32, 16 * kMiB, 256 * kMiB);
    bytes = std::min<uint64_t>(bytes, ctx.properties.limits.maxStorageBufferRange);
    if (ctx.maxAllocationSize > 0) bytes = std::min(bytes, ctx.maxAllocationSize);
    return bytes / kMiB * kMiB;  // whole MiB: a multiple of 16 and easy to read in the report
}

CopyBandwidth measureCopyBandwidth(const gpu::Context& ctx, uint64_t bytes, uint32_t repetitions) {
    if (repetitions == 0 || repetitions > 32) throw std::runtime_error("bandwidth copy: 1..32 repetitions");
    const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    const gpu::Buffer src(ctx, bytes, usage, gpu::MemoryUse::Device, "bandwidth copy source");
    const gpu::Buffer dst(ctx, bytes, usage, gpu::MemoryUse::Device, "bandwidth copy destination");
    const BandwidthCopyPass pass(ctx);
    gpu::GpuTimers timers(ctx, 1);
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        // Defined contents; the fill also touches every page before timing.
        vkCmdFillBuffer(cmd, src.handle(), 0, bytes, 0x3c3c3c3cu);
        gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
        pass.record(cmd, src, dst, bytes, nullptr, "");
    });
    CopyBandwidth out;
    out.bufferBytes = bytes;
    out.repetitions = repetitions;
    // One submission per copy: a begin timestamp (top of pipe) in the same
    // command buffer could be taken while the previous copy still runs.
    for (uint32_t r = 0; r < repetitions; ++r) {
        timers.reset();
        ctx.submitAndWait([&](VkCommandBuffer cmd) {
            copyAfterCopy(cmd);
            pass.record(cmd, src, dst, bytes, &timers, "bandwidth copy");
        });
        for (const gpu::TimerResult& t : timers.results()) out.samplesMs.push_back(t.ms);
    }
    std::vector<double> sorted = out.samplesMs;
    std::sort(sorted.begin(), sorted.end());
    const size_t n = sorted.size();
    out.medianMs = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    out.gbps = out.medianMs > 0.0 ? double(2 * bytes) / (out.medianMs * 1e6) : 0.0;
    return out;
}

}  // namespace dvsgi::bench
