// The public facade (include/dvsgi/dvsgi.h) over scene::, render:: and gpu::.
// It owns the mapping from the small public Settings to render::RenderSettings
// and turns every internal exception into dvsgi::Error naming the setting.
#include "dvsgi/dvsgi.h"

#include <string_view>
#include <utility>

#include "gpu/barriers.h"
#include "gpu/check.h"
#include "gpu/context.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/load.h"
#include "shared/composite_pass.h"

#ifndef DVSGI_VERSION
#define DVSGI_VERSION "unknown"
#endif

namespace dvsgi {

namespace {

// Internal messages about a setting start with the setting's name as
// `dvsgi render` spells it ("voxels: ..."); a library user sees the public
// field instead, or a description of a setting the public API does not expose.
std::string settingNames(std::string message) {
    static const std::pair<std::string_view, const char*> names[] = {
        {"width", "Settings::width"},           {"height", "Settings::height"},
        {"supersample", "Settings::supersample"}, {"camera", "Settings::camera"},
        {"voxels", "Settings::voxels"},         {"shadow-map", "Settings::shadowMapSize"},
        {"device", "DeviceOptions::deviceName"}, {"validate", "DeviceOptions::validation"},
        {"shadows", "shadow cones"},            {"light-occlusion", "light occlusion"},
        {"view", "voxel view"},                 {"clipmap", "Settings::clipmapLevels"},
    };
    const size_t colon = message.find(':');
    for (const auto& [setting, name] : names)
        if (colon != std::string::npos && std::string_view(message).substr(0, colon) == setting)
            return name + message.substr(colon);
    return message;
}

// Runs `f`, rethrowing anything but dvsgi::Error as dvsgi::Error.
template <class F>
auto guarded(F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(settingNames(e.what()));
    }
}

[[noreturn]] void badSetting(const char* name, const std::string& expected, const std::string& got) {
    throw Error(std::string("Settings::") + name + ": expected " + expected + ", got " + got);
}

bool powerOfTwo(uint32_t n) { return n != 0 && (n & (n - 1)) == 0; }

// The same ranges as `dvsgi render` (app/settings_entries*.cpp), so both accept the same settings.
void validate(const Settings& s, uint32_t cameras) {
    if (s.width < 1 || s.width > 16384) badSetting("width", "1..16384", std::to_string(s.width));
    if (s.height < 1 || s.height > 16384) badSetting("height", "1..16384", std::to_string(s.height));
    if (s.supersample < 1 || s.supersample > 8) badSetting("supersample", "1..8", std::to_string(s.supersample));
    if (s.camera >= cameras)
        badSetting("camera", "an index below the scene's " + std::to_string(cameras) + " camera(s)",
                   std::to_string(s.camera));
    if (s.voxels != 0 && (s.voxels < 32 || s.voxels > 512 || !powerOfTwo(s.voxels)))
        badSetting("voxels", "0 or a power of two in 32..512", std::to_string(s.voxels));
    if (s.clipmapLevels > 8) badSetting("clipmapLevels", "0..8", std::to_string(s.clipmapLevels));
    if (!(s.clipmapVoxel >= 0.0f && s.clipmapVoxel <= 1000.0f))
        badSetting("clipmapVoxel", "0..1000 (metres)", std::to_string(s.clipmapVoxel));
    if (s.bounces < -1 || s.bounces > 64) badSetting("bounces", "-1 (auto) or 0..64", std::to_string(s.bounces));
    if (!(s.bounceConvergence >= 1e-5f && s.bounceConvergence <= 0.5f))
        badSetting("bounceConvergence", "0.00001..0.5", std::to_string(s.bounceConvergence));
    if (s.maxBounces < 1 || s.maxBounces > 1000) badSetting("maxBounces", "1..1000", std::to_string(s.maxBounces));
    if (s.bounceTrace != Trace::Rays && s.bounceTrace != Trace::Cones)
        badSetting("bounceTrace", "Trace::Rays or Trace::Cones", std::to_string(int(s.bounceTrace)));
    if (s.gatherTrace != Trace::Rays && s.gatherTrace != Trace::Cones)
        badSetting("gatherTrace", "Trace::Rays or Trace::Cones", std::to_string(int(s.gatherTrace)));
    if (s.gatherRays < 1 || s.gatherRays > 1024) badSetting("gatherRays", "1..1024", std::to_string(s.gatherRays));
    if (s.gatherRayFilter < 1 || s.gatherRayFilter > 5)
        badSetting("gatherRayFilter", "1..5", std::to_string(s.gatherRayFilter));
    if (s.cones != 6 && s.cones != 16) badSetting("cones", "6 or 16", std::to_string(s.cones));
    if (!(s.aoLambda >= 0.0f && s.aoLambda <= 1000.0f))
        badSetting("aoLambda", "0..1000", std::to_string(s.aoLambda));
    if (!(s.traceScale >= 0.125f && s.traceScale <= 1.0f))
        badSetting("traceScale", "0.125..1", std::to_string(s.traceScale));
    if (s.shadowMapSize < 256 || s.shadowMapSize > 8192 || !powerOfTwo(s.shadowMapSize))
        badSetting("shadowMapSize", "a power of two in 256..8192", std::to_string(s.shadowMapSize));
    if (int(s.output) < 0 || int(s.output) > int(Output::Shadow))
        badSetting("output", "an Output value", std::to_string(int(s.output)));
}

// The library's defaults (render::RenderSettings' initialisers, which the CLI
// also starts from) with the public settings on top, so both give the same
// image for the same values; tests/api checks it against `dvsgi render`.
render::RenderSettings toRenderSettings(const Settings& s) {
    render::RenderSettings rs;
    rs.width = s.width;
    rs.height = s.height;
    rs.supersample = s.supersample;
    rs.shadowMapSize = s.shadowMapSize;
    rs.camera = int(s.camera);
    rs.voxels = s.voxels;
    rs.clipmap.levels = s.clipmapLevels;
    rs.clipmap.voxelSize = s.clipmapVoxel;
    rs.voxelLight.bounceMode = s.bounces < 0 ? vxgi::BounceMode::Converge : vxgi::BounceMode::Fixed;
    if (s.bounces >= 0) rs.voxelLight.bounces = uint32_t(s.bounces);
    rs.voxelLight.convergence = s.bounceConvergence;
    rs.voxelLight.maxBounces = s.maxBounces;
    rs.voxelLight.bounceTrace = s.bounceTrace == Trace::Rays ? vxgi::BounceTrace::Rays : vxgi::BounceTrace::Cones;
    rs.gather.trace = s.gatherTrace == Trace::Rays ? render::GatherTrace::Rays : render::GatherTrace::Cones;
    rs.gather.rays = s.gatherRays;
    rs.gather.rayFilterPasses = s.gatherRayFilter;
    rs.cones.coneSet = s.cones;
    rs.gather.aoLambda = s.aoLambda;
    rs.gather.specular = s.specular;
    rs.gather.traceScale = s.traceScale;
    rs.applyAO = s.ao;
    static_assert(uint32_t(Output::Shadow) == shader::TERM_SHADOW && uint32_t(Output::AO) == shader::TERM_AO &&
                  uint32_t(Output::Full) == shader::TERM_FULL);
    rs.outputTerm = uint32_t(s.output);
    return rs;
}

VkImageMemoryBarrier2 layoutBarrier(VkImage image, VkImageLayout from, VkImageLayout to) {
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.image = image;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    return b;
}

void barrier(VkCommandBuffer cmd, const VkImageMemoryBarrier2& b) {
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);
}

void checkTarget(const gpu::Context& ctx, const TargetImage& t, bool exact) {
    if (!t.image) throw Error("TargetImage::image: VK_NULL_HANDLE");
    if (t.width == 0 || t.height == 0) throw Error("TargetImage::width/height: the size must not be 0");
    if (t.finalLayout == VK_IMAGE_LAYOUT_UNDEFINED || t.finalLayout == VK_IMAGE_LAYOUT_PREINITIALIZED)
        throw Error("TargetImage::finalLayout: must be a layout the image can be left in, not UNDEFINED/PREINITIALIZED");
    if (exact) return;
    VkFormatProperties fp;
    vkGetPhysicalDeviceFormatProperties(ctx.physical, t.format, &fp);
    if (!(fp.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT))
        throw Error("TargetImage::format: VkFormat " + std::to_string(int(t.format)) +
                    " cannot be a blit destination on " + ctx.deviceName +
                    " (use R32G32B32A32_SFLOAT at the output size for an exact copy)");
}

// Copy or blit of the RGBA32F output, which the renderer keeps in
// gpu::use::ComputeWrite between frames, into the application's image.
void copyOutput(const gpu::Context& ctx, const gpu::Image& output, const TargetImage& t) {
    const VkExtent3D e = output.desc().extent;
    const bool exact = t.format == VK_FORMAT_R32G32B32A32_SFLOAT && t.width == e.width && t.height == e.height;
    checkTarget(ctx, t, exact);
    VkFormatProperties src;
    vkGetPhysicalDeviceFormatProperties(ctx.physical, output.desc().format, &src);
    const bool sameSize = t.width == e.width && t.height == e.height;
    const VkFilter filter = !sameSize && (src.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT)
                                ? VK_FILTER_LINEAR
                                : VK_FILTER_NEAREST;
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        gpu::transition(cmd, output, gpu::use::ComputeWrite, gpu::use::TransferSrc);
        // ALL_COMMANDS / MEMORY_* as the first scope: whatever the application
        // did with the image before, on this queue, is finished and visible.
        VkImageMemoryBarrier2 in = layoutBarrier(t.image, t.currentLayout, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        in.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        in.srcAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
        in.dstStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
        in.dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        barrier(cmd, in);
        const VkImageSubresourceLayers layer{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        if (exact) {
            VkImageCopy region{};
            region.srcSubresource = region.dstSubresource = layer;
            region.extent = {t.width, t.height, 1};
            vkCmdCopyImage(cmd, output.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, t.image,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        } else {
            VkImageBlit blit{};
            blit.srcSubresource = blit.dstSubresource = layer;
            blit.srcOffsets[1] = {int32_t(e.width), int32_t(e.height), 1};
            blit.dstOffsets[1] = {int32_t(t.width), int32_t(t.height), 1};
            vkCmdBlitImage(cmd, output.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, t.image,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, filter);
        }
        VkImageMemoryBarrier2 out = layoutBarrier(t.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, t.finalLayout);
        out.srcStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
        out.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        out.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        out.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
        barrier(cmd, out);
        gpu::transition(cmd, output, gpu::use::TransferSrc, gpu::use::ComputeWrite);
    });
}

}  // namespace

std::string version() { return DVSGI_VERSION; }

// ---- Scene ----

struct Scene::Data {
    scene::Scene scene;
    uint32_t cameras = 0;
};

namespace {
// A template so that only the members of Scene, which may, name Scene::Data.
template <class Data>
std::shared_ptr<const Data> makeData(scene::Scene s) {
    auto d = std::make_shared<Data>();
    // The renderer picks among placed cameras (camera nodes), not the camera list.
    d->cameras = uint32_t(scene::placedCameras(s, scene::worldMatrices(s)).size());
    d->scene = std::move(s);
    return d;
}
}  // namespace

Scene Scene::load(const std::string& path) {
    return guarded([&] { return Scene(makeData<Data>(scene::loadScene(path))); });
}

Scene Scene::cornellBox() {
    return guarded([&] { return Scene(makeData<Data>(scene::builtinCornellBox())); });
}

const std::string& Scene::source() const { return data_->scene.source; }
const std::vector<std::string>& Scene::warnings() const { return data_->scene.warnings; }
uint32_t Scene::cameraCount() const { return data_->cameras; }
uint32_t Scene::lightCount() const { return uint32_t(data_->scene.lights.size()); }

// ---- Renderer ----

struct Renderer::Impl {
    std::shared_ptr<const Scene::Data> scene;
    Settings settings;
    std::unique_ptr<gpu::Context> ctx;
    std::unique_ptr<render::Renderer> renderer;
    bool haveFrame = false;

    void build(const Settings& s) {
        validate(s, scene->cameras);
        renderer.reset();  // free the old resources before allocating new ones
        haveFrame = false;
        renderer = std::make_unique<render::Renderer>(*ctx, scene->scene, toRenderSettings(s));
        settings = s;
    }
    // After a failed setSettings() (e.g. out of memory) there is no renderer
    // until a later setSettings() succeeds.
    render::Renderer& live() const {
        if (!renderer) throw Error("Renderer: no renderer for the current settings (setSettings failed)");
        return *renderer;
    }
    const render::Renderer& frame() const {
        if (!haveFrame) throw Error("Renderer: no frame yet (call render() first)");
        return live();
    }
};

Renderer::Renderer(const Scene& scene, const Settings& settings, const DeviceOptions& device)
    : impl_(std::make_unique<Impl>()) {
    guarded([&] {
        impl_->scene = scene.data_;
        validate(settings, scene.data_->cameras);
        gpu::ContextOptions co;
        co.validation = device.validation;
        co.deviceName = device.deviceName;
        co.printDevice = device.printDevice;
        impl_->ctx = std::make_unique<gpu::Context>(co);
        impl_->build(settings);
    });
}

Renderer::Renderer(const Scene& scene, const Settings& settings, const ExternalDevice& device)
    : impl_(std::make_unique<Impl>()) {
    guarded([&] {
        impl_->scene = scene.data_;
        validate(settings, scene.data_->cameras);
        gpu::ExternalDevice ext;
        ext.instance = device.instance;
        ext.physical = device.physicalDevice;
        ext.device = device.device;
        ext.queueFamily = device.queueFamily;
        ext.queue = device.queue;
        ext.shaderImageFloat32AtomicAdd = device.shaderImageFloat32AtomicAdd;
        ext.conservativeRasterization = device.conservativeRasterization;
        ext.samplerAnisotropy = device.samplerAnisotropy;
        ext.shaderFloat64 = device.shaderFloat64;
        ext.debugUtils = device.debugUtils;
        impl_->ctx = std::make_unique<gpu::Context>(ext, gpu::ContextOptions{});
        impl_->build(settings);
    });
}

Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

void Renderer::setSettings(const Settings& settings) {
    guarded([&] { impl_->build(settings); });
}

const Settings& Renderer::settings() const { return impl_->settings; }

FrameInfo Renderer::render() {
    return guarded([&] {
        const render::FrameStats stats = impl_->live().renderFrame();
        impl_->haveFrame = true;
        FrameInfo info;
        for (const gpu::TimerResult& r : stats.passes) info.passes.push_back({r.name, r.ms});
        info.gpuMs = stats.gpuMs;
        info.bounces = stats.bounces;
        info.converged = stats.converged;
        return info;
    });
}

Image Renderer::readImage() const {
    return guarded([&] {
        image::ImageRGBA32F img = impl_->frame().readOutput();
        return Image{img.width, img.height, std::move(img.rgba)};
    });
}

void Renderer::copyTo(const TargetImage& target) const {
    guarded([&] { copyOutput(*impl_->ctx, impl_->frame().outputImage(), target); });
}

FrameInfo Renderer::renderTo(const TargetImage& target) {
    FrameInfo info = render();
    copyTo(target);
    return info;
}

std::vector<MemoryUse> Renderer::memory() const {
    std::vector<MemoryUse> out;
    for (const render::MemoryItem& m : impl_->live().memory()) out.push_back({m.name, m.bytes});
    return out;
}

std::string Renderer::deviceName() const { return impl_->ctx->deviceName; }

uint32_t Renderer::validationErrors() const { return impl_->ctx->validationErrors(); }

std::vector<std::string> Renderer::warnings() const {
    std::vector<std::string> out = impl_->scene->scene.warnings;
    for (const std::string& w : impl_->live().warnings()) out.push_back(w);
    return out;
}

void writeExr(const std::string& path, const Image& img, bool half) {
    guarded([&] {
        if (img.rgba.size() != size_t(img.width) * img.height * 4)
            throw Error(path + ": Image::rgba holds " + std::to_string(img.rgba.size()) + " floats, not width*height*4");
        image::ImageRGBA32F im;
        im.width = img.width;
        im.height = img.height;
        im.rgba = img.rgba;
        image::ExrOptions o;
        o.type = half ? image::PixelType::Half : image::PixelType::Float;
        image::writeExr(path, im, o);
    });
}

}  // namespace dvsgi
