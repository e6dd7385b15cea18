// `dvsgi view`: the interactive viewer (issue #6). A GLFW window with a Vulkan
// swapchain; every frame runs exactly the passes of the headless renderer
// (render::Renderer::renderFrame) and then blits the output image into the
// swapchain image (app/view_swapchain.cpp): presentation is the only addition.
#pragma once

#include "options.h"

namespace dvsgi::app {

// True when this build has the viewer (GLFW was found at configure time).
bool viewAvailable();

// Returns the process exit code: 0, 1 without a display or on failure, 3 when
// --validate saw validation errors. Errors are printed as one line on stderr.
int runView(const RenderOptions& options);

}  // namespace dvsgi::app
