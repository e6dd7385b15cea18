#include "render/gather.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "gpu/barriers.h"
#include "gpu/context.h"
#include "gpu/timers.h"
#include "render/gbuffer.h"
#include "shared/bindings.h"
#include "shared/push.h"
#include "shared/scene_data.h"
#include "vxgi/volumes.h"

namespace dvsgi::render {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kGather[] = {
#include "shaders/gather.comp.inc"
};
const uint32_t kUpsample[] = {
#include "shaders/upsample.comp.inc"
};

gpu::Image termImage(const gpu::Context& ctx, uint32_t w, uint32_t h, const char* name) {
    gpu::ImageDesc d;
    d.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    d.extent = {w, h, 1};
    d.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    d.name = name;
    return gpu::Image(ctx, d);
}

}  // namespace

GatherPass::GatherPass(const gpu::Context& ctx, uint32_t width, uint32_t height, float traceScale)
    : traceWidth(std::max(1u, uint32_t(std::lround(width * traceScale)))),
      traceHeight(std::max(1u, uint32_t(std::lround(height * traceScale)))),
      ctx_(ctx),
      width_(width),
      height_(height) {
    diffuse = termImage(ctx, width, height, "indirect diffuse");
    specular = termImage(ctx, width, height, "specular");
    if (traceWidth != width || traceHeight != height) {
        lowDiffuse_ = termImage(ctx, traceWidth, traceHeight, "indirect diffuse (trace size)");
        lowSpecular_ = termImage(ctx, traceWidth, traceHeight, "specular (trace size)");
    }
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_CONE_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_GATHER_RADIANCE, sampled, cs},
                       {sh::BIND_CONE_DIRECTIONAL, sampled, cs, 6},
                       {sh::BIND_GATHER_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_GATHER_BASE, sampled, cs},
                       {sh::BIND_GATHER_NORMAL, sampled, cs},
                       {sh::BIND_GATHER_DEPTH, sampled, cs},
                       {sh::BIND_GATHER_OUT_DIFFUSE, storage, cs},
                       {sh::BIND_GATHER_OUT_SPECULAR, storage, cs}};
    layout.pushConstantBytes = sizeof(sh::GatherPush);
    layout.pushConstantStages = cs;
    gather_ = gpu::Pipeline(ctx, gpu::Spirv(kGather), layout, "cone tracing");

    gpu::LayoutDesc up;
    up.bindings = {{sh::BIND_UP_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                   {sh::BIND_UP_NORMAL, sampled, cs},
                   {sh::BIND_UP_DEPTH, sampled, cs},
                   {sh::BIND_UP_LOW_DIFFUSE, storage, cs},
                   {sh::BIND_UP_LOW_SPECULAR, storage, cs},
                   {sh::BIND_UP_OUT_DIFFUSE, storage, cs},
                   {sh::BIND_UP_OUT_SPECULAR, storage, cs}};
    up.pushConstantBytes = sizeof(sh::UpsamplePush);
    up.pushConstantStages = cs;
    upsample_ = gpu::Pipeline(ctx, gpu::Spirv(kUpsample), up, "upsample");
}

void GatherPass::record(VkCommandBuffer cmd, const GBufferPass& g, const vxgi::VoxelVolumes& v, VkSampler volumeSampler,
                        const gpu::Buffer& frame, const GatherSettings& s, const vxgi::ConeSettings& cone,
                        gpu::GpuTimers* timers) const {
    const bool reduced = bool(lowDiffuse_);
    const gpu::Image& outD = reduced ? lowDiffuse_ : diffuse;
    const gpu::Image& outS = reduced ? lowSpecular_ : specular;
    {
        gpu::GpuTimerScope timer(timers, cmd, "cone tracing");
        gpu::transition(cmd, outD, gpu::use::Undefined, gpu::use::ComputeWrite);
        gpu::transition(cmd, outS, gpu::use::Undefined, gpu::use::ComputeWrite);
        std::array<VkImageView, 6> dirs;
        for (uint32_t d = 0; d < 6; ++d) dirs[d] = v.directional[d].view();
        const VkSampler point = g.pointSampler.handle();
        gpu::bind(cmd, gather_);
        gpu::Descriptors()
            .uniformBuffer(sh::BIND_CONE_GRID, v.gridBuffer.handle())
            .sampledImage(sh::BIND_GATHER_RADIANCE, v.radiance.view(), volumeSampler, VK_IMAGE_LAYOUT_GENERAL)
            .sampledImages(sh::BIND_CONE_DIRECTIONAL, dirs, volumeSampler, VK_IMAGE_LAYOUT_GENERAL)
            .uniformBuffer(sh::BIND_GATHER_FRAME, frame.handle())
            .sampledImage(sh::BIND_GATHER_BASE, g.base.view(), point)
            .sampledImage(sh::BIND_GATHER_NORMAL, g.normal.view(), point)
            .sampledImage(sh::BIND_GATHER_DEPTH, g.depth.view(), point, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
            .storageImage(sh::BIND_GATHER_OUT_DIFFUSE, outD.view())
            .storageImage(sh::BIND_GATHER_OUT_SPECULAR, outS.view())
            .push(ctx_, cmd, gather_);
        sh::GatherPush push{};
        push.cone = vxgi::gpuCone(cone, v.grid);
        push.params = glm::vec4(0.0f, s.aoLambda, 0.0f, std::tan(glm::radians(s.minSpecularDegrees)));
        push.flags = glm::uvec4(0u, s.specular ? 1u : 0u, traceWidth, traceHeight);
        gpu::pushConstants(cmd, gather_, VK_SHADER_STAGE_COMPUTE_BIT, push);
        vkCmdDispatch(cmd, gpu::groupCount(traceWidth, 8), gpu::groupCount(traceHeight, 8), 1);
    }
    if (!reduced) return;
    gpu::GpuTimerScope timer(timers, cmd, "upsample");
    gpu::transition(cmd, outD, gpu::use::ComputeWrite, gpu::use::ComputeReadWrite);
    gpu::transition(cmd, outS, gpu::use::ComputeWrite, gpu::use::ComputeReadWrite);
    gpu::transition(cmd, diffuse, gpu::use::Undefined, gpu::use::ComputeWrite);
    gpu::transition(cmd, specular, gpu::use::Undefined, gpu::use::ComputeWrite);
    const VkSampler point = g.pointSampler.handle();
    gpu::bind(cmd, upsample_);
    gpu::Descriptors()
        .uniformBuffer(sh::BIND_UP_FRAME, frame.handle())
        .sampledImage(sh::BIND_UP_NORMAL, g.normal.view(), point)
        .sampledImage(sh::BIND_UP_DEPTH, g.depth.view(), point, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
        .storageImage(sh::BIND_UP_LOW_DIFFUSE, outD.view())
        .storageImage(sh::BIND_UP_LOW_SPECULAR, outS.view())
        .storageImage(sh::BIND_UP_OUT_DIFFUSE, diffuse.view())
        .storageImage(sh::BIND_UP_OUT_SPECULAR, specular.view())
        .push(ctx_, cmd, upsample_);
    const sh::UpsamplePush push{glm::uvec4(traceWidth, traceHeight, width_, height_)};
    gpu::pushConstants(cmd, upsample_, VK_SHADER_STAGE_COMPUTE_BIT, push);
    vkCmdDispatch(cmd, gpu::groupCount(width_, 8), gpu::groupCount(height_, 8), 1);
}

}  // namespace dvsgi::render
