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

Scene loadScene(const std::string& path, const LoadOptions& options) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    // Say what the path is when it is not a file: "no such file" for a
    // directory or a FIFO sends the user looking in the wrong place.
    if (st.type() == fs::file_type::not_found || (ec && st.type() == fs::file_type::none))
        throw LoadError(detail::printable(path + ": no such file"));
    if (st.type() == fs::file_type::directory)
        throw LoadError(detail::printable(path + ": is a directory, not a scene file"));
    if (st.type() != fs::file_type::regular)
        throw LoadError(detail::printable(path + ": is not a regular file (a FIFO, socket or device cannot be a scene)"));
    std::string ext = detail::lowercase(fs::path(path).extension().string());
    Scene scene;
    if (ext == ".gltf" || ext == ".glb") {
        scene = loadGltf(path, options);
    } else if (ext == ".obj" || ext == ".ply") {
        scene = loadWithAssimp(path, options);
    } else {
        throw LoadError(detail::printable(path + ": unsupported scene format '" + ext +
                                          "' (supported: .gltf .glb .obj .ply)"));
    }
    validateScene(scene);
    ensureValidMaterials(scene);
    addDefaults(scene);
    return scene;
}

}  // namespace dvsgi::scene
