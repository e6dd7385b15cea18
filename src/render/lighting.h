// Deferred direct lighting (compute): G-buffer + lights + shadow maps -> the
// direct-radiance image (RGBA32F, linear W m^-2 sr^-1, emission included).
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

// Shadow cones (paper Table V): a cone toward each light through the voxel
// volumes instead of the shadow maps.
// They march like the gather's cones (RenderSettings::cones).
struct ShadowConeSettings {
    bool enabled = false;
    float apertureDegrees = 5.0f;  // full cone angle
};

struct LightingInputs {
    const GBuffer& gbuffer;
    const gpu::Image& shadowMap;
    const gpu::Image& shadowGradient;  // the casters' depth gradients (FrameTargets::shadowGradient)
    const Samplers& samplers;
    const gpu::Buffer& frame;
    const gpu::Buffer& lights;
    const gpu::Buffer& views;
    const vxgi::VoxelVolumes& volumes;  // radiance and directional (shadow cones, area-light visibility)
    const vxgi::ClipTrace* clip = nullptr;  // clipmap levels to trace instead of `volumes`
    bool areaLights = false;                // `lights` holds LIGHT_AREA patches
    // This frame's voxels' normals and occupancy bits: area lights' visibility
    // by a ray per patch instead of a cone (a fitted grid's; null: cones).
    const vxgi::RayData* rays = nullptr;
    float rayOffsetVoxels = 1.0f;  // the rays' origins off the surface (GatherSettings::rayOffsetVoxels)
};

class LightingPass {
public:
    // clipmap: also the pipeline whose cones trace clipmap levels (compiled only when asked for).
    explicit LightingPass(const gpu::Context& ctx, bool clipmap = false);
    // Writes `direct` and `visibility` (FrameTargets) whole.
    void record(VkCommandBuffer cmd, gpu::Tracker& tracker, const LightingInputs& in, const gpu::Image& direct,
                const gpu::Image& visibility, const ShadowConeSettings& shadowCones, const vxgi::ConeSettings& cone,
                gpu::GpuTimers* timers) const;

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_, clipPipeline_;
    gpu::Pipeline rays_;      // area lights' visibility by rays (AREA_RAYS)
    gpu::Pipeline mapsOnly_;  // no shadow cones, no area lights: the variant without the voxel cones
};

}  // namespace dvsgi::render
