// G-buffer: base colour + metallic, normal + roughness, emission + coverage
// (all RGBA16F so albedo keeps better than 0.1 % precision), and D32 depth.
#pragma once

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "render/frame_resources.h"

namespace dvsgi::gpu {
class GpuTimers;
class Tracker;
}

namespace dvsgi::gpuscene {
class SceneGpu;
struct DrawList;
}

namespace dvsgi::render {

using gpuscene::SceneGpu;

// The G-buffer's fragment shader: the variant that can discard (MASK/BLEND
// coverage) or the one for opaque materials, which must not, so the depth test
// can run before shading; each also without the emissive and metallic-roughness
// samples, for materials that have no such texture (`baseColorOnly`).
gpu::Spirv gbufferFragmentShader(bool alphaTested, bool baseColorOnly = false);

class GBufferPass {
public:
    GBufferPass(const gpu::Context& ctx, const SceneGpu& scene);
    // Rasterizes `draws` of the scene into `out` (FrameTargets::gbuffer) as
    // seen by `frame` (gpuscene::visibleDraws culled with the same view).
    void record(VkCommandBuffer cmd, gpu::Tracker& tracker, const SceneGpu& scene, const gpuscene::DrawList& draws,
                const gpu::Buffer& frame, const GBuffer& out, gpu::GpuTimers* timers) const;

private:
    const gpu::Context& ctx_;
    gpu::Pipeline opaque_;       // OPAQUE materials: no discard, early depth test
    gpu::Pipeline alphaTested_;  // MASK and BLEND materials
    gpu::Pipeline opaqueBaseColorOnly_, alphaTestedBaseColorOnly_;  // the same, base colour sampled alone
};

}  // namespace dvsgi::render
