#include "render/composite.h"

#include "gpu/tracker.h"
#include "gpu/context.h"
#include "gpu/timers.h"
#include "shared/composite_pass.h"

namespace dvsgi::render {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kComp[] = {
#include "shaders/composite.comp.inc"
};

}  // namespace

CompositePass::CompositePass(const gpu::Context& ctx) : ctx_(ctx) {
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::LayoutDesc layout;
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    layout.bindings = {{sh::BIND_COMP_DIRECT, storage, cs}, {sh::BIND_COMP_OUT, storage, cs},
                       {sh::BIND_COMP_DIFFUSE, storage, cs}, {sh::BIND_COMP_SPECULAR, storage, cs},
                       {sh::BIND_COMP_SHADOW, storage, cs},
                       {sh::BIND_COMP_BASE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, cs}};
    layout.pushConstantBytes = sizeof(sh::CompositePush);
    layout.pushConstantStages = cs;
    pipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kComp), layout, "composite");
}

void CompositePass::record(VkCommandBuffer cmd, gpu::Tracker& tracker, const CompositeInputs& in,
                           const gpu::Image& output, uint32_t supersample, uint32_t term, bool applyAO,
                           gpu::GpuTimers* timers) const {
    gpu::GpuTimerScope timer(timers, cmd, "composite");
    tracker.image(in.direct, gpu::use::ComputeRead).image(in.visibility, gpu::use::ComputeRead);
    tracker.image(in.base, gpu::use::ShaderRead);
    if (in.indirect) tracker.image(in.diffuse, gpu::use::ComputeRead).image(in.specular, gpu::use::ComputeRead);
    else  // bound but not read: any layout the descriptor accepts
        tracker.image(in.diffuse, gpu::use::ComputeRead, true).image(in.specular, gpu::use::ComputeRead, true);
    tracker.image(output, gpu::use::ComputeWrite, true).flush(cmd);
    const uint32_t width = output.desc().extent.width, height = output.desc().extent.height;
    gpu::bind(cmd, pipeline_);
    gpu::Descriptors()
        .storageImage(sh::BIND_COMP_DIRECT, in.direct.view())
        .storageImage(sh::BIND_COMP_OUT, output.view())
        .storageImage(sh::BIND_COMP_DIFFUSE, in.diffuse.view())
        .storageImage(sh::BIND_COMP_SPECULAR, in.specular.view())
        .storageImage(sh::BIND_COMP_SHADOW, in.visibility.view())
        .sampledImage(sh::BIND_COMP_BASE, in.base.view(), in.point)
        .push(ctx_, cmd, pipeline_);
    const sh::CompositePush push{glm::uvec4(width, height, supersample, term),
                                 glm::uvec4(applyAO ? 1u : 0u, in.indirect ? 1u : 0u, 0u, 0u)};
    gpu::pushConstants(cmd, pipeline_, VK_SHADER_STAGE_COMPUTE_BIT, push);
    vkCmdDispatch(cmd, gpu::groupCount(width, sh::COMPOSITE_GROUP), gpu::groupCount(height, sh::COMPOSITE_GROUP), 1);
}

}  // namespace dvsgi::render
