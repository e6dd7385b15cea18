// Per-pixel voxel cone tracing (indirect diffuse + AO, specular) at the trace
// resolution, and the depth-aware upsampling to the internal resolution.
#pragma once

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "render/frame_resources.h"
#include "vxgi/cone_settings.h"

namespace dvsgi::gpu {
class GpuTimers;
class Tracker;
}
namespace dvsgi::vxgi {
class VoxelVolumes;
struct ClipTrace;
struct RayData;
}

namespace dvsgi::render {

// How each pixel gathers its indirect diffuse light.
enum class GatherTrace {
    Cones,  // the cone set through the filtered volumes (the paper)
    Rays,   // cosine rays marched voxel by voxel through the radiance volume (gather.comp's RAYS)
};

// What the gather adds to the shared cone settings (RenderSettings::cones).
struct GatherSettings {
    // Rays on a fitted grid (docs/quality.md, "The gather by rays"); with
    // clipmap levels or the pv voxelizer the cones (GatherInputs::rays null).
    GatherTrace trace = GatherTrace::Rays;
    uint32_t rays = 16;  // per traced pixel
    float rayOffsetVoxels = 1.0f;  // ray origins off the surface along its normal
    float aoLambda = 0.5f;        // f(r) = 1 / (1 + lambda r), r in voxels
    bool specular = true;
    float minSpecularDegrees = 1.0f;  // half-angle of the narrowest specular cone, degrees
    // Trace resolution / internal resolution. Half: a quarter of the cone work;
    // the reference renders differ by under 0.003 relative RMSE (docs/quality.md).
    float traceScale = 0.5f;
    // The six-cone set turned per pixel over 2x2 blocks, then resolved by a
    // 3x3 tent (cone_resolve.comp): blotches a cone wide become none
    // (docs/quality.md, "Six cones, turned per pixel"). Off: the paper's fixed set.
    bool spin = true;
    // Tests: with spin, every pixel turned by this many steps (0..CONE_SPIN_STEPS-1)
    // and nothing resolved; -1: turned per pixel and resolved.
    int fixedTurn = -1;
    // Rays with spin: the resolve's tent runs this many times, its taps 1, 2,
    // 4, ... trace pixels apart (docs/quality.md, "The rays filtered"); 1 =
    // the tent alone.
    uint32_t rayFilterPasses = 3;
};

// How many times the resolve's tent runs over the gather's term (0: no
// resolve): the turned six cones once, rays rayFilterPasses times.
uint32_t resolvePasses(const GatherSettings& s, bool rays, uint32_t coneSet);

struct GatherInputs {
    const GBuffer& gbuffer;
    const vxgi::VoxelVolumes& volumes;  // radiance and the filtered directional volumes
    const Samplers& samplers;
    const gpu::Buffer& frame;
    const vxgi::ClipTrace* clip = nullptr;  // clipmap levels to trace instead of `volumes`
    // The voxels' packed normals and occupancy bits for GatherTrace::Rays,
    // recorded this frame (vxgi::BouncePass::recordRayData); null: cones.
    const vxgi::RayData* rays = nullptr;
    bool backsDark = true;  // rays: a one-sided voxel met from behind shows no light (--voxel-backs-dark)
};

// The cone-traced terms at internal size, and at trace size when the trace
// runs at a lower resolution (then upsampled); FrameTargets holds them all.
struct GatherTargets {
    const gpu::Image& diffuse;
    const gpu::Image& specular;
    const gpu::Image* traceDiffuse = nullptr;   // null: trace at internal size
    const gpu::Image* traceSpecular = nullptr;
    // Trace size: the diffuse term as the turned cones left it, before the
    // resolve (GatherSettings::spin with the six-cone set).
    const gpu::Image& turnedDiffuse;
};

class GatherPass {
public:
    // clipmap: also the pipeline that traces clipmap levels (compiled only when asked for).
    explicit GatherPass(const gpu::Context& ctx, bool clipmap = false);
    // Writes the targets whole (diffuse.a = ambient occlusion).
    void record(VkCommandBuffer cmd, gpu::Tracker& tracker, const GatherInputs& in, const GatherTargets& out,
                const GatherSettings& settings, const vxgi::ConeSettings& cone, gpu::GpuTimers* timers) const;

private:
    // The gather's term (trace size) resolved by `passes` runs of the 3x3
    // tent into `resolved`, ping-ponging with `turned`: the gather wrote it
    // into `turned` if `passes` is odd, else into `resolved`. `rays`: the
    // gather's rays, whose filter also weighs neighbours by world distance
    // (RESOLVE_REACH_VOXELS); the turned cones' tent must weigh the four
    // turns alike, so it does not.
    void recordResolve(VkCommandBuffer cmd, gpu::Tracker& tracker, const GatherInputs& in, uint32_t passes, bool rays,
                       const gpu::Image& turned, const gpu::Image& resolved, gpu::GpuTimers* timers) const;

    const gpu::Context& ctx_;
    gpu::Pipeline gather_, clipGather_, rayGather_, resolve_, upsample_;
};

}  // namespace dvsgi::render
