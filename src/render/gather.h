// Per-pixel voxel cone tracing (indirect diffuse + AO, specular) at the trace
// resolution, and the depth-aware upsampling to the internal resolution.
#pragma once

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "shared/gather_data.h"
#include "vxgi/cone_settings.h"

namespace dvsgi::gpu {
class GpuTimers;
}
namespace dvsgi::vxgi {
class VoxelVolumes;
}

namespace dvsgi::render {

class GBufferPass;

// What the gather adds to the shared cone settings (RenderSettings::cones).
struct GatherSettings {
    float aoLambda = 0.5f;        // f(r) = 1 / (1 + lambda r), r in voxels
    bool specular = true;
    float minSpecularDegrees = 1.0f;  // half-angle of the narrowest specular cone, degrees
    float traceScale = 1.0f;      // trace resolution / internal resolution
};

class GatherPass {
public:
    GatherPass(const gpu::Context& ctx, uint32_t width, uint32_t height, float traceScale);
    // Writes `diffuse`/`specular` at internal size (upsampled when traceScale < 1),
    // left in use::ComputeWrite.
    void record(VkCommandBuffer cmd, const GBufferPass& gbuffer, const vxgi::VoxelVolumes& volumes,
                VkSampler volumeSampler, const gpu::Buffer& frame, const GatherSettings& settings,
                const vxgi::ConeSettings& cone,
                gpu::GpuTimers* timers) const;
    gpu::Image diffuse, specular;       // internal size, RGBA16F
    uint32_t traceWidth, traceHeight;

private:
    const gpu::Context& ctx_;
    gpu::Image lowDiffuse_, lowSpecular_;  // trace size (only when traceScale < 1)
    gpu::Pipeline gather_, upsample_;
    uint32_t width_, height_;
};

}  // namespace dvsgi::render
