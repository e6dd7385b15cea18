#include "gpu/barriers.h"
#include "gpu/context.h"
#include "gpu/timers.h"
#include "vxgi/voxel_light.h"
#include "vxgi/volumes.h"

namespace dvsgi::vxgi {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kInject[] = {
#include "shaders/inject.comp.inc"
};

constexpr VkPipelineStageFlags2 kShaders =
    VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;

}  // namespace

InjectPass::InjectPass(const gpu::Context& ctx, uint32_t n) : ctx_(ctx) {
    gpu::ImageDesc d;
    d.type = VK_IMAGE_TYPE_3D;
    d.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    d.extent = {n, n, n};
    d.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    d.name = "voxel direct light";
    direct = gpu::Image(ctx, d);
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        gpu::transition(cmd, direct, gpu::use::Undefined, gpu::use::ComputeReadWrite);
    });

    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_INJECT_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_INJECT_ACCUM, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_INJECT_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_INJECT_SHADOW_VIEWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_INJECT_SHADOW_MAP, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, cs},
                       {sh::BIND_INJECT_RADIANCE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs}};
    layout.pushConstantBytes = sizeof(sh::VoxelLightPush);
    layout.pushConstantStages = cs;
    pipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kInject), layout, "voxel inject");
}

void InjectPass::record(VkCommandBuffer cmd, const VoxelVolumes& v, const ShadowInputs& s,
                        const VoxelLightSettings& settings, gpu::GpuTimers* timers) const {
    gpu::GpuTimerScope timer(timers, cmd, "voxel direct light");
    gpu::storageWritesVisible(cmd, kShaders | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    gpu::bind(cmd, pipeline_);
    gpu::Descriptors()
        .uniformBuffer(sh::BIND_INJECT_GRID, v.gridBuffer.handle())
        .storageImage(sh::BIND_INJECT_ACCUM, v.accum.view())
        .storageBuffer(sh::BIND_INJECT_LIGHTS, s.lights)
        .storageBuffer(sh::BIND_INJECT_SHADOW_VIEWS, s.views)
        .sampledImage(sh::BIND_INJECT_SHADOW_MAP, s.shadowMap, s.shadowSampler)
        .storageImage(sh::BIND_INJECT_RADIANCE, direct.view())
        .push(ctx_, cmd, pipeline_);
    const sh::VoxelLightPush push{
        glm::uvec4(s.lightCount, settings.normalWeighted ? 1u : 0u, uint32_t(settings.occlusion),
                   s.shadowsRendered ? 1u : 0u),
        glm::vec4(settings.softKappa, settings.shadowNormalOffset, settings.emissionInRadiance ? 1.0f : 0.0f, 0.0f)};
    gpu::pushConstants(cmd, pipeline_, VK_SHADER_STAGE_COMPUTE_BIT, push);
    const uint32_t groups = gpu::groupCount(v.grid.n, 4);
    vkCmdDispatch(cmd, groups, groups, groups);
    gpu::storageWritesVisible(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                              VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT);
}

void InjectPass::copyToRadiance(VkCommandBuffer cmd, const VoxelVolumes& v) const {
    VkImageCopy region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstSubresource = region.srcSubresource;
    region.extent = direct.desc().extent;
    vkCmdCopyImage(cmd, direct.handle(), VK_IMAGE_LAYOUT_GENERAL, v.radiance.handle(), VK_IMAGE_LAYOUT_GENERAL, 1,
                   &region);
    gpu::storageWritesVisible(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
}

}  // namespace dvsgi::vxgi
