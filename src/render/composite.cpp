#include "render/composite.h"

#include "gpu/barriers.h"
#include "gpu/context.h"
#include "gpu/timers.h"
#include "shared/bindings.h"
#include "shared/gather_data.h"
#include "shared/push.h"

namespace dvsgi::render {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kComp[] = {
#include "shaders/composite.comp.inc"
};

}  // namespace

CompositePass::CompositePass(const gpu::Context& ctx, uint32_t width, uint32_t height, uint32_t supersample)
    : ctx_(ctx), width_(width), height_(height), supersample_(supersample) {
    gpu::ImageDesc d;
    d.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    d.extent = {width, height, 1};
    d.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    d.name = "output";
    output = gpu::Image(ctx, d);
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::LayoutDesc layout;
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    layout.bindings = {{sh::BIND_COMP_DIRECT, storage, cs}, {sh::BIND_COMP_OUT, storage, cs},
                       {sh::BIND_COMP_DIFFUSE, storage, cs}, {sh::BIND_COMP_SPECULAR, storage, cs},
                       {sh::BIND_COMP_SHADOW, storage, cs}};
    layout.pushConstantBytes = sizeof(sh::CompositePush);
    layout.pushConstantStages = cs;
    pipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kComp), layout, "composite");
}

void CompositePass::record(VkCommandBuffer cmd, const gpu::Image& direct, const gpu::Image& shadow,
                           const gpu::Image& diffuse, const gpu::Image& specular, bool indirect, uint32_t term,
                           bool applyAO, gpu::GpuTimers* timers) const {
    gpu::GpuTimerScope timer(timers, cmd, "composite");
    for (const gpu::Image* img : {&direct, &shadow, &diffuse, &specular})
        gpu::transition(cmd, *img, gpu::use::ComputeWrite, gpu::use::ComputeReadWrite);
    gpu::transition(cmd, output, gpu::use::Undefined, gpu::use::ComputeWrite);
    gpu::bind(cmd, pipeline_);
    gpu::Descriptors()
        .storageImage(sh::BIND_COMP_DIRECT, direct.view())
        .storageImage(sh::BIND_COMP_OUT, output.view())
        .storageImage(sh::BIND_COMP_DIFFUSE, diffuse.view())
        .storageImage(sh::BIND_COMP_SPECULAR, specular.view())
        .storageImage(sh::BIND_COMP_SHADOW, shadow.view())
        .push(ctx_, cmd, pipeline_);
    const sh::CompositePush push{glm::uvec4(width_, height_, supersample_, term),
                                 glm::uvec4(applyAO ? 1u : 0u, indirect ? 1u : 0u, 0u, 0u)};
    gpu::pushConstants(cmd, pipeline_, VK_SHADER_STAGE_COMPUTE_BIT, push);
    vkCmdDispatch(cmd, gpu::groupCount(width_, 8), gpu::groupCount(height_, 8), 1);
}

}  // namespace dvsgi::render
