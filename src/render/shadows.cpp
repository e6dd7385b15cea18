#include "render/shadows.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

#include "gpu/tracker.h"
#include "gpu/context.h"
#include "gpu/timers.h"
#include "gpuscene/draw_list.h"
#include "gpuscene/scene_gpu.h"
#include "shared/geometry_pass.h"
#include "shared/scene_data.h"
#include "shared/shadow_pass.h"

namespace dvsgi::render {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kShadowVert[] = {
#include "shaders/shadow.vert.inc"
};
const uint32_t kShadowFrag[] = {
#include "shaders/shadow.frag.inc"
};
const uint32_t kShadowAlphaTestedFrag[] = {
#include "shaders/shadow_alpha_tested.frag.inc"
};

constexpr VkFormat kGradientFormat = VK_FORMAT_R16G16_SFLOAT;

glm::vec3 upFor(glm::vec3 dir) {
    return std::abs(dir.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
}

sh::GpuShadowView perspectiveView(glm::vec3 eye, glm::vec3 dir, float fov, float nearZ, float farZ, uint32_t size) {
    sh::GpuShadowView v{};
    v.viewProj = glm::perspective(fov, 1.0f, nearZ, farZ) * glm::lookAt(eye, eye + dir, upFor(dir));
    v.params = glm::vec4(2.0f * std::tan(fov * 0.5f) / float(size), 1.0f, 0.0f, 0.0f);
    return v;
}

// An orthographic view along `dir` whose square covers the sphere (centre,
// radius) and whose depth range covers the scene's sphere (everything that can
// cast a shadow into it). The centre moves in whole texels across the light's
// view, so a focus that follows the camera does not make the shadows shimmer.
sh::GpuShadowView orthoView(glm::vec3 dir, glm::vec3 centre, float radius, glm::vec3 sceneCentre, float sceneRadius,
                            uint32_t size) {
    const float texel = 2.0f * radius / float(size);
    const glm::mat4 turn = glm::lookAt(glm::vec3(0.0f), dir, upFor(dir));
    glm::vec3 c = glm::vec3(turn * glm::vec4(centre, 1.0f));
    c.x = std::round(c.x / texel) * texel;
    c.y = std::round(c.y / texel) * texel;
    centre = glm::vec3(glm::inverse(turn) * glm::vec4(c, 1.0f));
    const float along = glm::dot(sceneCentre - centre, dir);
    const float margin = sceneRadius * 0.01f;
    const float front = along - sceneRadius - margin, back = along + sceneRadius + margin;
    const glm::vec3 eye = centre + dir * (front - margin);
    sh::GpuShadowView v{};
    v.viewProj = glm::ortho(-radius, radius, -radius, radius, margin, back - front + margin) *
                 glm::lookAt(eye, eye + dir, upFor(dir));
    v.params = glm::vec4(texel, 0.0f, 0.0f, 0.0f);
    return v;
}

}  // namespace

float shadowFocusRadius(const scene::Bounds& bounds, float halfSide) {
    if (!bounds.valid()) return 0.0f;
    const float sceneRadius = glm::length(bounds.max - bounds.min) * 0.5f;
    return halfSide > 0.0f && halfSide < kShadowFocusFraction * sceneRadius ? halfSide : 0.0f;
}

LightSetup setupLights(const std::vector<scene::PlacedLight>& lights, const scene::Bounds& bounds,
                       uint32_t shadowMapSize, bool shadows, const ShadowFocus& focus) {
    LightSetup out;
    const glm::vec3 center = bounds.valid() ? (bounds.min + bounds.max) * 0.5f : glm::vec3(0.0f);
    const float radius = bounds.valid() ? std::max(glm::length(bounds.max - bounds.min) * 0.5f, 1e-3f) : 1.0f;
    for (const scene::PlacedLight& pl : lights) {
        const scene::Light& l = pl.light;
        sh::GpuLight g{};
        g.position = glm::vec4(pl.position, float(uint32_t(l.type)));
        g.direction = glm::vec4(glm::normalize(pl.direction), std::cos(l.outerConeAngle));
        g.radiant = glm::vec4(l.color * l.intensity, std::cos(l.innerConeAngle));
        g.shadow = glm::uvec4(uint32_t(out.views.size()), 0u, 0u, 0u);
        if (shadows && bounds.valid()) {
            const glm::vec3 dir = glm::vec3(g.direction);
            // Depth range: from just in front of the light to the far side of the scene.
            const float farZ = glm::length(pl.position - center) + radius * 1.01f;
            const float nearZ = std::max(radius * 2e-3f, 1e-4f);
            if (l.type == scene::LightType::Directional) {
                if (focus.radius > 0.0f) {
                    out.views.push_back(orthoView(dir, focus.centre, focus.radius, center, radius, shadowMapSize));
                    g.shadow.y = 1;
                }
                sh::GpuShadowView v{};
                const glm::vec3 eye = center - dir * (2.0f * radius);
                v.viewProj = glm::ortho(-radius, radius, -radius, radius, radius * 0.5f, radius * 3.5f) *
                             glm::lookAt(eye, center, upFor(dir));
                v.params = glm::vec4(2.0f * radius / float(shadowMapSize), 0.0f, 0.0f, 0.0f);
                out.views.push_back(v);
                g.shadow.y += 1;
            } else if (l.type == scene::LightType::Spot) {
                const float fov = std::min(2.0f * l.outerConeAngle * 1.05f, glm::radians(170.0f));
                out.views.push_back(perspectiveView(pl.position, dir, fov, nearZ, farZ, shadowMapSize));
                g.shadow.y = 1;
            } else {
                const glm::vec3 faces[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
                for (const glm::vec3& f : faces)
                    out.views.push_back(perspectiveView(pl.position, f, glm::radians(90.0f), nearZ, farZ, shadowMapSize));
                g.shadow.y = 6;
            }
        }
        out.lights.push_back(g);
    }
    return out;
}

ShadowPass::ShadowPass(const gpu::Context& ctx, const SceneGpu& scene) : ctx_(ctx) {
    gpu::GraphicsDesc g;
    g.vertex = kShadowVert;
    g.fragment = kShadowFrag;
    g.colorFormats = {kGradientFormat};
    g.depthFormat = VK_FORMAT_D32_SFLOAT;
    g.depthBias = true;
    gpu::LayoutDesc layout;
    const VkShaderStageFlags vs = VK_SHADER_STAGE_VERTEX_BIT, fs = VK_SHADER_STAGE_FRAGMENT_BIT;
    layout.bindings = {{sh::BIND_GEOM_DRAWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vs},
                       {sh::BIND_GEOM_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fs},
                       {sh::BIND_GEOM_SHADOW_VIEWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vs}};
    layout.extraSet = scene.textureTable->layout();
    layout.pushConstantBytes = sizeof(sh::DrawPush);
    layout.pushConstantStages = vs;
    opaque_ = gpu::Pipeline(ctx, g, layout, "shadow opaque");
    g.fragment = kShadowAlphaTestedFrag;
    alphaTested_ = gpu::Pipeline(ctx, g, layout, "shadow alpha-tested");
    for (const gpuscene::DrawRange& r : scene.ranges) hasDynamic_ = hasDynamic_ || r.dynamic;
}

void ShadowPass::record(VkCommandBuffer cmd, gpu::Tracker& tracker, const SceneGpu& scene, const gpu::Buffer& views,
                        const std::vector<sh::GpuShadowView>& hostViews, const ShadowTargets& map,
                        StaticShadows statics, gpu::GpuTimers* timers) {
    gpu::GpuTimerScope timer(timers, cmd, "shadow maps");
    const uint32_t viewCount = uint32_t(hostViews.size());
    // A layer's static depth is reused where its view is the one it was
    // rendered with (one light moving, or a focus that follows the camera,
    // leaves the other layers alone).
    std::vector<bool> stale(viewCount, true);
    reusedLayers_ = 0;
    drawnTriangles_ = 0;
    if (statics == StaticShadows::Kept && keptMap_ == map.depth.serial())
        for (uint32_t v = 0; v < viewCount && v < keptViews_.size(); ++v) {
            stale[v] = std::memcmp(&hostViews[v], &keptViews_[v], sizeof(sh::GpuShadowView)) != 0;
            reusedLayers_ += !stale[v];
        }
    // Nothing is kept across a frame without views (shadows off) or one that
    // keeps nothing: static geometry may move meanwhile.
    keptMap_ = 0;
    keptViews_.clear();
    if (viewCount == 0) return;
    if (statics == StaticShadows::Uncached) {
        render(cmd, tracker, scene, views, hostViews, map, gpuscene::DrawFilter::All, true, nullptr);
        return;
    }
    const bool anyStale = reusedLayers_ < viewCount;
    // Every layer stale: render them all, and the image's old contents may go.
    const std::vector<bool>* layers = reusedLayers_ > 0 ? &stale : nullptr;
    if (!hasDynamic_) {
        if (anyStale) render(cmd, tracker, scene, views, hostViews, map, gpuscene::DrawFilter::All, true, layers);
    } else {
        if (anyStale) {
            if (!cache_.handle()) {
                gpu::ImageDesc d = map.depth.desc();
                d.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
                d.name = "shadow map static cache";
                cache_ = gpu::Image(ctx_, d);
                d = map.gradient.desc();
                d.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
                d.name = "shadow gradient static cache";
                gradientCache_ = gpu::Image(ctx_, d);
            }
            render(cmd, tracker, scene, views, hostViews, {cache_, gradientCache_}, gpuscene::DrawFilter::Static, true,
                   layers);
        }
        copyLayers(cmd, tracker, cache_, map.depth, VK_IMAGE_ASPECT_DEPTH_BIT, viewCount);
        copyLayers(cmd, tracker, gradientCache_, map.gradient, VK_IMAGE_ASPECT_COLOR_BIT, viewCount);
        render(cmd, tracker, scene, views, hostViews, map, gpuscene::DrawFilter::Dynamic, false, nullptr);
    }
    keptViews_ = hostViews;
    keptMap_ = map.depth.serial();
}

void ShadowPass::copyLayers(VkCommandBuffer cmd, gpu::Tracker& tracker, const gpu::Image& from, const gpu::Image& to,
                            VkImageAspectFlags aspect, uint32_t layers) const {
    tracker.image(from, gpu::use::TransferSrc).image(to, gpu::use::TransferDst, true).flush(cmd);
    VkImageCopy region{};
    region.srcSubresource = {aspect, 0, 0, layers};
    region.dstSubresource = region.srcSubresource;
    region.extent = from.desc().extent;
    vkCmdCopyImage(cmd, from.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to.handle(),
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
}

void ShadowPass::render(VkCommandBuffer cmd, gpu::Tracker& tracker, const SceneGpu& scene, const gpu::Buffer& views,
                        const std::vector<sh::GpuShadowView>& hostViews, const ShadowTargets& map,
                        gpuscene::DrawFilter draws, bool clear, const std::vector<bool>* layers) {
    // Discarding the images' contents is right only when every layer is rendered again.
    tracker.image(map.depth, gpu::use::DepthAttachment, clear && !layers)
        .image(map.gradient, gpu::use::ColorAttachment, clear && !layers)
        .flush(cmd);
    const uint32_t size = map.depth.desc().extent.width;
    // Both pipelines share one layout, so descriptors pushed once serve both.
    gpu::bind(cmd, opaque_);
    gpu::Descriptors()
        .storageBuffer(sh::BIND_GEOM_DRAWS, scene.draws.handle())
        .storageBuffer(sh::BIND_GEOM_MATERIALS, scene.materials.handle())
        .storageBuffer(sh::BIND_GEOM_SHADOW_VIEWS, views.handle())
        .push(ctx_, cmd, opaque_);
    scene.bindGeometry(cmd, opaque_.layout());
    const VkViewport viewport{0, 0, float(size), float(size), 0, 1};
    const VkRect2D scissor{{0, 0}, {size, size}};
    // No slope-scaled bias: the lookup extends each caster's plane to the receiver (shared/shadow_pass.h).
    vkCmdSetDepthBias(cmd, sh::SHADOW_CONSTANT_BIAS, 0.0f, 0.0f);

    for (uint32_t v = 0; v < hostViews.size(); ++v) {
        if (layers && !(*layers)[v]) continue;
        VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        depth.imageView = map.depth.layerView(v);
        depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
        depth.loadOp = clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
        depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        depth.clearValue.depthStencil = {1.0f, 0};
        VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
        ri.renderArea = scissor;
        ri.layerCount = 1;
        ri.pDepthAttachment = &depth;
        // Cleared texels have no caster: a flat "plane" at the far depth.
        VkRenderingAttachmentInfo gradient = depth;
        gradient.imageView = map.gradient.layerView(v);
        gradient.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        gradient.clearValue.color = {{0.0f, 0.0f, 0.0f, 0.0f}};
        ri.colorAttachmentCount = 1;
        ri.pColorAttachments = &gradient;
        vkCmdBeginRendering(cmd, &ri);
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        // Each view rasterizes only what reaches its frustum (a point light's face: 90 degrees of it).
        const gpuscene::DrawList list = gpuscene::visibleDraws(scene, hostViews[v].viewProj, draws);
        drawnTriangles_ += list.triangles();
        gpuscene::recordDraws(cmd, list, {opaque_, alphaTested_}, v);
        vkCmdEndRendering(cmd);
    }
}

}  // namespace dvsgi::render
