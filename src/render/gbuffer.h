// G-buffer: base colour + metallic, normal + roughness, emission + coverage
// (all RGBA16F so albedo keeps better than 0.1 % precision), and D32 depth.
#pragma once

#include "gpu/pipeline.h"
#include "gpu/resources.h"

namespace dvsgi::gpu {
class GpuTimers;
}

namespace dvsgi::render {

class SceneGpu;

class GBufferPass {
public:
    static constexpr VkFormat kColorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

    GBufferPass(const gpu::Context& ctx, const SceneGpu& scene, uint32_t width, uint32_t height);
    // Leaves every target in use::ShaderRead (depth in use::DepthRead).
    void record(VkCommandBuffer cmd, const SceneGpu& scene, const gpu::Buffer& frame, gpu::GpuTimers* timers) const;

    gpu::Image base, normal, emission, depth;
    gpu::Sampler pointSampler;
    uint64_t memoryBytes() const;

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
    uint32_t width_, height_;
};

}  // namespace dvsgi::render
