#include "render/lighting.h"

#include "gpu/barriers.h"
#include "gpu/context.h"
#include "gpu/timers.h"
#include "render/gbuffer.h"
#include <array>
#include <cmath>

#include "render/shadows.h"
#include "shared/bindings.h"
#include "vxgi/cone_settings.h"
#include "vxgi/volumes.h"

namespace dvsgi::render {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kComp[] = {
#include "shaders/lighting.comp.inc"
};

struct LightingPush {  // mirrors lighting.comp
    sh::ConeParams cone;
    glm::vec4 shadow;
};

}  // namespace

LightingPass::LightingPass(const gpu::Context& ctx, uint32_t width, uint32_t height)
    : ctx_(ctx), width_(width), height_(height) {
    gpu::ImageDesc d;
    d.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    d.extent = {width, height, 1};
    d.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    d.name = "direct radiance";
    direct = gpu::Image(ctx, d);
    d.format = VK_FORMAT_R16_SFLOAT;
    d.name = "light visibility";
    shadow = gpu::Image(ctx, d);

    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_LIGHT_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_LIGHT_GBUF_BASE, sampled, cs},
                       {sh::BIND_LIGHT_GBUF_NORMAL, sampled, cs},
                       {sh::BIND_LIGHT_GBUF_EMISSION, sampled, cs},
                       {sh::BIND_LIGHT_DEPTH, sampled, cs},
                       {sh::BIND_LIGHT_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_LIGHT_SHADOW_VIEWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_LIGHT_SHADOW_MAP, sampled, cs},
                       {sh::BIND_LIGHT_OUT_DIRECT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_LIGHT_VOXEL_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_LIGHT_VOXEL_RADIANCE, sampled, cs},
                       {sh::BIND_LIGHT_VOXEL_DIRECTIONAL, sampled, cs, 6},
                       {sh::BIND_LIGHT_OUT_SHADOW, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs}};
    layout.pushConstantBytes = sizeof(LightingPush);
    layout.pushConstantStages = cs;
    pipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kComp), layout, "lighting");
}

void LightingPass::record(VkCommandBuffer cmd, const GBufferPass& g, const ShadowPass& shadows,
                          const gpu::Buffer& frame, const gpu::Buffer& lights, const gpu::Buffer& views,
                          const vxgi::VoxelVolumes& volumes, VkSampler volumeSampler, const ShadowConeSettings& cones,
                          const vxgi::ConeSettings& cone, gpu::GpuTimers* timers) const {
    gpu::GpuTimerScope timer(timers, cmd, "direct lighting");
    gpu::transition(cmd, direct, gpu::use::Undefined, gpu::use::ComputeWrite);
    gpu::transition(cmd, shadow, gpu::use::Undefined, gpu::use::ComputeWrite);
    std::array<VkImageView, 6> dirs;
    for (uint32_t i = 0; i < 6; ++i) dirs[i] = volumes.directional[i].view();
    gpu::bind(cmd, pipeline_);
    const VkSampler point = g.pointSampler.handle();
    gpu::Descriptors()
        .uniformBuffer(sh::BIND_LIGHT_FRAME, frame.handle())
        .sampledImage(sh::BIND_LIGHT_GBUF_BASE, g.base.view(), point)
        .sampledImage(sh::BIND_LIGHT_GBUF_NORMAL, g.normal.view(), point)
        .sampledImage(sh::BIND_LIGHT_GBUF_EMISSION, g.emission.view(), point)
        .sampledImage(sh::BIND_LIGHT_DEPTH, g.depth.view(), point, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
        .storageBuffer(sh::BIND_LIGHT_LIGHTS, lights.handle())
        .storageBuffer(sh::BIND_LIGHT_SHADOW_VIEWS, views.handle())
        .sampledImage(sh::BIND_LIGHT_SHADOW_MAP, shadows.map().view(), shadows.sampler().handle())
        .storageImage(sh::BIND_LIGHT_OUT_DIRECT, direct.view())
        .uniformBuffer(sh::BIND_LIGHT_VOXEL_GRID, volumes.gridBuffer.handle())
        .sampledImage(sh::BIND_LIGHT_VOXEL_RADIANCE, volumes.radiance.view(), volumeSampler, VK_IMAGE_LAYOUT_GENERAL)
        .sampledImages(sh::BIND_LIGHT_VOXEL_DIRECTIONAL, dirs, volumeSampler, VK_IMAGE_LAYOUT_GENERAL)
        .storageImage(sh::BIND_LIGHT_OUT_SHADOW, shadow.view())
        .push(ctx_, cmd, pipeline_);
    const LightingPush push{vxgi::gpuCone(cone, volumes.grid),
                            glm::vec4(cones.enabled ? 1.0f : 0.0f, std::tan(glm::radians(cones.apertureDegrees * 0.5f)),
                                      0.0f, 0.0f)};
    gpu::pushConstants(cmd, pipeline_, VK_SHADER_STAGE_COMPUTE_BIT, push);
    vkCmdDispatch(cmd, gpu::groupCount(width_, 8), gpu::groupCount(height_, 8), 1);
}

}  // namespace dvsgi::render
