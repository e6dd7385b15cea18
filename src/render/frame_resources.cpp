#include "render/frame_resources.h"

#include <algorithm>
#include <cmath>

namespace dvsgi::render {

namespace {

gpu::Image image2D(const gpu::Context& ctx, VkFormat format, uint32_t w, uint32_t h, VkImageUsageFlags usage,
                   const char* name, uint32_t layers = 1) {
    gpu::ImageDesc d;
    d.format = format;
    d.extent = {w, h, 1};
    d.layers = layers;
    d.usage = usage;
    d.name = name;
    return gpu::Image(ctx, d);
}

}  // namespace

uint64_t GBuffer::memoryBytes() const {
    return base.memorySize() + normal.memorySize() + emission.memorySize() + depth.memorySize();
}

uint64_t TemporalHistory::memoryBytes() const {
    uint64_t bytes = 0;
    for (int i = 0; i < 2; ++i) bytes += color[i].memorySize() + surface[i].memorySize();
    return bytes;
}

uint32_t FrameSize::traceWidth() const { return std::max(1u, uint32_t(std::lround(internalWidth() * traceScale))); }
uint32_t FrameSize::traceHeight() const { return std::max(1u, uint32_t(std::lround(internalHeight() * traceScale))); }

GBuffer createGBuffer(const gpu::Context& ctx, uint32_t width, uint32_t height, bool light) {
    const VkImageUsageFlags read = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    const VkImageUsageFlags color = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | read;
    GBuffer g;
    g.base = image2D(ctx, GBuffer::kColorFormat, width, height, color, light ? "rsm base colour" : "gbuffer base colour");
    g.normal = image2D(ctx, GBuffer::kColorFormat, width, height, color, light ? "rsm normal" : "gbuffer normal");
    g.emission = image2D(ctx, GBuffer::kColorFormat, width, height, color, light ? "rsm emission" : "gbuffer emission");
    g.depth = image2D(ctx, GBuffer::kDepthFormat, width, height, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | read,
                      light ? "rsm depth" : "gbuffer depth");
    return g;
}

FrameTargets createFrameTargets(const gpu::Context& ctx, const FrameSize& s) {
    const uint32_t iw = s.internalWidth(), ih = s.internalHeight();
    const VkImageUsageFlags storage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    FrameTargets t;
    t.gbuffer = createGBuffer(ctx, iw, ih);
    t.shadowMap = image2D(ctx, VK_FORMAT_D32_SFLOAT, s.shadowMapSize, s.shadowMapSize,
                          VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                              VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                          "shadow map array",
                          std::max(s.shadowViews, 2u));
    t.shadowGradient = image2D(ctx, VK_FORMAT_R16G16_SFLOAT, s.shadowMapSize, s.shadowMapSize,
                               VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                   VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                               "shadow gradient array", std::max(s.shadowViews, 2u));
    t.direct = image2D(ctx, VK_FORMAT_R32G32B32A32_SFLOAT, iw, ih, storage, "direct radiance");
    t.visibility = image2D(ctx, VK_FORMAT_R16_SFLOAT, iw, ih, storage, "light visibility");
    t.diffuse = image2D(ctx, VK_FORMAT_R16G16B16A16_SFLOAT, iw, ih, storage, "indirect diffuse");
    t.specular = image2D(ctx, VK_FORMAT_R16G16B16A16_SFLOAT, iw, ih, storage, "specular");
    t.traceWidth = s.traceWidth();
    t.traceHeight = s.traceHeight();
    if (t.traceWidth != iw || t.traceHeight != ih) {
        t.traceDiffuse = image2D(ctx, VK_FORMAT_R16G16B16A16_SFLOAT, t.traceWidth, t.traceHeight, storage,
                                 "indirect diffuse (trace size)");
        t.traceSpecular = image2D(ctx, VK_FORMAT_R16G16B16A16_SFLOAT, t.traceWidth, t.traceHeight, storage,
                                  "specular (trace size)");
    }
    t.turnedDiffuse = image2D(ctx, VK_FORMAT_R16G16B16A16_SFLOAT, t.traceWidth, t.traceHeight, storage,
                              "indirect diffuse (turned cones)");
    t.output = image2D(ctx, VK_FORMAT_R32G32B32A32_SFLOAT, s.width, s.height, storage, "output");
    if (s.temporalHistory)
        for (int i = 0; i < 2; ++i) {
            t.temporal.color[i] = image2D(ctx, VK_FORMAT_R32G32B32A32_SFLOAT, iw, ih, storage,
                                          i == 0 ? "indirect history 0" : "indirect history 1");
            t.temporal.surface[i] = image2D(ctx, VK_FORMAT_R16G16B16A16_SFLOAT, iw, ih, storage,
                                            i == 0 ? "history surface 0" : "history surface 1");
        }
    return t;
}

Samplers createSamplers(const gpu::Context& ctx) {
    Samplers s;
    gpu::SamplerDesc point;
    point.filter = VK_FILTER_NEAREST;
    point.mipmap = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    point.address = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    s.point = gpu::Sampler(ctx, point);
    // Outside the grid is empty: a transparent border, so coarse cells on the
    // grid's edge fade into nothing instead of repeating themselves beyond it.
    gpu::SamplerDesc volume;
    volume.address = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
    volume.transparentBorder = true;
    s.volume = gpu::Sampler(ctx, volume);
    return s;
}

}  // namespace dvsgi::render
