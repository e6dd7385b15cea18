#include "test_support.h"

#include <atomic>
#include <chrono>
#include <fstream>
#include <stdexcept>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include <gtest/gtest.h>

namespace scene_test {

TempDir::TempDir() {
    static std::atomic<int> counter{0};
    auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
    path_ = fs::temp_directory_path() /
            ("dvsgi_scene_test_" + std::to_string(stamp) + "_" + std::to_string(counter++));
    fs::create_directories(path_);
}

TempDir::~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

void writeText(const std::string& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary);
    out << text;
}

void writeBytes(const std::string& file, const std::vector<uint8_t>& bytes) {
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

void writePng(const std::string& file, int w, int h, const std::vector<uint8_t>& rgba) {
    if (!stbi_write_png(file.c_str(), w, h, 4, rgba.data(), w * 4)) throw std::runtime_error("png write failed");
}

std::vector<uint8_t> pngBytes(int w, int h, const std::vector<uint8_t>& rgba) {
    std::vector<uint8_t> out;
    auto sink = [](void* ctx, void* data, int size) {
        auto* v = static_cast<std::vector<uint8_t>*>(ctx);
        v->insert(v->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
    };
    stbi_write_png_to_func(sink, &out, w, h, 4, rgba.data(), w * 4);
    return out;
}

std::string base64(const std::vector<uint8_t>& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        uint32_t v = (bytes[i] << 16) | (bytes[i + 1] << 8) | bytes[i + 2];
        for (int k = 3; k >= 0; --k) out.push_back(table[(v >> (6 * k)) & 63]);
    }
    size_t rest = bytes.size() - i;
    if (rest > 0) {
        uint32_t v = bytes[i] << 16;
        if (rest == 2) v |= bytes[i + 1] << 8;
        out.push_back(table[(v >> 18) & 63]);
        out.push_back(table[(v >> 12) & 63]);
        out.push_back(rest == 2 ? table[(v >> 6) & 63] : '=');
        out.push_back('=');
    }
    return out;
}

GltfBuilder::GltfBuilder() {
    doc = {{"asset", {{"version", "2.0"}}}};
}

int GltfBuilder::addView(const void* data, size_t bytes, int stride) {
    while (bin.size() % 4) bin.push_back(0);
    json view = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}};
    if (stride) view["byteStride"] = stride;
    const auto* p = static_cast<const uint8_t*>(data);
    bin.insert(bin.end(), p, p + bytes);
    doc["bufferViews"].push_back(view);
    return static_cast<int>(doc["bufferViews"].size()) - 1;
}

int GltfBuilder::addAccessor(int view, int componentType, size_t count, const std::string& type, size_t byteOffset,
                             bool normalized) {
    json a = {{"componentType", componentType}, {"count", count}, {"type", type}};
    if (view >= 0) a["bufferView"] = view;
    if (byteOffset) a["byteOffset"] = byteOffset;
    if (normalized) a["normalized"] = true;
    doc["accessors"].push_back(a);
    return static_cast<int>(doc["accessors"].size()) - 1;
}

int GltfBuilder::addVec3(const std::vector<glm::vec3>& v) {
    return addAccessor(addView(v.data(), v.size() * sizeof(glm::vec3)), kFloat, v.size(), "VEC3");
}

int GltfBuilder::addVec4(const std::vector<glm::vec4>& v) {
    return addAccessor(addView(v.data(), v.size() * sizeof(glm::vec4)), kFloat, v.size(), "VEC4");
}

int GltfBuilder::addScalars(const std::vector<float>& v) {
    return addAccessor(addView(v.data(), v.size() * sizeof(float)), kFloat, v.size(), "SCALAR");
}

int GltfBuilder::addIndices(const std::vector<uint32_t>& idx, int componentType) {
    std::vector<uint8_t> raw;
    for (uint32_t i : idx) {
        if (componentType == kUByte) {
            raw.push_back(static_cast<uint8_t>(i));
        } else if (componentType == kUShort) {
            uint16_t s = static_cast<uint16_t>(i);
            raw.insert(raw.end(), reinterpret_cast<uint8_t*>(&s), reinterpret_cast<uint8_t*>(&s) + 2);
        } else {
            raw.insert(raw.end(), reinterpret_cast<uint8_t*>(&i), reinterpret_cast<uint8_t*>(&i) + 4);
        }
    }
    return addAccessor(addView(raw.data(), raw.size()), componentType, idx.size(), "SCALAR");
}

int GltfBuilder::addMesh(int position, int normal, int indices, int material, const std::string& name) {
    json prim = {{"attributes", {{"POSITION", position}}}};
    if (normal >= 0) prim["attributes"]["NORMAL"] = normal;
    if (indices >= 0) prim["indices"] = indices;
    if (material >= 0) prim["material"] = material;
    json mesh = {{"primitives", json::array({prim})}};
    if (!name.empty()) mesh["name"] = name;
    doc["meshes"].push_back(mesh);
    return static_cast<int>(doc["meshes"].size()) - 1;
}

int GltfBuilder::addTriangleMesh(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices,
                                 int material) {
    std::vector<glm::vec3> normals(positions.size(), glm::vec3(0, 0, 1));
    // Sequenced so that accessors 0, 1, 2 are position, normal, indices.
    int pos = addVec3(positions);
    int nrm = addVec3(normals);
    int idx = addIndices(indices, kUShort);
    return addMesh(pos, nrm, idx, material);
}

int GltfBuilder::addNode(const json& node) {
    doc["nodes"].push_back(node);
    return static_cast<int>(doc["nodes"].size()) - 1;
}

std::string GltfBuilder::writeGltfExternal(const TempDir& dir, const std::string& name, const std::string& binName) {
    doc["buffers"] = json::array({{{"byteLength", bin.size()}, {"uri", binName}}});
    writeBytes(dir.file(binName), bin);
    writeText(dir.file(name), doc.dump(1));
    return dir.file(name);
}

std::string GltfBuilder::writeGltfDataUri(const TempDir& dir, const std::string& name) {
    doc["buffers"] = json::array(
        {{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}});
    writeText(dir.file(name), doc.dump());
    return dir.file(name);
}

std::vector<uint8_t> GltfBuilder::glbBytes() {
    while (bin.size() % 4) bin.push_back(0);
    doc["buffers"] = json::array({{{"byteLength", bin.size()}}});
    std::string text = doc.dump();
    while (text.size() % 4) text.push_back(' ');
    std::vector<uint8_t> out;
    auto u32 = [&](uint32_t v) { out.insert(out.end(), reinterpret_cast<uint8_t*>(&v), reinterpret_cast<uint8_t*>(&v) + 4); };
    out.insert(out.end(), {'g', 'l', 'T', 'F'});
    u32(2);
    u32(static_cast<uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
    u32(static_cast<uint32_t>(text.size()));
    u32(0x4E4F534Au);
    out.insert(out.end(), text.begin(), text.end());
    u32(static_cast<uint32_t>(bin.size()));
    u32(0x004E4942u);
    out.insert(out.end(), bin.begin(), bin.end());
    return out;
}

std::string GltfBuilder::writeGlb(const TempDir& dir, const std::string& name) {
    writeBytes(dir.file(name), glbBytes());
    return dir.file(name);
}

GltfBuilder triangleScene() {
    GltfBuilder b;
    b.addTriangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2});
    b.addNode({{"mesh", 0}});
    b.doc["scenes"] = json::array({{{"nodes", {0}}}});
    return b;
}

std::string loadError(const std::string& path, const dvsgi::scene::LoadOptions& options) {
    try {
        dvsgi::scene::loadScene(path, options);
    } catch (const dvsgi::scene::LoadError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no LoadError for " << path;
    return {};
}

void expectError(const std::string& path, const std::string& fragment) {
    std::string msg = loadError(path);
    EXPECT_EQ(msg.rfind(path, 0), 0u) << "message does not start with the path: " << msg;
    EXPECT_NE(msg.find(fragment), std::string::npos) << "'" << fragment << "' not in: " << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "message is not one line: " << msg;
}

}  // namespace scene_test
