#include "render/renderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "gpu/tracker.h"
#include "gpu/context.h"
#include "gpu/transfer.h"
#include "gpuscene/draw_list.h"
#include "render/composite.h"
#include "render/emitters.h"
#include "render/gbuffer.h"
#include "render/lighting.h"
#include "gpuscene/scene_gpu.h"
#include "render/shadows.h"
#include "shared/bounce_pass.h"
#include "shared/scene_data.h"
#include "shared/voxel_list_pass.h"
#include "vxgi/aniso_filter.h"
#include "vxgi/voxel_list.h"
#include "vxgi/bounce.h"
#include "vxgi/inject.h"
#include "vxgi/voxelize.h"

namespace dvsgi::render {

namespace sh = dvsgi::shader;

namespace {

// Timing scopes one frame may record. Converging records three per bounce
// with a fitted grid (frame, bounce, filtering); with a clipmap each bounce
// runs level after level (a scratch clear, the bounce, the filter and an
// atlas copy per level, then the fold), and each level adds its own
// voxelization, scroll and light passes to the frame.
uint32_t timerScopes(const RenderSettings& s) {
    const uint32_t levels = s.voxels > 0 ? s.clipmap.levels : 0;
    const uint32_t bounces = std::max({s.voxelLight.maxBounces, s.voxelLight.bounces, 1u});
    return 64 + 16 * levels + (3 + 5 * levels) * bounces;
}

}  // namespace

glm::mat4 viewMatrix(const scene::PlacedCamera& camera) { return glm::inverse(camera.world); }

glm::mat4 projectionMatrix(const scene::PlacedCamera& camera, uint32_t width, uint32_t height) {
    const float aspect = float(width) / float(height);
    glm::mat4 p = glm::perspective(camera.camera.yfov, aspect, camera.camera.znear, camera.camera.zfar);
    p[1][1] *= -1.0f;
    return p;
}

Renderer::Renderer(const gpu::Context& ctx, const scene::Scene& sceneIn, const RenderSettings& settings)
    : ctx_(ctx), scene_(sceneIn), settings_(settings) {
    const scene::Scene& scene = scene_;
    const std::vector<glm::mat4> world = scene::worldMatrices(scene);
    const std::vector<scene::PlacedCamera> cameras = scene::placedCameras(scene, world);
    if (cameras.empty()) throw std::runtime_error(scene.source + ": the scene has no camera");
    if (settings.camera < 0 || size_t(settings.camera) >= cameras.size())
        throw std::runtime_error("camera: " + std::to_string(settings.camera) + " is out of range; " + scene.source +
                                 " has " + std::to_string(cameras.size()) + " camera(s)");
    camera_ = cameras[size_t(settings.camera)];
    const float aspect = float(settings.width) / float(settings.height);
    if (camera_.camera.aspectRatio > 0.0f && std::abs(camera_.camera.aspectRatio - aspect) > 1e-3f * aspect)
        warnings_.push_back("camera '" + camera_.camera.name + "' has aspectRatio " +
                            std::to_string(camera_.camera.aspectRatio) + " but the image is " +
                            std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                            "; the horizontal field of view follows the image");

    for (const auto& entry : settings.lightOcclusion) {
        const bool found = std::any_of(scene.lights.begin(), scene.lights.end(),
                                       [&](const scene::Light& l) { return l.name == entry.first; });
        if (!found) throw std::runtime_error("light-occlusion: " + scene.source + " has no light named '" +
                                             entry.first + "'");
    }
    const uint32_t iw = settings.width * settings.supersample, ih = settings.height * settings.supersample;
    const uint32_t maxDim = ctx.properties.limits.maxImageDimension2D;
    if (iw > maxDim || ih > maxDim)
        throw std::runtime_error("supersample: the internal image " + std::to_string(iw) + "x" + std::to_string(ih) +
                                 " (width and height x supersample) exceeds " + ctx.deviceName + "'s limit of " +
                                 std::to_string(maxDim) + " pixels per side");
    // Textures larger than the device allows are box-filtered down (with a warning).
    scene::limitTextureSize(scene_, maxDim, &warnings_);
    sceneGpu_ = std::make_unique<gpuscene::SceneGpu>(ctx, scene, float(settings_.textureAnisotropy));
    // With a clipmap the camera walks through a scene that may be far larger
    // than level 0: directional shadows get a view of their own over level 0's
    // window (a square as wide as the window around the camera), so the finest
    // voxels and the pixels near the camera keep shadows as fine as in a small
    // scene. Decided once: the shadow-map array's layers are fixed here.
    if (settings.shadowFocus && settings.clipmap.levels > 0 && settings.voxels > 0) {
        shadowFocusRadius_ = shadowFocusRadius(sceneGpu_->bounds, 0.5f * float(settings.voxels) * clipBaseVoxel());
    }
    uploadLights();
    frame_ = std::make_unique<gpu::Buffer>(ctx, sizeof(sh::FrameConstants),
                                           VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                           gpu::MemoryUse::Device, "frame constants");
    FrameSize size;
    size.width = settings.width;
    size.height = settings.height;
    size.supersample = settings.supersample;
    size.traceScale = settings.gather.traceScale;
    size.shadowMapSize = settings.shadowMapSize;
    size.shadowViews = viewCount_;
    size.temporalHistory = settings.voxels > 0;
    targets_ = std::make_unique<FrameTargets>(createFrameTargets(ctx, size));
    samplers_ = std::make_unique<Samplers>(createSamplers(ctx));
    shadows_ = std::make_unique<ShadowPass>(ctx, *sceneGpu_);
    gbuffer_ = std::make_unique<GBufferPass>(ctx, *sceneGpu_);
    // Clipmap variants are compiled only for a clipmap (each pipeline costs lavapipe a JIT compile).
    const bool clipmap = settings.clipmap.levels > 0 && settings.voxels > 0;
    lighting_ = std::make_unique<LightingPass>(ctx, clipmap);
    composite_ = std::make_unique<CompositePass>(ctx);
    timers_ = std::make_unique<gpu::GpuTimers>(ctx, timerScopes(settings));
    gather_ = std::make_unique<GatherPass>(ctx, clipmap);
    if (settings.voxels == 0) {
        // The lighting pass always binds voxel volumes; without voxels it gets
        // small empty ones that nothing writes.
        if (settings.shadowCones.enabled) throw std::runtime_error("shadows: cone needs voxels (voxels > 0)");
        if (settings.clipmap.levels > 0) throw std::runtime_error("clipmap: needs voxels (voxels > 0)");
        volumes_ = std::make_unique<vxgi::VoxelVolumes>(ctx, vxgi::fitGrid(sceneGpu_->bounds, 8));
    } else {
        const vxgi::GridSpec grid =
            settings.hasVoxelBox ? vxgi::gridForBox(settings.voxelBoxMin, settings.voxelBoxMax, settings.voxels)
                                 : vxgi::fitGrid(sceneGpu_->bounds, settings.voxels);
        voxelizer_ =
            std::make_unique<vxgi::Voxelizer>(ctx, *sceneGpu_, settings.hardwareConservative, settings.voxelizer);
        if (voxelizer_->kind() == vxgi::VoxelizerKind::Pv) pv_ = std::make_unique<vxgi::PvVoxelizer>(ctx);
        if (settings.clipmap.levels > 0)
            createClipmap();
        else
            volumes_ = std::make_unique<vxgi::VoxelVolumes>(ctx, grid, settings.voxelSlots);
        voxelView_ = std::make_unique<VoxelViewPass>(ctx);
        list_ = std::make_unique<vxgi::VoxelListPass>(ctx);
        listHeader_ = vxgi::createListHeaderReadback(ctx);
        inject_ = std::make_unique<vxgi::InjectPass>(ctx);
        aniso_ = std::make_unique<vxgi::AnisoFilterPass>(ctx);
        bounce_ = std::make_unique<vxgi::BouncePass>(ctx, clipmap);
        rayData_ = std::make_unique<vxgi::RayData>();
        rayData_->edgeFaces = vxgi::edgeFacesLit(settings.voxelLight);
        temporal_ = std::make_unique<TemporalIndirectPass>(ctx);
    }
    for (const gpu::Image* v : volumes_->all()) tracker_.assume(*v, gpu::use::ComputeReadWrite);
    if (settings.voxels == 0 && settings.view.mode != ViewMode::Final)
        throw std::runtime_error("view: the voxel views need voxels (voxels 0 turns them off)");
    updateFrameConstants();
}

void Renderer::uploadLights() {
    const std::vector<glm::mat4> world = scene::worldMatrices(scene_);
    const std::vector<scene::PlacedLight> placed = scene::placedLights(scene_, world);
    const ShadowFocus focus{glm::vec3(camera_.world[3]), shadowFocusRadius_};
    LightSetup setup =
        setupLights(placed, sceneGpu_->bounds, settings_.shadowMapSize, settings_.shadows, focus);
    for (size_t i = 0; i < placed.size(); ++i)
        for (const auto& [name, mode] : settings_.lightOcclusion)
            if (placed[i].light.name == name) setup.lights[i].shadow.z = uint32_t(mode);
    patchCount_ = 0;
    if (settings_.emitterLights && settings_.voxels > 0) {
        const EmitterPatches patches =
            emitterPatches(scene_, scene::drawItems(scene_, world), settings_.emitterPatches);
        if (patches.complete) {
            setup.lights.insert(setup.lights.end(), patches.lights.begin(), patches.lights.end());
            patchCount_ = uint32_t(patches.lights.size());
        } else if (warnings_.empty() || warnings_.back().find("emissive texture") == std::string::npos) {
            warnings_.push_back("an emissive texture cannot be lit as area lights; cones gather the emission");
        }
    }
    const VkDeviceSize lightBytes = setup.lights.size() * sizeof(sh::GpuLight);
    // Accumulated indirect light of other lights would linger (ghosts).
    const auto* records = reinterpret_cast<const uint8_t*>(setup.lights.data());
    if (!std::equal(records, records + lightBytes, lightRecords_.begin(), lightRecords_.end())) {
        lightRecords_.assign(records, records + lightBytes);
        temporalState_.drop(lightSettleFrames());
        dropVoxelHistory();
    }
    const VkDeviceSize viewBytes = setup.views.size() * sizeof(sh::GpuShadowView);
    shadowViews_ = setup.views;
    if (lights_ && uint32_t(setup.lights.size()) == lightCount_ && uint32_t(setup.views.size()) == viewCount_) {
        if (lightBytes) gpu::uploadBuffer(ctx_, *lights_, setup.lights.data(), lightBytes);
        if (viewBytes) gpu::uploadBuffer(ctx_, *views_, setup.views.data(), viewBytes);
        return;
    }
    lightCount_ = uint32_t(setup.lights.size());
    viewCount_ = uint32_t(setup.views.size());
    lights_ = std::make_unique<gpu::Buffer>(
        gpu::createBuffer(ctx_, setup.lights.data(), lightBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "lights"));
    views_ = std::make_unique<gpu::Buffer>(
        gpu::createBuffer(ctx_, setup.views.data(), viewBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "shadow views"));
}

void Renderer::sceneChanged() {
    const std::vector<glm::mat4> world = scene::worldMatrices(scene_);
    const std::vector<scene::DrawItem> items = scene::drawItems(scene_, world);
    // SceneGpu still holds the world matrices it last uploaded.
    for (size_t i = 0; i < items.size() && i < sceneGpu_->drawWorld.size(); ++i)
        if (!sceneGpu_->ranges[i].dynamic && items[i].world != sceneGpu_->drawWorld[i]) staticDirty_ = true;
    sceneGpu_->updateDraws(ctx_, scene_, items);
    const std::vector<scene::PlacedCamera> cameras = scene::placedCameras(scene_, world);
    camera_ = cameras.at(size_t(settings_.camera));
    uploadLights();  // shadow views follow the lights and the scene bounds
    updateFrameConstants();
}

void Renderer::setTime(float seconds) {
    scene::applyAnimations(scene_, seconds);
    if (cameraPath_) scene::applyCameraPath(scene_, settings_.camera, *cameraPath_, seconds);
    sceneChanged();
}

void Renderer::setCameraPath(std::optional<scene::CameraPath> path) {
    cameraPath_ = std::move(path);
    setTime(0.0f);
}

Renderer::~Renderer() = default;

uint64_t Renderer::triangleCount() const { return sceneGpu_->triangleCount; }

glm::mat4 Renderer::viewProjection() const {
    const uint32_t iw = settings_.width * settings_.supersample, ih = settings_.height * settings_.supersample;
    return projectionMatrix(camera_, iw, ih) * viewMatrix(camera_);
}

void Renderer::recordCameraGBuffer(VkCommandBuffer cmd) {
    const gpuscene::DrawList draws = gpuscene::visibleDraws(*sceneGpu_, viewProjection(), gpuscene::DrawFilter::All);
    gbufferTriangles_ = draws.triangles();
    gbuffer_->record(cmd, tracker_, *sceneGpu_, draws, *frame_, targets_->gbuffer, timers_.get());
}

void Renderer::updateFrameConstants() {
    const uint32_t iw = settings_.width * settings_.supersample, ih = settings_.height * settings_.supersample;
    sh::FrameConstants f{};
    f.viewProj = viewProjection();
    f.invViewProj = glm::inverse(f.viewProj);
    f.cameraPos = glm::vec4(glm::vec3(camera_.world[3]), 1.0f);
    f.sizes = glm::uvec4(iw, ih, lightCount_, settings_.shadowMapSize);
    f.shadowParams = glm::vec4(settings_.normalOffsetTexels, settings_.shadows ? 1.0f : 0.0f, 0.0f, 0.0f);
    gpu::uploadBuffer(ctx_, *frame_, &f, sizeof(f));
    if (pv_) uploadPvViews();
}

// Voxelization, shadow maps and the voxel light up to (not including) the
// bounces of Fixed/Converge; a Feedback frame records its one bounce here.
void Renderer::recordVoxels(VkCommandBuffer cmd) {
    gpu::GpuTimers* t = timers_.get();
    if (rayData_) rayData_->packed = false;
    if (pv_) {
        recordProgressiveVoxels(cmd);
    } else if (!clip_.empty()) {
        recordClipmapVoxels(cmd);
    } else if (voxelizer_) {
        // The occupied-voxel list holds the static voxels, then this frame's
        // dynamic ones; the per-voxel passes below run over it.
        if (staticDirty_) {
            recordStaticVoxels(cmd);
        } else {
            voxelizer_->clearDynamic(cmd, tracker_, *volumes_, t);
            list_->dropDynamic(cmd, tracker_, *volumes_);
        }
        voxelizer_->voxelize(cmd, tracker_, *sceneGpu_, *volumes_, vxgi::VoxelizeMode::Dynamic, t);
        list_->finish(cmd, tracker_, *volumes_, false);
        list_->copyHeader(cmd, tracker_, *volumes_, *listHeader_);
    }
    if (!pv_) recordShadows(cmd);
    if (!voxelizer_) return;
    const vxgi::ShadowInputs shadows{*lights_,
                                     lightCount_,
                                     *views_,
                                     targets_->shadowMap,
                                     targets_->shadowGradient,
                                     samplers_->point.handle(),
                                     settings_.shadows};
    // Emitters lit as patches leave their emission out of the voxel radiance.
    vxgi::VoxelLightSettings light = settings_.voxelLight;
    light.emissionInRadiance = patchCount_ == 0;
    // A feedback frame bounces once from the directional volumes, which still
    // hold the previous frame's filtered radiance: one more bounce of light.
    const bool feedback = feedbackFrame();
    const bool blend = blendsVoxelRadiance();
    light.keepSideReflection = feedback;
    light.keepStaticRadiance = feedback && staticLightKept_ && bounceRays();
    const std::optional<vxgi::ClipTrace> trace = bounceTrace();
    // Rays read no filtered light, and mark the cells that hold voxels
    // themselves: where a ray bounce follows in this frame, the filtering
    // after it is the first that anything reads.
    const vxgi::BounceMode mode = settings_.voxelLight.bounceMode;
    const bool bounceFollows = !feedback && (mode == vxgi::BounceMode::Converge ||
                                             (mode == vxgi::BounceMode::Fixed && settings_.voxelLight.bounces > 0));
    // Where rays read the voxels' normals and occupancy bits this frame anyway,
    // they are packed first, and the voxels' shadow rays (to emitter patches,
    // --voxel-occlusion raycast) cross empty cells by the bits.
    packRayData(cmd);
    const gpu::Buffer* occupancy = raysRead() ? &rayData_->occupancy : nullptr;
    recordLevels(cmd, feedback ? "voxel filtering (bounce)" : "voxel filtering",
                 [&](size_t l, const vxgi::VoxelVolumes& v) {
                     inject_->record(cmd, tracker_, v, shadows, light, t, occupancy);
                     if (feedback) recordLevelBounce(cmd, l, v, trace ? &*trace : nullptr, false, blend);
                 },
                 !(bounceFollows && bounceRays()));
}

void Renderer::recordStaticVoxels(VkCommandBuffer cmd) {
    gpu::GpuTimers* t = timers_.get();
    if (rayData_) rayData_->packed = false;
    staticLightKept_ = false;
    for (size_t l = 0; l < clip_.size(); ++l) recordClipmapStatic(cmd, l, clip_[l].windowMin);
    if (!clip_.empty()) return;
    // Clears every voxel, dynamic ones included: the list restarts empty.
    // New volumes start zeroed with an empty list, and after that the list
    // names every voxel that can hold anything, so clearing those is enough
    // (the whole grid's clear took 3.5 ms on an H200 at 256^3, where 3 % of
    // Sponza's voxels are occupied).
    voxelizer_->clearOccupied(cmd, tracker_, *volumes_, t);
    list_->reset(cmd, tracker_, *volumes_);
    voxelizer_->voxelize(cmd, tracker_, *sceneGpu_, *volumes_, vxgi::VoxelizeMode::Static, t);
    list_->finish(cmd, tracker_, *volumes_, true);
}

void Renderer::recordShadows(VkCommandBuffer cmd) {
    const StaticShadows statics =
        shadowsStale_ ? StaticShadows::Uncached : (staticDirty_ ? StaticShadows::Changed : StaticShadows::Kept);
    const ShadowTargets map{targets_->shadowMap, targets_->shadowGradient};
    shadows_->record(cmd, tracker_, *sceneGpu_, *views_, shadowViews_, map, statics, timers_.get());
    shadowsStale_ = false;
}

std::vector<gpu::TimerResult> Renderer::revoxelizeStatic() {
    shadowsStale_ = true;
    if (!voxelizer_ || pv_) return {};
    timers_->reset();
    ctx_.submitAndWait([&](VkCommandBuffer cmd) {
        recordStaticVoxels(cmd);
        for (size_t l = 0; l < levelVolumes().size(); ++l) list_->copyHeader(cmd, tracker_, level(l), levelHeader(l));
    });
    // As after a frame: claims dropped for want of slots left index words
    // that no list entry names, which only new, larger volumes clear.
    if (growVoxelSlots()) return revoxelizeStatic();
    staticDirty_ = false;
    return timers_->results();
}

void Renderer::recordImage(VkCommandBuffer cmd) {
    gpu::GpuTimers* t = timers_.get();
    FrameTargets& f = *targets_;
    if (settings_.view.mode != ViewMode::Final) {
        voxelView_->record(cmd, tracker_, *volumes_, *frame_, f.output, settings_.view, t);
        return;
    }
    if (!pv_) recordCameraGBuffer(cmd);  // pv: before the voxels
    const std::optional<vxgi::ClipTrace> trace =
        clip_.empty() ? std::nullopt
                      : std::optional<vxgi::ClipTrace>({*coneLevels_, *atlases_, levelVolumes().back()->grid});
    // Packed before the voxel light unless the voxels changed since (a
    // render's frame after a revoxelization).
    packRayData(cmd);
    const bool areaRays = areaLightRays();
    LightingInputs lit{f.gbuffer, f.shadowMap, f.shadowGradient, *samplers_, *frame_, *lights_, *views_, *volumes_,
                       trace ? &*trace : nullptr, patchCount_ > 0};
    if (areaRays) {
        lit.rays = rayData_.get();
        lit.rayOffsetVoxels = settings_.gather.rayOffsetVoxels;
    }
    lighting_->record(cmd, tracker_, lit, f.direct, f.visibility, settings_.shadowCones, settings_.cones, t);
    if (voxelizer_) {
        const GatherInputs in{f.gbuffer, *volumes_, *samplers_, *frame_, trace ? &*trace : nullptr,
                              gatherRays() ? rayData_.get() : nullptr, settings_.voxelLight.backsDark};
        const GatherTargets out{f.diffuse, f.specular, f.reducedTrace() ? &f.traceDiffuse : nullptr,
                                f.reducedTrace() ? &f.traceSpecular : nullptr, f.turnedDiffuse};
        gather_->record(cmd, tracker_, in, out, settings_.gather, settings_.cones, t);
        recordTemporal(cmd);
    }
    recordComposite(cmd, settings_.outputTerm, t);
}

void Renderer::recordTemporal(VkCommandBuffer cmd) {
    if (!settings_.temporal.enabled) {
        temporalState_.reset();
        return;
    }
    FrameTargets& f = *targets_;
    TemporalState& s = temporalState_;
    // Only feedback bounces from the first frame leave the voxel light
    // climbing while the history runs: a converging render settles it in its
    // first frame, and after a change the history is held back until it settles.
    const bool lightClimbs = voxelizer_ && settings_.voxelLight.bounceMode == vxgi::BounceMode::Feedback;
    const TemporalIndirectInputs in{f.gbuffer, *samplers_, *frame_, f.temporal.color[s.previous],
                                    f.temporal.surface[s.previous], s.previousViewProj, s.valid, s.frames,
                                    lightClimbs};
    const TemporalIndirectTargets out{f.diffuse, f.temporal.color[1 - s.previous], f.temporal.surface[1 - s.previous]};
    temporal_->record(cmd, tracker_, in, out, settings_.temporal, timers_.get());
    s.advance(viewProjection());
}

// After lights or static geometry change, feedback frames carry the voxel
// light on from the old volumes, one bounce per frame, and the indirect
// term's history stays dropped until it has settled (settleFrames;
// tests/render/temporal_renderer_test.cpp).
uint32_t Renderer::lightSettleFrames() const { return voxelizer_ && haveHistory_ ? settleFrames() : 1u; }

void Renderer::recordComposite(VkCommandBuffer cmd, uint32_t term, gpu::GpuTimers* timers) const {
    const FrameTargets& f = *targets_;
    const CompositeInputs in{f.direct,      f.visibility, f.diffuse, f.specular, f.gbuffer.base,
                             samplers_->point.handle(), voxelizer_ != nullptr};
    composite_->record(cmd, tracker_, in, f.output, settings_.supersample, term, settings_.applyAO, timers);
}

FrameStats Renderer::renderFrame() {
    timers_->reset();
    if (staticDirty_) {
        temporalState_.drop(lightSettleFrames());
        dropVoxelHistory();
    }
    const bool blend = blendsVoxelRadiance();
    if (blend) {
        prepareVoxelHistory();
        if (++historyTag_ == UINT32_MAX) historyTag_ = 1;
    }
    temporalState_.beginFrame();
    gbufferTriangles_ = 0;
    gpu::GpuTimers* t = timers_.get();
    FrameStats stats;
    const vxgi::VoxelLightSettings& vl = settings_.voxelLight;
    const bool feedback = voxelizer_ && feedbackFrame();
    const bool converge = voxelizer_ && !feedback && vl.bounceMode == vxgi::BounceMode::Converge;
    const uint32_t fixed = voxelizer_ && vl.bounceMode == vxgi::BounceMode::Fixed ? vl.bounces : 0;
    if (converge && bounceStats_.empty())
        for (const vxgi::VoxelVolumes* v : levelVolumes())
            bounceStats_.push_back(std::make_unique<gpu::Buffer>(
                ctx_, sizeof(float) * vxgi::BouncePass::statsFloats(v->slots),
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback,
                "bounce statistics"));
    // Converging takes one submission per bounce (the host reads each one's
    // change); everything else is one command buffer.
    ctx_.submitAndWait([&](VkCommandBuffer cmd) {
        gpu::GpuTimerScope total(t, cmd, "frame");
        recordVoxels(cmd);
        for (uint32_t b = 0; b < fixed; ++b) recordBounce(cmd, false);
        if (converge) recordBounce(cmd, true);
        if (!converge) recordImage(cmd);
    });
    if (growVoxelSlots()) return renderFrame();
    readClipmapHeaders();
    stats.bounces = feedback ? 1 : fixed;
    if (converge) {
        // Bounce increments shrink geometrically (by r per bounce), so what is
        // still missing after a change c is about c r / (1 - r): stop when that
        // is below the threshold, or when c no longer shrinks but is already
        // below it (a limit cycle of rounding; none is known since the change
        // is measured on the stored light). c is measured against the voxels'
        // reflected light, not all of it: where the sun lights much that the
        // pixels see only by its bounces (a room lit through a window, and its
        // outside walls), the direct light hid a missing 3 % of the indirect light.
        double previous = 0.0;
        auto done = [&](double change) {
            const double r = previous > 0.0 ? change / previous : 1.0;
            const double remaining = r < 1.0 ? change * r / (1.0 - r) : 1e30;
            previous = change;
            return change == 0.0 || remaining <= vl.convergence || (r >= 1.0 && change <= vl.convergence);
        };
        auto measure = [&] {
            stats.bounceChange = bounceChange();
            stats.converged = done(stats.bounceChange);
        };
        stats.bounces = 1;
        measure();
        while (!stats.converged && stats.bounces < vl.maxBounces) {
            ctx_.submitAndWait([&](VkCommandBuffer cmd) {
                gpu::GpuTimerScope total(t, cmd, "frame");
                recordBounce(cmd, true);
            });
            ++stats.bounces;
            measure();
        }
        ctx_.submitAndWait([&](VkCommandBuffer cmd) {
            gpu::GpuTimerScope total(t, cmd, "frame");
            recordImage(cmd);
        });
    }
    if (converge) convergedBounces_ = stats.bounces;
    lastHistoryTag_ = blend ? historyTag_ : 0;
    if (blend && historyHold_ > 0) --historyHold_;
    if (converge) historyHold_ = 0;  // the light has settled: nothing to hold back
    staticDirty_ = false;
    haveHistory_ = voxelizer_ != nullptr;
    staticLightKept_ = voxelizer_ != nullptr;
    stats.gbufferTriangles = gbufferTriangles_;
    stats.shadowTriangles = shadows_->drawnTriangles();
    for (const gpu::TimerResult& r : timers_->results()) {
        if (r.name == "frame") {
            stats.gpuMs = r.ms;
            continue;
        }
        // --clipmap: a pass run once per level is reported once, summed.
        const auto same = std::find_if(stats.passes.begin(), stats.passes.end(),
                                       [&](const gpu::TimerResult& p) { return p.name == r.name; });
        if (!clip_.empty() && same != stats.passes.end())
            same->ms += r.ms;
        else
            stats.passes.push_back(r);
    }
    return stats;
}

bool Renderer::growVoxelSlots() {
    if (!voxelizer_) return false;
    bool grown = false;
    for (size_t l = 0; l < levelVolumes().size(); ++l) {
        sh::VoxelListHeader header;
        std::memcpy(&header, levelHeader(l).mapped(), sizeof(header));
        if (header.counts.w == 0) continue;
        // Every claim past the capacity was counted; a quarter more leaves
        // room for moving objects. The old volumes are idle (the frame was waited for).
        vxgi::VoxelVolumes& v = level(l);
        const uint64_t wanted = (uint64_t(v.slots) + header.counts.w) * 5 / 4;
        const uint32_t slots = vxgi::roundSlotCapacity(v.grid.n, wanted);
        if (slots <= v.slots)
            throw std::runtime_error("voxels: a voxelization ran out of its " + std::to_string(v.slots) +
                                     " voxel slots, which already cover the whole grid");
        const vxgi::GridSpec grid = v.grid;
        std::unique_ptr<vxgi::VoxelVolumes>& owner = l == 0 ? volumes_ : clip_[l].volumes;
        // Levels 1.. keep sharing their dense volumes (cleared before each use);
        // level 0's start zeroed, as the fitted grid's list-driven clears need.
        const std::shared_ptr<vxgi::DenseVolumes> dense = l == 0 ? nullptr : owner->dense();
        owner.reset();
        owner = std::make_unique<vxgi::VoxelVolumes>(ctx_, grid, slots, dense);
        for (const gpu::Image* img : owner->all()) tracker_.assume(*img, gpu::use::ComputeReadWrite);
        if (!clip_.empty()) clip_[l].placed = false;
        grown = true;
    }
    if (!grown) return false;
    bounceStats_.clear();
    staticDirty_ = true;
    if (rayData_) rayData_->packed = false;
    haveHistory_ = false;
    dropVoxelHistory();
    return true;
}

bool needsNewRenderer(const RenderSettings& a, const RenderSettings& b) {
    return a.width != b.width || a.height != b.height || a.supersample != b.supersample ||
           a.shadowMapSize != b.shadowMapSize || a.camera != b.camera || a.voxels != b.voxels || a.voxelSlots != b.voxelSlots ||
           a.hasVoxelBox != b.hasVoxelBox || a.voxelBoxMin != b.voxelBoxMin || a.voxelBoxMax != b.voxelBoxMax ||
           a.hardwareConservative != b.hardwareConservative || a.voxelizer != b.voxelizer || a.pv.rsm != b.pv.rsm || a.pv.views != b.pv.views ||
           a.gather.traceScale != b.gather.traceScale || a.clipmap.levels != b.clipmap.levels ||
           a.clipmap.voxelSize != b.clipmap.voxelSize || a.shadowFocus != b.shadowFocus ||
           a.textureAnisotropy != b.textureAnisotropy ||
           a.emitterLights != b.emitterLights || a.emitterPatches != b.emitterPatches ||
           (a.voxels == 0 && (b.shadowCones.enabled || b.view.mode != ViewMode::Final));
}

bool Renderer::applySettings(const RenderSettings& s) {
    if (needsNewRenderer(settings_, s)) return false;
    const vxgi::VoxelLightSettings& o = settings_.voxelLight;
    const vxgi::VoxelLightSettings& n = s.voxelLight;
    const vxgi::ConeSettings& oc = settings_.cones;
    const vxgi::ConeSettings& nc = s.cones;
    const bool light = o.normalWeighted != n.normalWeighted || o.occlusion != n.occlusion ||
                       o.softKappa != n.softKappa || o.bounceMode != n.bounceMode || o.bounces != n.bounces ||
                       o.convergence != n.convergence || o.maxBounces != n.maxBounces ||
                       o.bounceStepFactor != n.bounceStepFactor || o.bounceTrace != n.bounceTrace ||
                       o.bounceRays != n.bounceRays || o.backsDark != n.backsDark || o.edgeFaces != n.edgeFaces ||
                       oc.stepFactor != nc.stepFactor ||
                       oc.minStepVoxels != nc.minStepVoxels || oc.maxDistance != nc.maxDistance ||
                       oc.firstSampleVoxels != nc.firstSampleVoxels || oc.clearance != nc.clearance ||
                       s.shadows != settings_.shadows || s.normalOffsetTexels != settings_.normalOffsetTexels ||
                       s.lightOcclusion != settings_.lightOcclusion;
    settings_ = s;
    temporalState_.reset();  // the accumulated term belongs to the old settings
    if (s.voxelLight.temporalAlpha >= 1.0f) voxelHistory_.clear();
    const uint32_t scopes = timerScopes(s);
    if (scopes > timers_->capacity()) timers_ = std::make_unique<gpu::GpuTimers>(ctx_, scopes);
    if (light) {
        if (rayData_) {
            rayData_->edgeFaces = vxgi::edgeFacesLit(s.voxelLight);
            rayData_->packed = false;
        }
        uploadLights();
        updateFrameConstants();
        haveHistory_ = false;
        dropVoxelHistory();
    }
    return true;
}

}  // namespace dvsgi::render
