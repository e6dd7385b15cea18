// Scene import entry points. Every failure throws LoadError with a message that
// names the file (and, where it helps, the glTF element) so the CLI can print it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace dvsgi::scene {

struct LoadError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct LoadOptions {
    // Buffers, images, MTL files and textures must lie inside the scene file's
    // folder (after resolving symlinks); true lifts that for trusted scenes.
    bool allowOutsideReferences = false;
};

// Dispatch by extension: .gltf/.glb (own parser), .obj/.ply (assimp).
// Validates the result (docs/RELIABILITY.md) and adds defaults (addDefaults)
// when the file has no camera or no light.
Scene loadScene(const std::string& path, const LoadOptions& options = {});

Scene loadGltf(const std::string& path, const LoadOptions& options = {});
Scene loadWithAssimp(const std::string& path, const LoadOptions& options = {});  // OBJ+MTL, PLY

// The OBJ/PLY path on bytes already in memory (`ext` is ".obj" or ".ply";
// `path` only names the input in messages). An OBJ's mtllib cannot be
// resolved this way; the fuzz targets use it.
Scene loadWithAssimpFromMemory(const std::string& path, const std::string& ext, const uint8_t* data, size_t size);
// The glTF/GLB parser on bytes in memory; relative URIs resolve against `dir`.
Scene loadGltfFromMemory(const std::string& path, const std::vector<uint8_t>& bytes, const LoadOptions& options = {});

// The checks loadScene applies after any importer: non-finite or oversized
// values, negative radiometric values, degenerate cameras, unusable normals.
// Throws LoadError naming `scene.source`; repairs are added as warnings.
void validateScene(Scene& scene);

// The built-in Cornell box: geometry, materials, camera and lights of
// shared/scenes/cornell-box/cornell-lights.gltf, without reading any file.
Scene builtinCornellBox();

}  // namespace dvsgi::scene
