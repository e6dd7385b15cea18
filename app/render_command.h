// `dvsgi render`: load, render one frame headless, write EXR/PNG/metrics.
#pragma once

#include <optional>

#include "options.h"
#include "scene/camera_path.h"
#include "scene/scene.h"

namespace dvsgi::app {

// The scene with --dynamic and --add-model applied.
scene::Scene loadForOptions(const RenderOptions& options);
// The --camera-path keyframes (std::nullopt without the option); throws naming the file.
std::optional<scene::CameraPath> cameraPathFor(const RenderOptions& options);
// Adds `model` to `scene` as the --add-model object: scaled to `size` metres
// (0: 1/5 of the scene), moving on a circle, dynamic. `label` names it in errors.
void placeMovingModel(scene::Scene& scene, const scene::Scene& model, float size, const std::string& label);

// Returns the process exit code. Errors are printed as one line on stderr.
int runRender(const RenderOptions& options);

}  // namespace dvsgi::app
