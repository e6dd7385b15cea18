// Composition of the frame's terms into the output image at output size
// (box-averaging k x k internal pixels when supersampling).
#pragma once

#include "gpu/pipeline.h"
#include "gpu/resources.h"

namespace dvsgi::gpu {
class GpuTimers;
}

namespace dvsgi::render {

class CompositePass {
public:
    CompositePass(const gpu::Context& ctx, uint32_t width, uint32_t height, uint32_t supersample);
    // `direct` must be in use::ComputeWrite; leaves `output` in use::ComputeWrite.
    void record(VkCommandBuffer cmd, const gpu::Image& direct, gpu::GpuTimers* timers) const;
    gpu::Image output;  // RGBA32F at output size

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
    uint32_t width_, height_, supersample_;
};

}  // namespace dvsgi::render
