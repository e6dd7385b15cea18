// One frame of dvsgi, headless: voxelization (static once, dynamic every
// frame) -> shadow maps -> G-buffer -> direct lighting -> composite, or the
// voxel debug view. docs/ARCHITECTURE.md lists the passes with what they read
// and write.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gpu/timers.h"
#include "gpu/tracker.h"
#include "image/image_io.h"
#include "render/frame_resources.h"
#include "render/gather.h"
#include "render/lighting.h"
#include "render/temporal_indirect.h"
#include "render/voxel_view.h"
#include "scene/camera_path.h"
#include "scene/scene.h"
#include "shared/scene_data.h"
#include "vxgi/clipmap.h"
#include "vxgi/volumes.h"
#include "vxgi/voxel_light_settings.h"
#include "vxgi/pv_voxelize.h"
#include "vxgi/voxelize.h"

namespace dvsgi::gpuscene {
class SceneGpu;
}
namespace dvsgi::gpu {
class Context;
class Buffer;
class Image;
}

namespace dvsgi::render {

struct RenderSettings {
    uint32_t width = 512;
    uint32_t height = 512;
    uint32_t supersample = 1;       // internal resolution = k * output, box-filtered
    uint32_t shadowMapSize = 2048;
    // Scene textures' sampler: the most anisotropic filtering it may do (1:
    // none; the device's limit caps it). Sharp textures at grazing angles are
    // nearly free on a GPU; on a CPU device (llvmpipe) 8x costs about 45 % of
    // the G-buffer pass (docs/benchmarks.md).
    uint32_t textureAnisotropy = 8;
    int camera = 0;
    bool shadows = true;
    bool shadowFocus = true;  // with a clipmap: a directional shadow view over level 0's window (render/shadows.h)
    // Shadow lookups at pixels move this many shadow-map texels along the
    // normal. Every shadow shrinks by about that much: at 1.5 Sponza's sunlit
    // image came out 1.6 % above Cycles' direct light, at 0.5 0.7 %. None (0)
    // lets point lights' cube maps shadow their own surfaces (the Cornell box
    // 21 % dark); 0.25 still did not, so 0.5 keeps twice that margin.
    float normalOffsetTexels = 0.5f;
    uint32_t voxels = 128;            // N of the N^3 grid; 0 = no voxel passes
    uint32_t voxelSlots = 0;          // initial voxel slot capacity (0 = vxgi::defaultSlotCapacity); grows as needed
    bool hasVoxelBox = false;         // grid on a user box instead of the scene bounds
    vxgi::ClipmapSettings clipmap;    // levels > 0: camera-following clipmap levels instead of one fitted grid
    glm::vec3 voxelBoxMin{0.0f}, voxelBoxMax{0.0f};
    bool hardwareConservative = true; // VK_EXT_conservative_rasterization when the device has it
    vxgi::VoxelizerKind voxelizer = vxgi::VoxelizerKind::Auto;  // resolved by vxgi::resolveVoxelizer
    vxgi::PvSettings pv;              // --voxelizer pv: progressive voxelization from the frame's buffers
    ViewSettings view;
    vxgi::VoxelLightSettings voxelLight;
    // Per-light occlusion mode for the voxel light pass, by light name
    // (lights not listed use shadow maps).
    std::vector<std::pair<std::string, vxgi::Occlusion>> lightOcclusion;
    vxgi::ConeSettings cones;        // the gather's, the shadow cones' and (bounceCones) the bounce's
    GatherSettings gather;           // per-pixel cone tracing (needs voxels)
    ShadowConeSettings shadowCones;  // cones instead of shadow maps for direct light
    uint32_t outputTerm = 0;         // shader::TERM_* (full, direct, indirect, specular, ao, shadow)
    bool applyAO = false;            // multiply the indirect terms by the cone AO
    TemporalSettings temporal;       // accumulation of the indirect diffuse term over frames
    // Emissive surfaces as area-light patches (render/emitters.h) at voxels and
    // pixels, their emission then left out of the cone-gathered radiance.
    bool emitterLights = true;
    uint32_t emitterPatches = 64;
    // Pixels see each patch by a ray through this frame's voxels (areaLightRays),
    // else by a cone as wide as the patch looks.
    bool emitterRays = true;
};

struct FrameStats {
    std::vector<gpu::TimerResult> passes;
    double gpuMs = 0.0;  // sum of the passes
    uint32_t bounces = 0;         // voxel bounces computed this frame
    double bounceChange = -1.0;   // the last bounce's luminance change over the voxels' reflected light (-1: not measured)
    bool converged = false;       // BounceMode::Converge reached its threshold this frame
    // Triangles the raster passes were given after culling per view
    // (gpuscene::visibleDraws): the camera's G-buffer, and all shadow views
    // together (0 when every view kept its depth from an earlier frame).
    uint64_t gbufferTriangles = 0, shadowTriangles = 0;
};

struct MemoryItem {
    std::string name;
    uint64_t bytes;
};

class ShadowPass;
class GBufferPass;
class LightingPass;
class CompositePass;
class VoxelViewPass;
class GatherPass;
}  // namespace dvsgi::render
namespace dvsgi::vxgi {
class VoxelListPass;
class InjectPass;
class AnisoFilterPass;
class BouncePass;
class ClipScrollPass;
struct RayData;
}
namespace dvsgi::render {

class Renderer {
public:
    Renderer(const gpu::Context& ctx, const scene::Scene& scene, const RenderSettings& settings);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Records, submits and waits. When voxelization ran out of voxel slots,
    // grows the voxel storage and renders the frame again.
    FrameStats renderFrame();

    // Takes new settings from the next frame on when none of the changes needs
    // new resources (needsNewRenderer); otherwise returns false and keeps the
    // old ones, and the caller builds a new Renderer. A change to the voxel
    // light makes BounceMode::Converge converge again.
    bool applySettings(const RenderSettings& settings);
    const RenderSettings& settings() const { return settings_; }

    // Scene changes: edit scene() (node transforms, ...) then call sceneChanged(),
    // or let setTime() apply the glTF animations. A static node that moved
    // makes the next frame re-run static voxelization.
    scene::Scene& scene() { return scene_; }
    void sceneChanged();
    void setTime(float seconds);
    // A camera path (scene/camera_path.h) that setTime() applies after the
    // animations, to the settings' camera; it takes effect at once (time 0).
    // std::nullopt: the scene's own camera (and its animation) again.
    void setCameraPath(std::optional<scene::CameraPath> path);
    void markStaticDirty() { staticDirty_ = true; }
    // Re-runs static voxelization now, in its own submission (what the next
    // frame does after markStaticDirty), and returns its passes' GPU times:
    // how the bench times it beside ordinary frames. Empty without voxels.
    // The next frame renders every shadow again and keeps none of them
    // (StaticShadows::Uncached), so it costs what an everything-dynamic frame
    // does.
    std::vector<gpu::TimerResult> revoxelizeStatic();

    const ShadowPass& shadows() const { return *shadows_; }
    // The voxel volumes (with --clipmap, level 0's, the finest).
    const vxgi::VoxelVolumes* volumes() const { return voxelizer_ ? volumes_.get() : nullptr; }
    // Whether the voxel bounce marches rays (bounceTracesRays).
    bool bounceRays() const;
    // Whether the per-pixel gather marches rays (gatherTracesRays).
    bool gatherRays() const;
    // Area lights' visibility at pixels by a ray per patch (a fitted grid's).
    bool areaLightRays() const;
    // Whether any rays (the bounce's, the gather's, the patches') read the
    // voxels' packed normals and occupancy bits (vxgi::RayData).
    bool raysRead() const;
    // The voxel data per grid voxel (VoxelVolumes::bytesPerGridVoxel, with the rays' results when they run).
    double voxelBytesPerGridVoxel() const {
        return volumes_->bytesPerGridVoxel(bounceRays(), raysRead());
    }
    // Every clipmap level's volumes, finest first; the one fitted grid's without --clipmap.
    std::vector<const vxgi::VoxelVolumes*> levelVolumes() const;
    // --clipmap: what its cones sample (left in gpu::use::ComputeRead after a frame); else null.
    const vxgi::ClipAtlases* clipAtlases() const { return atlases_.get(); }
    const vxgi::Voxelizer* voxelizer() const { return voxelizer_.get(); }
    const vxgi::InjectPass* injectPass() const { return inject_.get(); }
    const vxgi::BouncePass* bouncePass() const { return bounce_.get(); }
    image::ImageRGBA32F readOutput() const;    // linear radiance, output size
    // The RGBA32F output image (linear radiance, output size) that renderFrame()
    // leaves in gpu::use::ComputeWrite. For presentation (dvsgi view): a user
    // may read it after renderFrame() returns and must leave it in
    // gpu::use::ComputeWrite again.
    const gpu::Image& outputImage() const;
    std::vector<MemoryItem> memory() const;
    const scene::PlacedCamera& camera() const { return camera_; }
    const std::vector<std::string>& warnings() const { return warnings_; }
    uint64_t triangleCount() const;
    uint32_t emitterPatchCount() const { return patchCount_; }
    uint32_t shadowViewCount() const { return viewCount_; }  // shadow-map layers rendered per frame

private:
    // An extra G-buffer for pv (see rsm_, around_) and its FrameConstants.
    struct PvView {
        GBuffer gbuffer;
        std::unique_ptr<gpu::Buffer> frame;
        glm::mat4 viewProj{1.0f};  // as in `frame`, for culling the draws
    };
    void updateFrameConstants();
    void uploadLights();
    void recordVoxels(VkCommandBuffer cmd);
    // Packs the voxels' normals and occupancy bits once per change of the
    // voxels, where raysRead().
    void packRayData(VkCommandBuffer cmd);
    void recordStaticVoxels(VkCommandBuffer cmd);
    void recordProgressiveVoxels(VkCommandBuffer cmd);
    void uploadPvViews();
    void setPvViews(std::vector<PvView>& views, const std::vector<glm::mat4>& viewProj, uint32_t size);
    void recordPvViews(VkCommandBuffer cmd, const std::vector<PvView>& views, const char* timer);
    void injectPvViews(VkCommandBuffer cmd, const std::vector<PvView>& views, const char* timer);
    // Shadow maps, told what static depth they may reuse (StaticShadows).
    void recordShadows(VkCommandBuffer cmd);
    void recordBounce(VkCommandBuffer cmd, bool withStats);
    void recordLevelBounce(VkCommandBuffer cmd, size_t l, const vxgi::VoxelVolumes& v, const vxgi::ClipTrace* trace,
                           bool withStats, bool blend = false);
    bool blendsVoxelRadiance() const;  // this frame blends the bounced radiance with last frame's
    void prepareVoxelHistory();        // per-level history images, zeroed when (re)created
    // Blends with nothing written before, and with nothing at all while the
    // light settles after a change.
    void dropVoxelHistory();
    std::optional<vxgi::ClipTrace> bounceTrace() const;
    // Clipmap (renderer_clipmap.cpp): levels, windows, scrolls.
    void createClipmap();
    float clipBaseVoxel() const;  // level 0's voxel edge (m)
    void recordClipmapVoxels(VkCommandBuffer cmd);
    void recordClipmapStatic(VkCommandBuffer cmd, size_t level, const glm::ivec3& windowMin);
    // Per level: `pass`, then its filtering (and with --clipmap, its atlas
    // copy); then the atlas fold. `filter` false (no clipmap): `pass` alone.
    void recordLevels(VkCommandBuffer cmd, const char* filterTimer,
                      const std::function<void(size_t, const vxgi::VoxelVolumes&)>& pass, bool filter = true);
    std::shared_ptr<vxgi::DenseVolumes> clipScratch() const;
    vxgi::VoxelVolumes& level(size_t l) { return l == 0 ? *volumes_ : *clip_[l].volumes; }
    const gpu::Buffer& levelHeader(size_t l) const { return l == 0 ? *listHeader_ : *clip_[l].header; }
    void readClipmapHeaders();  // after a frame: levels that freed many entries start afresh
    void recordImage(VkCommandBuffer cmd);
    void recordComposite(VkCommandBuffer cmd, uint32_t term, gpu::GpuTimers* timers) const;
    void recordTemporal(VkCommandBuffer cmd);
    glm::mat4 viewProjection() const;  // of the internal image (output x supersample)
    void recordCameraGBuffer(VkCommandBuffer cmd);
    uint64_t gbufferTriangles_ = 0;  // of the last recordCameraGBuffer
    uint32_t settleFrames() const;       // frames the light takes to settle after a change (renderer_voxel_history.cpp)
    uint32_t lightSettleFrames() const;  // settleFrames(), or 1 before any light to settle
    double bounceChange() const;  // summed |luminance change| over the voxels' reflected light
    bool feedbackFrame() const;  // from bounceStats_ after a bounce with statistics
    bool growVoxelSlots();       // after a voxelization that ran out of slots: bigger volumes

    const gpu::Context& ctx_;
    scene::Scene scene_;  // own copy: animation and edits change it
    RenderSettings settings_;
    scene::PlacedCamera camera_;
    std::vector<std::string> warnings_;
    uint32_t lightCount_ = 0, viewCount_ = 0, patchCount_ = 0;
    std::unique_ptr<gpuscene::SceneGpu> sceneGpu_;
    std::unique_ptr<gpu::Buffer> frame_, lights_, views_;
    std::unique_ptr<FrameTargets> targets_;
    std::unique_ptr<Samplers> samplers_;
    // Every image's last use, across frames; mutable because reading terms
    // back (const) re-runs the composite.
    mutable gpu::Tracker tracker_;
    std::unique_ptr<ShadowPass> shadows_;
    std::unique_ptr<GBufferPass> gbuffer_;
    std::unique_ptr<LightingPass> lighting_;
    std::unique_ptr<CompositePass> composite_;
    std::unique_ptr<vxgi::VoxelVolumes> volumes_;
    std::unique_ptr<vxgi::Voxelizer> voxelizer_;
    // --voxelizer pv: fills the volumes from the G-buffer, which is then
    // recorded before the voxel passes; its depth views are the camera's and
    // the shadow maps' (shader::PvDepthView, camera first).
    std::unique_ptr<vxgi::PvVoxelizer> pv_;
    std::unique_ptr<gpu::Buffer> pvViews_;
    uint32_t pvViewCount_ = 0;
    std::vector<shader::GpuShadowView> shadowViews_;  // host copy of the uploaded shadow views
    float shadowFocusRadius_ = 0.0f;  // > 0: directional lights' view around the camera (render/shadows.h)
    // Extra G-buffers for pv, each rendered with its own FrameConstants:
    // reflective shadow maps, one per shadow view (settings.pv.rsm), and six
    // views around the camera (settings.pv.views).
    std::vector<PvView> rsm_, around_;
    std::unique_ptr<VoxelViewPass> voxelView_;
    std::unique_ptr<vxgi::VoxelListPass> list_;
    std::unique_ptr<vxgi::InjectPass> inject_;
    std::unique_ptr<vxgi::AnisoFilterPass> aniso_;
    std::unique_ptr<vxgi::BouncePass> bounce_;
    std::unique_ptr<vxgi::RayData> rayData_;  // what the rays read (the bounce's, the gather's, the patches')
    // --clipmap: one entry per level (level 0's volumes and header are
    // volumes_ and listHeader_); empty for a fitted grid.
    struct ClipLevel {
        std::unique_ptr<vxgi::VoxelVolumes> volumes;
        std::unique_ptr<gpu::Buffer> header;  // host-visible copy of its list header
        glm::ivec3 windowMin{0};
        bool placed = false;  // voxelized at windowMin (else: from scratch next frame)
    };
    std::vector<ClipLevel> clip_;
    glm::vec3 clipLattice_{0.0f};  // vxgi::clipLattice: where every level's voxels start
    std::unique_ptr<vxgi::ClipScrollPass> scroll_;
    // shader::ConeLevels of this frame's windows, and of the windows the
    // directional volumes were filtered in (last frame's until this frame filters).
    std::unique_ptr<gpu::Buffer> coneLevels_, coneHistory_;
    std::unique_ptr<vxgi::ClipAtlases> atlases_;  // what the clipmap's cones sample, filled after filtering
    shader::ConeLevels coneLevelsHost_{};
    const gpu::Buffer* directionalLevels_ = nullptr;
    std::unique_ptr<GatherPass> gather_;
    std::unique_ptr<TemporalIndirectPass> temporal_;
    TemporalState temporalState_;  // dropped when static geometry, lights or settings change
    std::vector<uint8_t> lightRecords_;  // the GpuLight records last uploaded, to notice a change
    uint32_t convergedBounces_ = 0;      // bounces the last converging frame took
    bool staticDirty_ = true;
    bool shadowsStale_ = false;  // the next frame's shadows: StaticShadows::Uncached (after revoxelizeStatic)
    std::optional<scene::CameraPath> cameraPath_;
    bool haveHistory_ = false;  // the directional volumes hold an earlier frame's filtered radiance
    // The static voxels' radiance holds the light an earlier frame's bounce
    // left there (none re-voxelized since): a feedback frame's rays read it.
    bool staticLightKept_ = false;
    // --voxel-temporal-alpha: per level, the light each slot reflected after
    // the last blending frame (vxgi::VoxelHistory); frame tags count up from
    // 1, lastHistoryTag_ is 0 when nothing may be blended with, and
    // historyHold_ blending frames pass without blending after a change.
    std::vector<gpu::Image> voxelHistory_;
    uint32_t historyTag_ = 0, lastHistoryTag_ = 0, historyHold_ = 0;
    std::unique_ptr<gpu::Buffer> listHeader_;  // host-visible copy of the list header after voxelization
    // Host-visible, BouncePass::statsFloats(slots) floats per level: a
    // clipmap's change counts every level (level 0 may hold nothing).
    std::vector<std::unique_ptr<gpu::Buffer>> bounceStats_;
    std::unique_ptr<gpu::GpuTimers> timers_;

public:
    // Arbitrary output variables of the last frame (call after renderFrame(),
    // final view only). readTerm re-runs only the composite with another
    // shader::TERM_* and reads it back at output size, then composites the
    // frame's own term again so outputImage() and readOutput() are unchanged.
    image::ImageRGBA32F readTerm(uint32_t term) const;
    // The G-buffer at output size, box-averaging the k x k internal samples:
    // albedo (base colour, a = metallic), world normal (a = roughness,
    // averaged then renormalized), depth (r = distance along the camera axis
    // in metres, averaged over the samples that hit geometry; +inf where none
    // did). Alpha of depth = fraction of samples that hit geometry.
    struct SurfaceImages {
        image::ImageRGBA32F albedo, normal, depth;
    };
    SurfaceImages readSurface() const;
};

// True when going from `a` to `b` changes an image, a buffer, a pipeline or
// the grid (sizes, voxels, shadow map, trace scale, emitter patches, camera).
bool needsNewRenderer(const RenderSettings& a, const RenderSettings& b);

// Whether the voxel bounce marches rays: --bounce-trace rays on a fitted grid
// voxelized whole (clipmap levels and progressive voxelization trace cones:
// their feedback frames have no static voxels whose last light the rays
// could read, Renderer::recordVoxels).
inline bool bounceTracesRays(const RenderSettings& s) {
    return s.voxelLight.bounceTrace == vxgi::BounceTrace::Rays && s.clipmap.levels == 0 &&
           s.voxelizer != vxgi::VoxelizerKind::Pv;
}

// Whether the per-pixel gather marches rays: --gather-trace rays on a fitted
// grid (not with --clipmap or --voxelizer pv, which gather with cones).
inline bool gatherTracesRays(const RenderSettings& s) {
    return s.gather.trace == GatherTrace::Rays && s.clipmap.levels == 0 && s.voxelizer != vxgi::VoxelizerKind::Pv;
}

// Camera matrices for an image of the given size (Vulkan clip space, Y flipped
// so row 0 is the top of the image).
glm::mat4 viewMatrix(const scene::PlacedCamera& camera);
glm::mat4 projectionMatrix(const scene::PlacedCamera& camera, uint32_t width, uint32_t height);

}  // namespace dvsgi::render
