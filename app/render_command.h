// `dvsgi render`: load, render one frame headless, write EXR/PNG/metrics.
#pragma once

#include "options.h"
#include "scene/scene.h"

namespace dvsgi::app {

// The scene with --dynamic and --add-model applied.
scene::Scene loadForOptions(const RenderOptions& options);
// Adds `model` to `scene` as the --add-model object: scaled to `size` metres
// (0: 1/5 of the scene), moving on a circle, dynamic. `label` names it in errors.
void placeMovingModel(scene::Scene& scene, const scene::Scene& model, float size, const std::string& label);

// Returns the process exit code. Errors are printed as one line on stderr.
int runRender(const RenderOptions& options);

}  // namespace dvsgi::app
