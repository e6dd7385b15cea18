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
    // Inputs in use::ComputeWrite (internal size). `indirect` false: no cone
    // tracing ran and `diffuse`/`specular` are not read. Leaves `output` in use::ComputeWrite.
    void record(VkCommandBuffer cmd, const gpu::Image& direct, const gpu::Image& shadow, const gpu::Image& diffuse,
                const gpu::Image& specular, bool indirect, uint32_t term, bool applyAO, gpu::GpuTimers* timers) const;
    gpu::Image output;  // RGBA32F at output size

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
    uint32_t width_, height_, supersample_;
};

}  // namespace dvsgi::render
