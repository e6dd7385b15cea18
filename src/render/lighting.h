// Deferred direct lighting (compute): G-buffer + lights + shadow maps -> the
// direct-radiance image (RGBA32F, linear W m^-2 sr^-1, emission included).
#pragma once

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "shared/voxel_data.h"
#include "vxgi/cone_settings.h"

namespace dvsgi::gpu {
class GpuTimers;
}
namespace dvsgi::vxgi {
class VoxelVolumes;
}

namespace dvsgi::render {

class GBufferPass;
class ShadowPass;

// Shadow cones (paper Table V): a cone toward each light through the voxel
// volumes instead of the shadow maps.
// They march like the gather's cones (RenderSettings::cones).
struct ShadowConeSettings {
    bool enabled = false;
    float apertureDegrees = 5.0f;  // full cone angle
};

class LightingPass {
public:
    LightingPass(const gpu::Context& ctx, uint32_t width, uint32_t height);
    // Leaves `direct` and `shadow` in use::ComputeWrite.
    void record(VkCommandBuffer cmd, const GBufferPass& gbuffer, const ShadowPass& shadows, const gpu::Buffer& frame,
                const gpu::Buffer& lights, const gpu::Buffer& views, const vxgi::VoxelVolumes& volumes,
                VkSampler volumeSampler, const ShadowConeSettings& shadowCones, const vxgi::ConeSettings& cone,
                gpu::GpuTimers* timers) const;
    gpu::Image direct;
    gpu::Image shadow;  // R16F: mean visibility of the lights facing each pixel

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
    uint32_t width_, height_;
};

}  // namespace dvsgi::render
