#include "render/gbuffer.h"

#include "gpu/barriers.h"
#include "gpu/context.h"
#include "gpu/timers.h"
#include "render/scene_gpu.h"
#include "shared/bindings.h"
#include "shared/push.h"

namespace dvsgi::render {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kVert[] = {
#include "shaders/gbuffer.vert.inc"
};
const uint32_t kFrag[] = {
#include "shaders/gbuffer.frag.inc"
};

gpu::Image target(const gpu::Context& ctx, VkFormat format, uint32_t w, uint32_t h, VkImageUsageFlags usage,
                  const char* name) {
    gpu::ImageDesc d;
    d.format = format;
    d.extent = {w, h, 1};
    d.usage = usage | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    d.name = name;
    return gpu::Image(ctx, d);
}

}  // namespace

GBufferPass::GBufferPass(const gpu::Context& ctx, const SceneGpu& scene, uint32_t width, uint32_t height)
    : ctx_(ctx), width_(width), height_(height) {
    const VkImageUsageFlags color = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    base = target(ctx, kColorFormat, width, height, color, "gbuffer base colour");
    normal = target(ctx, kColorFormat, width, height, color, "gbuffer normal");
    emission = target(ctx, kColorFormat, width, height, color, "gbuffer emission");
    depth = target(ctx, kDepthFormat, width, height, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, "gbuffer depth");
    gpu::SamplerDesc sd;
    sd.filter = VK_FILTER_NEAREST;
    sd.mipmap = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sd.address = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    pointSampler = gpu::Sampler(ctx, sd);

    gpu::GraphicsDesc g;
    g.vertex = kVert;
    g.fragment = kFrag;
    g.colorFormats = {kColorFormat, kColorFormat, kColorFormat};
    g.depthFormat = kDepthFormat;
    gpu::LayoutDesc layout;
    const VkShaderStageFlags vs = VK_SHADER_STAGE_VERTEX_BIT, fs = VK_SHADER_STAGE_FRAGMENT_BIT;
    layout.bindings = {{sh::BIND_GEOM_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, vs},
                       {sh::BIND_GEOM_DRAWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vs},
                       {sh::BIND_GEOM_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fs}};
    layout.extraSet = scene.textureTable->layout();
    layout.pushConstantBytes = sizeof(sh::DrawPush);
    layout.pushConstantStages = vs;
    pipeline_ = gpu::Pipeline(ctx, g, layout, "gbuffer");
}

uint64_t GBufferPass::memoryBytes() const {
    return base.memorySize() + normal.memorySize() + emission.memorySize() + depth.memorySize();
}

void GBufferPass::record(VkCommandBuffer cmd, const SceneGpu& scene, const gpu::Buffer& frame,
                         gpu::GpuTimers* timers) const {
    gpu::GpuTimerScope timer(timers, cmd, "gbuffer");
    const gpu::Image* colors[3] = {&base, &normal, &emission};
    for (const gpu::Image* c : colors) gpu::transition(cmd, *c, gpu::use::Undefined, gpu::use::ColorAttachment);
    gpu::transition(cmd, depth, gpu::use::Undefined, gpu::use::DepthAttachment);

    VkRenderingAttachmentInfo colorInfo[3];
    for (int i = 0; i < 3; ++i) {
        colorInfo[i] = {VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        colorInfo[i].imageView = colors[i]->view();
        colorInfo[i].imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        colorInfo[i].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;  // emission.a = 0 marks background
        colorInfo[i].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        colorInfo[i].clearValue.color = {{0, 0, 0, 0}};
    }
    VkRenderingAttachmentInfo depthInfo{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depthInfo.imageView = depth.view();
    depthInfo.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depthInfo.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depthInfo.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    depthInfo.clearValue.depthStencil = {1.0f, 0};
    const VkRect2D area{{0, 0}, {width_, height_}};
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = area;
    ri.layerCount = 1;
    ri.colorAttachmentCount = 3;
    ri.pColorAttachments = colorInfo;
    ri.pDepthAttachment = &depthInfo;
    vkCmdBeginRendering(cmd, &ri);

    gpu::bind(cmd, pipeline_);
    gpu::Descriptors()
        .uniformBuffer(sh::BIND_GEOM_FRAME, frame.handle())
        .storageBuffer(sh::BIND_GEOM_DRAWS, scene.draws.handle())
        .storageBuffer(sh::BIND_GEOM_MATERIALS, scene.materials.handle())
        .push(ctx_, cmd, pipeline_);
    scene.bindGeometry(cmd, pipeline_.layout());
    const VkViewport viewport{0, 0, float(width_), float(height_), 0, 1};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &area);
    for (uint32_t i = 0; i < scene.ranges.size(); ++i) {
        const sh::DrawPush push{glm::uvec4(i, 0, 0, 0)};
        gpu::pushConstants(cmd, pipeline_, VK_SHADER_STAGE_VERTEX_BIT, push);
        const DrawRange& r = scene.ranges[i];
        vkCmdDrawIndexed(cmd, r.indexCount, 1, r.firstIndex, r.vertexOffset, 0);
    }
    vkCmdEndRendering(cmd);

    for (const gpu::Image* c : colors) gpu::transition(cmd, *c, gpu::use::ColorAttachment, gpu::use::ShaderRead);
    gpu::transition(cmd, depth, gpu::use::DepthAttachment, gpu::use::DepthRead);
}

}  // namespace dvsgi::render
