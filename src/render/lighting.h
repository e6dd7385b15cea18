// Deferred direct lighting (compute): G-buffer + lights + shadow maps -> the
// direct-radiance image (RGBA32F, linear W m^-2 sr^-1, emission included).
#pragma once

#include "gpu/pipeline.h"
#include "gpu/resources.h"

namespace dvsgi::gpu {
class GpuTimers;
}

namespace dvsgi::render {

class GBufferPass;
class ShadowPass;

class LightingPass {
public:
    LightingPass(const gpu::Context& ctx, uint32_t width, uint32_t height);
    // Leaves `direct` in use::ComputeWrite.
    void record(VkCommandBuffer cmd, const GBufferPass& gbuffer, const ShadowPass& shadows, const gpu::Buffer& frame,
                const gpu::Buffer& lights, const gpu::Buffer& views, gpu::GpuTimers* timers) const;
    gpu::Image direct;

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
    uint32_t width_, height_;
};

}  // namespace dvsgi::render
