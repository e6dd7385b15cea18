// Shadow maps for every light: one layer of a depth array per view, and beside
// it each texel's caster's depth gradient (the lookup, lib/shadow_map.glsl,
// compares a receiver with the caster's plane; shared/shadow_pass.h).
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
enum class DrawFilter;
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
// own directional view: every focus whose texels are finer than the
// scene-wide view's. (At 0.7, one Sponza under a 40 m window had no focus and
// ten Sponzas had one, so the same place got its shadow edges from two texel
// grids, 0.050 relative RMSE apart; docs/clipmap.md, "Ten Sponzas".)
inline constexpr float kShadowFocusFraction = 1.0f;

// `halfSide` where it is worth a view of its own in a scene of `bounds`, else 0.
float shadowFocusRadius(const scene::Bounds& bounds, float halfSide);

// Builds the GPU light records and their shadow views from placed lights.
LightSetup setupLights(const std::vector<scene::PlacedLight>& lights, const scene::Bounds& bounds,
                       uint32_t shadowMapSize, bool shadows, const ShadowFocus& focus = {});

// Static geometry's depth is kept between frames: a view is rendered again
// only when it (its light, the bounds, a focus that moved) or the static
// geometry changed. With dynamic draws in the scene a copy of it (`cache`) is restored
// into the map each frame and only the dynamic draws are rendered over it;
// without, the map itself is kept.
enum class StaticShadows {
    Kept,      // static geometry as last frame: each view's depth is reused while that view is unchanged
    Changed,   // static geometry moved: render it again and keep it
    Uncached,  // render every draw into the map and keep nothing (a frame that stands for an
               // everything-dynamic one: the bench's, after Renderer::revoxelizeStatic)
};

// What ShadowPass renders (FrameTargets::shadowMap, shadowGradient): arrays of
// the same size and layers.
struct ShadowTargets {
    const gpu::Image& depth;  // D32
    const gpu::Image& gradient;  // RG16F
};

class ShadowPass {
public:
    ShadowPass(const gpu::Context& ctx, const SceneGpu& scene);
    // Renders view v of `views` (`hostViews` on the host) into layer v of `map`.
    void record(VkCommandBuffer cmd, gpu::Tracker& tracker, const SceneGpu& scene, const gpu::Buffer& views,
                const std::vector<shader::GpuShadowView>& hostViews, const ShadowTargets& map, StaticShadows statics,
                gpu::GpuTimers* timers);
    // Bytes of the kept static depth and gradients (0 when the map itself is kept).
    VkDeviceSize cacheBytes() const {
        return cache_.handle() ? cache_.memorySize() + gradientCache_.memorySize() : 0;
    }
    // Layers whose static depth the last record() reused (tests).
    uint32_t reusedLayers() const { return reusedLayers_; }
    // Triangles the last record() drew, over all its views.
    uint64_t drawnTriangles() const { return drawnTriangles_; }
    bool reusedStatic() const { return reusedLayers_ > 0 && reusedLayers_ == keptViews_.size(); }

private:
    // `layers`: only the views marked true (null: every view).
    void render(VkCommandBuffer cmd, gpu::Tracker& tracker, const SceneGpu& scene, const gpu::Buffer& views,
                const std::vector<shader::GpuShadowView>& hostViews, const ShadowTargets& map,
                gpuscene::DrawFilter draws, bool clear, const std::vector<bool>* layers);
    void copyLayers(VkCommandBuffer cmd, gpu::Tracker& tracker, const gpu::Image& from, const gpu::Image& to,
                    VkImageAspectFlags aspect, uint32_t layers) const;

    const gpu::Context& ctx_;
    gpu::Pipeline opaque_;       // depth and gradient, no discard (the depth test runs first)
    gpu::Pipeline alphaTested_;  // discards where MASK/BLEND coverage says there is no surface
    bool hasDynamic_ = false;
    gpu::Image cache_;       // static draws' depth, when there are dynamic draws
    gpu::Image gradientCache_;  // and their gradients
    std::vector<shader::GpuShadowView> keptViews_;
    uint64_t keptMap_ = 0;  // serial of the map the kept depth belongs to (0: nothing kept)
    uint32_t reusedLayers_ = 0;
    uint64_t drawnTriangles_ = 0;
};

}  // namespace dvsgi::render
