// loadScene: format dispatch plus the guarantees every caller relies on (at
// least one material, every primitive's material valid, a camera and a light).
#include <filesystem>

#include "scene/import_util.h"
#include "scene/load.h"

namespace dvsgi::scene {

namespace {

void ensureValidMaterials(Scene& scene) {
    bool needDefault = scene.materials.empty();
    for (const Primitive& p : scene.primitives) needDefault = needDefault || p.material >= scene.materials.size();
    if (!needDefault) return;
    Material m;
    m.name = "default";
    m.metallicFactor = 0.0f;  // plain white diffuse
    m.roughnessFactor = 1.0f;
    const uint32_t count = static_cast<uint32_t>(scene.materials.size());
    scene.materials.push_back(m);
    for (Primitive& p : scene.primitives)
        if (p.material >= count) p.material = count;
}

}  // namespace

Scene loadScene(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw LoadError(path + ": no such file");
    std::string ext = detail::lowercase(std::filesystem::path(path).extension().string());
    Scene scene;
    if (ext == ".gltf" || ext == ".glb") {
        scene = loadGltf(path);
    } else if (ext == ".obj" || ext == ".ply") {
        scene = loadWithAssimp(path);
    } else {
        throw LoadError(path + ": unsupported scene format '" + ext + "' (supported: .gltf .glb .obj .ply)");
    }
    ensureValidMaterials(scene);
    addDefaults(scene);
    return scene;
}

}  // namespace dvsgi::scene
