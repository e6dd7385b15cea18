// Shared state and helpers of the glTF importer, split across gltf_*.cpp.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/import_util.h"
#include "scene/load.h"

namespace dvsgi::scene::gltf {

using json = nlohmann::json;

struct Context {
    std::string path;               // as the caller gave it: every message starts with it
    std::filesystem::path dir;      // relative URIs resolve against this
    json doc;
    std::vector<std::vector<uint8_t>> buffers;
    std::vector<uint8_t> glbBin;    // the GLB BIN chunk, if any
    bool hasGlbBin = false;
    Scene scene;
    std::vector<int> cameraMap;     // glTF camera index -> Scene camera, -1 = skipped
    bool allowOutside = false;      // LoadOptions::allowOutsideReferences

    [[noreturn]] void fail(const std::string& what) const { throw LoadError(detail::printable(path + ": " + what)); }
    void warn(const std::string& what) { scene.warnings.push_back(detail::printable(path + ": " + what)); }
};

// ---- JSON access with validation (gltf_loader.cpp) ----
// `where` names the element in messages, e.g. "accessor 3".

// The array doc[key], or an empty array when absent; a non-array is an error.
const json& arrayOrEmpty(const Context& c, const json& obj, const char* key, const std::string& where);
const json& requireObject(const Context& c, const json& arr, size_t i, const std::string& where);
bool has(const json& obj, const char* key);
// An index value (e.g. an element of "children") checked against `count`
// elements of the collection `what`; `key` only names it in messages.
int checkIndex(const Context& c, const json& v, const char* key, size_t count, const std::string& where,
               const char* what);
// An index field checked against `count` elements of the collection `what`.
int optIndex(const Context& c, const json& obj, const char* key, size_t count, const std::string& where,
             const char* what);
int reqIndex(const Context& c, const json& obj, const char* key, size_t count, const std::string& where,
             const char* what);
double optNumber(const Context& c, const json& obj, const char* key, double def, const std::string& where);
double reqNumber(const Context& c, const json& obj, const char* key, const std::string& where);
uint64_t optUInt(const Context& c, const json& obj, const char* key, uint64_t def, const std::string& where);
std::string optString(const Context& c, const json& obj, const char* key, const std::string& def,
                      const std::string& where);
bool optBool(const Context& c, const json& obj, const char* key, bool def, const std::string& where);
// A fixed-length number array (e.g. a colour); `def` when absent.
std::vector<float> optFloats(const Context& c, const json& obj, const char* key, size_t n,
                             const std::vector<float>& def, const std::string& where);

// Decodes the payload of a data: URI (base64 only). Errors name `where`.
std::vector<uint8_t> decodeDataUri(const Context& c, const std::string& uri, const std::string& where);
// Percent-decodes a relative URI and resolves it against the glTF's folder,
// confined to it unless allowOutside. Errors name `where` and the URI.
std::filesystem::path resolveUri(const Context& c, const std::string& uri, const std::string& where);

// ---- Accessors (gltf_accessors.cpp) ----

// The number of accessors in the document, for index checks.
size_t accessorCount(const Context& c);

// Reads accessor `index` as float tuples (normalized integers mapped to
// [0,1] / [-1,1]). `types` lists the accepted accessor types, e.g. {"VEC3"}.
// Non-finite values are an error unless `allowNonFinite` (normals, which
// validateScene repairs).
std::vector<glm::vec4> readFloatAccessor(const Context& c, int index, std::initializer_list<const char*> types,
                                         const std::string& use, bool allowNonFinite = false);
std::vector<uint32_t> readIndexAccessor(const Context& c, int index, const std::string& use);
// Bytes of buffer view `index` (validated against its buffer).
std::pair<const uint8_t*, size_t> bufferViewBytes(const Context& c, int index);

// ---- Parts of the document (gltf_meshes.cpp, gltf_materials.cpp, gltf_objects.cpp) ----
void loadMeshes(Context& c);
void loadMaterials(Context& c);
void loadCameras(Context& c);
void loadLights(Context& c);
void loadNodes(Context& c);
void loadDefaultScene(Context& c);
void loadAnimations(Context& c);

}  // namespace dvsgi::scene::gltf
