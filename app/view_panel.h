// The Dear ImGui panel of `dvsgi view` (Debian's libimgui-dev, whose static
// library carries the GLFW and Vulkan backends): renderer parameters, lights
// and dynamic objects, per-pass GPU timings with a frame-time graph, GPU
// memory, and the screenshot button. Drawn over the presented image inside the
// swapchain's render pass; it never touches the renderer's own passes.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "options.h"

struct GLFWwindow;

namespace dvsgi::gpu {
class Context;
}
namespace dvsgi::render {
class Renderer;
struct FrameStats;
}

namespace dvsgi::app {

class Swapchain;

class ViewPanel {
public:
    ViewPanel(const gpu::Context& ctx, GLFWwindow* window, const Swapchain& swapchain);
    ~ViewPanel();
    ViewPanel(const ViewPanel&) = delete;
    ViewPanel& operator=(const ViewPanel&) = delete;

    // What the user asked for this frame.
    struct Actions {
        bool settingsChanged = false;  // a renderer setting changed: Renderer::applySettings, or a new one
        bool sceneEdited = false;      // a light or dynamic node changed: Renderer::sceneChanged()
        bool recreateSwapchain = false;  // vsync toggled
        bool screenshot = false;
        int camera = -1;               // a scene camera picked
    };

    // Builds the UI for this frame (call once per frame before record()).
    Actions build(RenderOptions& options, render::Renderer& renderer, const render::FrameStats& stats,
                  double frameMs, float& flySpeed, const char* presentMode);
    // Records the UI's draw commands; inside the swapchain's render pass.
    void record(VkCommandBuffer cmd);

    bool wantsMouse() const;
    bool wantsKeyboard() const;
    // Shown at the top of the panel (e.g. why a setting was reverted); empty clears it.
    void setError(std::string message) { error_ = std::move(message); }

private:
    std::string error_;
    const gpu::Context& ctx_;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    std::vector<float> frameMs_, gpuMs_;  // the graph's history
};

}  // namespace dvsgi::app
