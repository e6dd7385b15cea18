// Composition of the frame's terms into the output image at output size
// (box-averaging k x k internal pixels when supersampling).
#pragma once

#include "gpu/pipeline.h"
#include "gpu/resources.h"

namespace dvsgi::gpu {
class GpuTimers;
class Tracker;
}

namespace dvsgi::render {

struct CompositeInputs {
    const gpu::Image& direct;      // internal size (FrameTargets)
    const gpu::Image& visibility;
    const gpu::Image& diffuse;
    const gpu::Image& specular;
    const gpu::Image& base;  // G-buffer base colour + metallic (the diffuse term's albedo), internal size
    VkSampler point;
    bool indirect;  // false: no cone tracing ran, `diffuse` and `specular` are not read
};

class CompositePass {
public:
    explicit CompositePass(const gpu::Context& ctx);
    // Writes `output` whole, box-averaging supersample x supersample internal pixels.
    void record(VkCommandBuffer cmd, gpu::Tracker& tracker, const CompositeInputs& in, const gpu::Image& output,
                uint32_t supersample, uint32_t term, bool applyAO, gpu::GpuTimers* timers) const;

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
};

}  // namespace dvsgi::render
