// `dvsgi render`: load, render one frame headless, write EXR/PNG/metrics.
#pragma once

#include "options.h"
#include "scene/scene.h"

namespace dvsgi::app {

// The scene with --dynamic and --add-model applied.
scene::Scene loadForOptions(const RenderOptions& options);

// Returns the process exit code. Errors are printed as one line on stderr.
int runRender(const RenderOptions& options);

}  // namespace dvsgi::app
