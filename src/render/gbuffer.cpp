#include "render/gbuffer.h"

#include "gpu/tracker.h"
#include "gpu/context.h"
#include "gpu/timers.h"
#include "gpuscene/draw_list.h"
#include "gpuscene/scene_gpu.h"
#include "shared/geometry_pass.h"

namespace dvsgi::render {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kVert[] = {
#include "shaders/gbuffer.vert.inc"
};
const uint32_t kFrag[] = {
#include "shaders/gbuffer.frag.inc"
};
const uint32_t kFragAlphaTested[] = {
#include "shaders/gbuffer_alpha_tested.frag.inc"
};
const uint32_t kFragBaseColorOnly[] = {
#include "shaders/gbuffer_base_color_only.frag.inc"
};
const uint32_t kFragAlphaTestedBaseColorOnly[] = {
#include "shaders/gbuffer_alpha_tested_base_color_only.frag.inc"
};

}  // namespace

gpu::Spirv gbufferFragmentShader(bool alphaTested, bool baseColorOnly) {
    if (baseColorOnly) return alphaTested ? gpu::Spirv(kFragAlphaTestedBaseColorOnly) : gpu::Spirv(kFragBaseColorOnly);
    return alphaTested ? gpu::Spirv(kFragAlphaTested) : gpu::Spirv(kFrag);
}

GBufferPass::GBufferPass(const gpu::Context& ctx, const SceneGpu& scene) : ctx_(ctx) {
    constexpr VkFormat kColorFormat = GBuffer::kColorFormat;
    gpu::GraphicsDesc g;
    g.vertex = kVert;
    g.fragment = gbufferFragmentShader(false);
    g.colorFormats = {kColorFormat, kColorFormat, kColorFormat};
    g.depthFormat = GBuffer::kDepthFormat;
    gpu::LayoutDesc layout;
    const VkShaderStageFlags vs = VK_SHADER_STAGE_VERTEX_BIT, fs = VK_SHADER_STAGE_FRAGMENT_BIT;
    layout.bindings = {{sh::BIND_GEOM_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, vs},
                       {sh::BIND_GEOM_DRAWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vs},
                       {sh::BIND_GEOM_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fs}};
    layout.extraSet = scene.textureTable->layout();
    layout.pushConstantBytes = sizeof(sh::DrawPush);
    layout.pushConstantStages = vs;
    opaque_ = gpu::Pipeline(ctx, g, layout, "gbuffer opaque");
    g.fragment = gbufferFragmentShader(true);
    alphaTested_ = gpu::Pipeline(ctx, g, layout, "gbuffer alpha-tested");
    g.fragment = gbufferFragmentShader(false, true);
    opaqueBaseColorOnly_ = gpu::Pipeline(ctx, g, layout, "gbuffer opaque, base colour only");
    g.fragment = gbufferFragmentShader(true, true);
    alphaTestedBaseColorOnly_ = gpu::Pipeline(ctx, g, layout, "gbuffer alpha-tested, base colour only");
}

void GBufferPass::record(VkCommandBuffer cmd, gpu::Tracker& tracker, const SceneGpu& scene,
                         const gpuscene::DrawList& draws, const gpu::Buffer& frame, const GBuffer& out,
                         gpu::GpuTimers* timers) const {
    gpu::GpuTimerScope timer(timers, cmd, "gbuffer");
    const gpu::Image* colors[3] = {&out.base, &out.normal, &out.emission};
    for (const gpu::Image* c : colors) tracker.image(*c, gpu::use::ColorAttachment, true);
    tracker.image(out.depth, gpu::use::DepthAttachment, true).flush(cmd);
    const uint32_t width = out.depth.desc().extent.width, height = out.depth.desc().extent.height;

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
    depthInfo.imageView = out.depth.view();
    depthInfo.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depthInfo.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depthInfo.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    depthInfo.clearValue.depthStencil = {1.0f, 0};
    const VkRect2D area{{0, 0}, {width, height}};
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = area;
    ri.layerCount = 1;
    ri.colorAttachmentCount = 3;
    ri.pColorAttachments = colorInfo;
    ri.pDepthAttachment = &depthInfo;
    vkCmdBeginRendering(cmd, &ri);

    // All four pipelines share one layout, so descriptors pushed once serve them all.
    gpu::bind(cmd, opaque_);
    gpu::Descriptors()
        .uniformBuffer(sh::BIND_GEOM_FRAME, frame.handle())
        .storageBuffer(sh::BIND_GEOM_DRAWS, scene.draws.handle())
        .storageBuffer(sh::BIND_GEOM_MATERIALS, scene.materials.handle())
        .push(ctx_, cmd, opaque_);
    scene.bindGeometry(cmd, opaque_.layout());
    const VkViewport viewport{0, 0, float(width), float(height), 0, 1};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &area);
    gpuscene::recordDraws(cmd, draws, {opaque_, alphaTested_, &opaqueBaseColorOnly_, &alphaTestedBaseColorOnly_}, 0);
    vkCmdEndRendering(cmd);
}

}  // namespace dvsgi::render
