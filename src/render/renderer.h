// One frame of dvsgi, headless: shadow maps -> G-buffer -> direct lighting ->
// composite. docs/ARCHITECTURE.md lists the passes with what they read and write.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "gpu/timers.h"
#include "image/image_io.h"
#include "scene/scene.h"

namespace dvsgi::gpu {
class Context;
class Buffer;
}

namespace dvsgi::render {

struct RenderSettings {
    uint32_t width = 512;
    uint32_t height = 512;
    uint32_t supersample = 1;       // internal resolution = k * output, box-filtered
    uint32_t shadowMapSize = 2048;
    int camera = 0;
    bool shadows = true;
    float normalOffsetTexels = 1.5f;  // shadow lookup offset along the normal
};

struct FrameStats {
    std::vector<gpu::TimerResult> passes;
    double gpuMs = 0.0;  // sum of the passes
};

struct MemoryItem {
    std::string name;
    uint64_t bytes;
};

class SceneGpu;
class ShadowPass;
class GBufferPass;
class LightingPass;
class CompositePass;

class Renderer {
public:
    Renderer(const gpu::Context& ctx, const scene::Scene& scene, const RenderSettings& settings);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    FrameStats renderFrame();                  // records, submits and waits
    image::ImageRGBA32F readOutput() const;    // linear radiance, output size
    std::vector<MemoryItem> memory() const;
    const scene::PlacedCamera& camera() const { return camera_; }
    const std::vector<std::string>& warnings() const { return warnings_; }
    uint64_t triangleCount() const;

private:
    void updateFrameConstants();

    const gpu::Context& ctx_;
    const scene::Scene& scene_;
    RenderSettings settings_;
    scene::PlacedCamera camera_;
    std::vector<std::string> warnings_;
    uint32_t lightCount_ = 0, viewCount_ = 0;
    std::unique_ptr<SceneGpu> sceneGpu_;
    std::unique_ptr<gpu::Buffer> frame_, lights_, views_;
    std::unique_ptr<ShadowPass> shadows_;
    std::unique_ptr<GBufferPass> gbuffer_;
    std::unique_ptr<LightingPass> lighting_;
    std::unique_ptr<CompositePass> composite_;
    std::unique_ptr<gpu::GpuTimers> timers_;
};

// Camera matrices for an image of the given size (Vulkan clip space, Y flipped
// so row 0 is the top of the image).
glm::mat4 viewMatrix(const scene::PlacedCamera& camera);
glm::mat4 projectionMatrix(const scene::PlacedCamera& camera, uint32_t width, uint32_t height);

}  // namespace dvsgi::render
