// Scene import entry points. Every failure throws LoadError with a message that
// names the file (and, where it helps, the glTF element) so the CLI can print it.
#pragma once

#include <stdexcept>
#include <string>

#include "scene/scene.h"

namespace dvsgi::scene {

struct LoadError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Dispatch by extension: .gltf/.glb (own parser), .obj/.ply (assimp).
// Adds defaults (addDefaults) when the file has no camera or no light.
Scene loadScene(const std::string& path);

Scene loadGltf(const std::string& path);
Scene loadWithAssimp(const std::string& path);  // OBJ+MTL, PLY

// The built-in Cornell box: geometry, materials, camera and lights of
// shared/scenes/cornell-box/cornell-lights.gltf, without reading any file.
Scene builtinCornellBox();

}  // namespace dvsgi::scene
