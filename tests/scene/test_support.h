// Fixture helpers for scene_tests: temporary folders, a small glTF writer and
// PNG writing, so each test builds exactly the file it needs.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "scene/load.h"

namespace scene_test {

namespace fs = std::filesystem;
using json = nlohmann::json;

// A fresh folder under the system temp dir, removed with the object.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const fs::path& path() const { return path_; }
    std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
    fs::path path_;
};

void writeText(const std::string& file, const std::string& text);
void writeBytes(const std::string& file, const std::vector<uint8_t>& bytes);
// RGBA8 PNG, row 0 at the top.
void writePng(const std::string& file, int w, int h, const std::vector<uint8_t>& rgba);
std::vector<uint8_t> pngBytes(int w, int h, const std::vector<uint8_t>& rgba);
std::string base64(const std::vector<uint8_t>& bytes);

enum : int { kByte = 5120, kUByte = 5121, kShort = 5122, kUShort = 5123, kUInt = 5125, kFloat = 5126 };

// Accumulates one binary buffer and the JSON that describes it.
class GltfBuilder {
public:
    GltfBuilder();

    json doc;
    std::vector<uint8_t> bin;

    // Appends raw bytes as a new buffer view (4-byte aligned); returns its index.
    int addView(const void* data, size_t bytes, int stride = 0);
    int addAccessor(int view, int componentType, size_t count, const std::string& type, size_t byteOffset = 0,
                    bool normalized = false);
    int addVec3(const std::vector<glm::vec3>& v);
    int addVec4(const std::vector<glm::vec4>& v);
    int addScalars(const std::vector<float>& v);
    int addIndices(const std::vector<uint32_t>& idx, int componentType);
    // One mesh with one primitive; returns the mesh index. Negative indices = omitted.
    int addMesh(int position, int normal, int indices, int material = -1, const std::string& name = "");
    // A flat triangle list on the z=0 plane with +Z normals and u16 indices.
    int addTriangleMesh(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices,
                        int material = -1);
    int addNode(const json& node);

    // Finalises buffers[0] and writes the document.
    std::string writeGltfExternal(const TempDir& dir, const std::string& name, const std::string& binName);
    std::string writeGltfDataUri(const TempDir& dir, const std::string& name);
    std::vector<uint8_t> glbBytes();
    std::string writeGlb(const TempDir& dir, const std::string& name);
};

// One triangle on a node of the default scene.
GltfBuilder triangleScene();

// Loads `path` and returns the LoadError message; fails the test if loading
// succeeds or throws anything else.
std::string loadError(const std::string& path, const dvsgi::scene::LoadOptions& options = {});
// The error starts with the path, contains `fragment` and is one line.
void expectError(const std::string& path, const std::string& fragment);

}  // namespace scene_test
