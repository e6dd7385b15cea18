// Shadow maps for every light: one layer of a depth array per view.
// Directional: an orthographic view fitted to the scene's bounding sphere,
// preceded, when a focus is given that is much smaller than the scene, by one
// fitted to the focus (a sphere around the camera: the shader uses it for the
// points inside it), so a large scene keeps fine shadows near the camera.
// Spot: a perspective view covering the outer cone. Point: six 90-degree views.
#pragma once

#include <vector>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "scene/scene.h"
#include "shared/scene_data.h"

namespace dvsgi::gpu {
class GpuTimers;
class Tracker;
}

namespace dvsgi::gpuscene {
class SceneGpu;
}

namespace dvsgi::render {

using gpuscene::SceneGpu;

struct LightSetup {
    std::vector<shader::GpuLight> lights;
    std::vector<shader::GpuShadowView> views;
};

// Where directional shadow maps need their detail: a square of half-side
// `radius` across the light around `centre` (radius 0: none).
struct ShadowFocus {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
};

// A focus smaller than this fraction of the scene's bounding radius gets its
// own directional view; a larger one would gain little detail.
inline constexpr float kShadowFocusFraction = 0.7f;

// `halfSide` where it is worth a view of its own in a scene of `bounds`, else 0.
float shadowFocusRadius(const scene::Bounds& bounds, float halfSide);

// Builds the GPU light records and their shadow views from placed lights.
LightSetup setupLights(const std::vector<scene::PlacedLight>& lights, const scene::Bounds& bounds,
                       uint32_t shadowMapSize, bool shadows, const ShadowFocus& focus = {});

class ShadowPass {
public:
    ShadowPass(const gpu::Context& ctx, const SceneGpu& scene);
    // Renders view v of `views` into layer v of `map` (FrameTargets::shadowMap).
    void record(VkCommandBuffer cmd, gpu::Tracker& tracker, const SceneGpu& scene, const gpu::Buffer& views,
                uint32_t viewCount, const gpu::Image& map, gpu::GpuTimers* timers) const;

private:
    const gpu::Context& ctx_;
    gpu::Pipeline opaque_;       // depth only: no fragment shader, so no fragment work
    gpu::Pipeline alphaTested_;  // discards where MASK/BLEND coverage says there is no surface
};

}  // namespace dvsgi::render
