// Shadow maps for every light: one layer of a depth array per view.
// Directional: an orthographic view fitted to the scene's bounding sphere.
// Spot: a perspective view covering the outer cone. Point: six 90-degree views.
#pragma once

#include <vector>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "scene/scene.h"
#include "shared/scene_data.h"

namespace dvsgi::gpu {
class GpuTimers;
}

namespace dvsgi::render {

class SceneGpu;

struct LightSetup {
    std::vector<shader::GpuLight> lights;
    std::vector<shader::GpuShadowView> views;
};

// Builds the GPU light records and their shadow views from placed lights.
LightSetup setupLights(const std::vector<scene::PlacedLight>& lights, const scene::Bounds& bounds,
                       uint32_t shadowMapSize, bool shadows);

class ShadowPass {
public:
    ShadowPass(const gpu::Context& ctx, const SceneGpu& scene, uint32_t size, uint32_t viewCount);
    // Renders every view; leaves the map in use::ShaderRead.
    void record(VkCommandBuffer cmd, const SceneGpu& scene, const gpu::Buffer& views, uint32_t viewCount,
                gpu::GpuTimers* timers) const;
    const gpu::Image& map() const { return map_; }
    const gpu::Sampler& sampler() const { return sampler_; }
    uint64_t memoryBytes() const { return map_.memorySize(); }

private:
    const gpu::Context& ctx_;
    gpu::Image map_;
    gpu::Sampler sampler_;
    gpu::Pipeline opaque_;       // depth only: no fragment shader, so no fragment work
    gpu::Pipeline alphaTested_;  // discards where MASK/BLEND coverage says there is no surface
    uint32_t size_;
};

}  // namespace dvsgi::render
