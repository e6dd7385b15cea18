// The voxel bounce (paper section IX): cones per occupied voxel through the
// filtered directional volumes; radiance = direct + albedo / pi x irradiance.
// Repeated with filtering in between, or once per frame from the previous
// frame's volumes (feedback), it adds one bounce of light each time.
// With rays (--bounce-trace rays, a fitted grid's) a first dispatch packs
// each voxel's normal per slot and marks the coarse cells that hold voxels,
// a second marches each voxel's rays through
// the radiance volume, voxel by voxel, reading those normals, and keeps what
// they gathered per slot; the third shades as the cones' pass does. Three
// dispatches, because the rays read normals of voxels other invocations
// pack, and the radiance the shading writes.
#pragma once

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "vxgi/cone_settings.h"

namespace dvsgi::gpu {
class GpuTimers;
class Tracker;
}

namespace dvsgi::vxgi {

class VoxelVolumes;
struct ClipTrace;

// Temporal blending of the bounced radiance over feedback frames
// (BIND_BOUNCE_HISTORY in shared/bounce_pass.h): one RGBA32UI texel per slot
// of the bounced volumes (historyImageDesc).
struct VoxelHistory {
    const gpu::Image* image = nullptr;
    uint32_t tag = 0;          // this frame's, never 0
    uint32_t previousTag = 0;  // what a slot's history must carry to be blended with
    float alpha = 1.0f;        // weight of this frame's value
};
gpu::ImageDesc historyImageDesc(uint32_t slots);
// The rays' light per slot (BIND_BOUNCE_TRACED in shared/bounce_pass.h): RG32UI.
gpu::ImageDesc tracedImageDesc(uint32_t slots);
// The voxels' packed normals per slot that the rays read (BIND_BOUNCE_RAY_NORMALS): R32UI.
gpu::ImageDesc rayNormalsImageDesc(uint32_t slots);
// Bytes of the rays' occupancy bits of an n^3 grid (BIND_BOUNCE_RAY_OCCUPANCY).
VkDeviceSize rayOccupancyBytes(uint32_t n);

// What rays read besides the radiance (--bounce-trace rays, --gather-trace
// rays): each voxel's packed normal per slot (BIND_BOUNCE_RAY_NORMALS) and
// which coarse cells hold voxels (BIND_BOUNCE_RAY_OCCUPANCY), recorded from
// this frame's voxels by BouncePass::recordRayData; made at the first
// recording and again when the slot capacity or the grid's size changes.
struct RayData {
    gpu::Image normals;
    gpu::Buffer occupancy;
    // Packed from the voxels as they are now: set by recordRayData (and a ray
    // bounce, which packs them when this is false), cleared by whoever changes
    // the voxels. Within a frame the voxels do not change between bounces.
    bool packed = false;
    // --edge-voxels faces: the packed words carry which voxels show their
    // faces and their extents (set by the owner; repack when it changes).
    bool edgeFaces = false;
    VkDeviceSize bytes() const { return normals.handle() ? normals.memorySize() + occupancy.size() : 0; }
};

// What a pass whose pixels walk rays (the gather's, the area lights' in the
// lighting pass) binds besides the radiance volume, at its own binding
// numbers: the side light, the slot index, the rays' normals and occupancy bits.
struct RayBindings {
    uint32_t sides, index, normals, occupancy, extents;
};
void addRayBindings(gpu::LayoutDesc& layout, const RayBindings& b);
// Declares the four as read by compute (before the caller's flush).
void trackRayReads(gpu::Tracker& tracker, const VoxelVolumes& v, const RayData& rays);
void bindRays(gpu::Descriptors& d, const RayBindings& b, const VoxelVolumes& v, const RayData& rays);

class BouncePass {
public:
    // clipmap: also the pipeline that traces clipmap levels (compiled only when asked for).
    explicit BouncePass(const gpu::Context& ctx, bool clipmap = false);
    // Reads the attributes, `direct` and the directional volumes (through
    // `volumeSampler`), writes `radiance`. `stats` (optional, statsFloats(slots)
    // floats, host-visible) receives per-workgroup sums of |luminance change|
    // and luminance over occupied voxels, readable by the host after the submission.
    // With `clip`, `volumes` is clipmap level `level` and its cones trace the
    // levels from it up (clip's ConeLevels and volumes: the previous frame's
    // windows when the bounce feeds back); its directional volumes are read.
    // With `history`, each voxel's new radiance is blended with its last one.
    // `rays` > 0: that many rays per voxel instead of the cones (not with
    // `clip`), packing the voxels' normals and cells into `rayData` first;
    // `backsDark`: a one-sided voxel a ray meets from behind shows it no light.
    void record(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes, VkSampler volumeSampler,
                const ConeSettings& cone, uint32_t rays, RayData* rayData, bool backsDark, const gpu::Buffer* stats,
                gpu::GpuTimers* timers, const ClipTrace* clip = nullptr, uint32_t level = 0,
                const VoxelHistory* history = nullptr) const;
    // Packs each occupied voxel's normal and marks its cells in `rayData`
    // (made or remade to fit `volumes`), for the rays of the bounce and the gather.
    void recordRayData(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes, RayData& rayData,
                       gpu::GpuTimers* timers) const;
    static uint32_t statsFloats(uint32_t slots);
    // Bytes of the rays' per-slot results (0 until rays were traced).
    VkDeviceSize rayBytes() const { return traced_.handle() ? traced_.memorySize() : 0; }

private:
    void recordRayNormals(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes,
                          RayData& rayData) const;

    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_, clipPipeline_;
    gpu::Buffer noStats_;     // bound when no statistics are asked for (the binding must stay valid)
    gpu::Image noHistory_;    // bound when nothing is blended
    gpu::Pipeline rayNormalsPipeline_, rayPipeline_, rayShadePipeline_;
    // What the rays gathered, per slot (BIND_BOUNCE_TRACED): made at the
    // first ray bounce and again when the slot capacity changes.
    mutable gpu::Image traced_;
};

}  // namespace dvsgi::vxgi
