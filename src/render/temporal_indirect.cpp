#include "render/temporal_indirect.h"

#include "gpu/context.h"
#include "gpu/timers.h"
#include "gpu/tracker.h"
#include "shared/temporal_indirect_pass.h"

namespace dvsgi::render {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kTemporal[] = {
#include "shaders/temporal_indirect.comp.inc"
};

}  // namespace

TemporalIndirectPass::TemporalIndirectPass(const gpu::Context& ctx) : ctx_(ctx) {
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_TI_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_TI_NORMAL, sampled, cs},
                       {sh::BIND_TI_DEPTH, sampled, cs},
                       {sh::BIND_TI_DIFFUSE, storage, cs},
                       {sh::BIND_TI_HISTORY_IN, storage, cs},
                       {sh::BIND_TI_SURFACE_IN, storage, cs},
                       {sh::BIND_TI_HISTORY_OUT, storage, cs},
                       {sh::BIND_TI_SURFACE_OUT, storage, cs}};
    layout.pushConstantBytes = sizeof(sh::TemporalIndirectPush);
    layout.pushConstantStages = cs;
    pipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kTemporal), layout, "temporal indirect");
}

void TemporalIndirectPass::record(VkCommandBuffer cmd, gpu::Tracker& tracker, const TemporalIndirectInputs& in,
                                  const TemporalIndirectTargets& out, const TemporalSettings& s,
                                  gpu::GpuTimers* timers) const {
    gpu::GpuTimerScope timer(timers, cmd, "temporal indirect");
    const uint32_t width = out.diffuse.desc().extent.width, height = out.diffuse.desc().extent.height;
    // Without valid history the inputs are bound but not read: their
    // contents may be discarded (the first frame finds them undefined).
    tracker.image(in.gbuffer.normal, gpu::use::ShaderRead)
        .image(in.gbuffer.depth, gpu::use::DepthRead)
        .image(out.diffuse, gpu::use::ComputeReadWrite)
        .image(in.history, gpu::use::ComputeRead, !in.historyValid)
        .image(in.surface, gpu::use::ComputeRead, !in.historyValid)
        .image(out.history, gpu::use::ComputeWrite, true)
        .image(out.surface, gpu::use::ComputeWrite, true)
        .flush(cmd);
    const VkSampler point = in.samplers.point.handle();
    gpu::bind(cmd, pipeline_);
    gpu::Descriptors()
        .uniformBuffer(sh::BIND_TI_FRAME, in.frame.handle())
        .sampledImage(sh::BIND_TI_NORMAL, in.gbuffer.normal.view(), point)
        .sampledImage(sh::BIND_TI_DEPTH, in.gbuffer.depth.view(), point, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
        .storageImage(sh::BIND_TI_DIFFUSE, out.diffuse.view())
        .storageImage(sh::BIND_TI_HISTORY_IN, in.history.view())
        .storageImage(sh::BIND_TI_SURFACE_IN, in.surface.view())
        .storageImage(sh::BIND_TI_HISTORY_OUT, out.history.view())
        .storageImage(sh::BIND_TI_SURFACE_OUT, out.surface.view())
        .push(ctx_, cmd, pipeline_);
    sh::TemporalIndirectPush push{};
    push.prevViewProj = in.previousViewProj;
    push.params = glm::vec4(temporalBlendWeight(s.minAlpha, in.historyFrames, in.lightClimbs), sh::TEMPORAL_DEPTH_TOLERANCE,
                            sh::TEMPORAL_NORMAL_COSINE, sh::TEMPORAL_MAX_SAMPLES);
    push.flags = glm::uvec4(width, height, in.historyValid ? 1u : 0u, 0u);
    gpu::pushConstants(cmd, pipeline_, VK_SHADER_STAGE_COMPUTE_BIT, push);
    vkCmdDispatch(cmd, gpu::groupCount(width, sh::TEMPORAL_GROUP), gpu::groupCount(height, sh::TEMPORAL_GROUP), 1);
}

}  // namespace dvsgi::render
