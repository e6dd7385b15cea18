// glTF 2.0 importer entry point: container formats (.gltf JSON, .glb),
// buffers, validated JSON access, and the order in which the parts are read.
#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cstdint>
#include <cmath>
#include <cstring>

#include "scene/gltf_internal.h"
#include "scene/import_util.h"

namespace dvsgi::scene::gltf {

// ---- validated JSON access ----

bool has(const json& obj, const char* key) { return obj.is_object() && obj.contains(key); }

const json& arrayOrEmpty(const Context& c, const json& obj, const char* key, const std::string& where) {
    static const json empty = json::array();
    if (!has(obj, key)) return empty;
    const json& v = obj.at(key);
    if (!v.is_array()) c.fail(where + ": '" + key + "' must be an array");
    return v;
}

const json& requireObject(const Context& c, const json& arr, size_t i, const std::string& where) {
    const json& v = arr.at(i);
    if (!v.is_object()) c.fail(where + " must be a JSON object");
    return v;
}

int checkIndex(const Context& c, const json& v, const char* key, size_t count, const std::string& where,
               const char* what) {
    if (!v.is_number_integer()) c.fail(where + ": '" + key + "' must be an integer index");
    // Compare as signed 64-bit so a negative index or a huge one cannot wrap.
    int64_t i = v.is_number_unsigned() ? static_cast<int64_t>(std::min<uint64_t>(v.get<uint64_t>(), INT64_MAX))
                                       : v.get<int64_t>();
    if (i < 0 || static_cast<uint64_t>(i) >= count || i > INT32_MAX)
        c.fail(where + ": " + what + " index " + std::to_string(i) + " out of range (" + std::to_string(count) +
               " " + what + (count == 1 ? "" : "s") + ")");
    return static_cast<int>(i);
}

int optIndex(const Context& c, const json& obj, const char* key, size_t count, const std::string& where,
             const char* what) {
    if (!has(obj, key)) return -1;
    return checkIndex(c, obj.at(key), key, count, where, what);
}

int reqIndex(const Context& c, const json& obj, const char* key, size_t count, const std::string& where,
             const char* what) {
    if (!has(obj, key)) c.fail(where + ": missing required '" + key + "'");
    return checkIndex(c, obj.at(key), key, count, where, what);
}

double optNumber(const Context& c, const json& obj, const char* key, double def, const std::string& where) {
    if (!has(obj, key)) return def;
    const json& v = obj.at(key);
    if (!v.is_number()) c.fail(where + ": '" + key + "' must be a number");
    double d = v.get<double>();
    // Everything is stored as float; a value that overflows it would turn
    // into infinity and poison transforms or light sums downstream.
    if (!(std::abs(d) <= static_cast<double>(FLT_MAX))) c.fail(where + ": '" + key + "' is out of range");
    return d;
}

double reqNumber(const Context& c, const json& obj, const char* key, const std::string& where) {
    if (!has(obj, key)) c.fail(where + ": missing required '" + key + "'");
    return optNumber(c, obj, key, 0.0, where);
}

uint64_t optUInt(const Context& c, const json& obj, const char* key, uint64_t def, const std::string& where) {
    if (!has(obj, key)) return def;
    const json& v = obj.at(key);
    if (!v.is_number_integer() || (v.is_number_integer() && !v.is_number_unsigned() && v.get<int64_t>() < 0))
        c.fail(where + ": '" + key + "' must be a non-negative integer");
    return v.get<uint64_t>();
}

std::string optString(const Context& c, const json& obj, const char* key, const std::string& def,
                      const std::string& where) {
    if (!has(obj, key)) return def;
    const json& v = obj.at(key);
    if (!v.is_string()) c.fail(where + ": '" + key + "' must be a string");
    return v.get<std::string>();
}

bool optBool(const Context& c, const json& obj, const char* key, bool def, const std::string& where) {
    if (!has(obj, key)) return def;
    const json& v = obj.at(key);
    if (!v.is_boolean()) c.fail(where + ": '" + key + "' must be true or false");
    return v.get<bool>();
}

std::vector<float> optFloats(const Context& c, const json& obj, const char* key, size_t n,
                             const std::vector<float>& def, const std::string& where) {
    if (!has(obj, key)) return def;
    const json& v = obj.at(key);
    if (!v.is_array() || v.size() != n)
        c.fail(where + ": '" + key + "' must be an array of " + std::to_string(n) + " numbers");
    std::vector<float> out(n);
    for (size_t i = 0; i < n; ++i) {
        if (!v[i].is_number()) c.fail(where + ": '" + key + "' must contain numbers only");
        double d = v[i].get<double>();
        if (!(std::abs(d) <= static_cast<double>(FLT_MAX))) c.fail(where + ": '" + key + "' is out of range");
        out[i] = static_cast<float>(d);
    }
    return out;
}

// ---- URIs ----

std::vector<uint8_t> decodeDataUri(const Context& c, const std::string& uri, const std::string& where) {
    size_t comma = uri.find(',');
    if (comma == std::string::npos) c.fail(where + ": malformed data URI");
    std::string header = uri.substr(0, comma);
    if (header.size() < 7 || header.compare(header.size() - 7, 7, ";base64") != 0)
        c.fail(where + ": only base64 data URIs are supported");
    std::vector<uint8_t> out;
    out.reserve((uri.size() - comma) * 3 / 4);
    uint32_t acc = 0;
    int bits = 0;
    for (size_t i = comma + 1; i < uri.size(); ++i) {
        char ch = uri[i];
        int v;
        if (ch >= 'A' && ch <= 'Z') v = ch - 'A';
        else if (ch >= 'a' && ch <= 'z') v = ch - 'a' + 26;
        else if (ch >= '0' && ch <= '9') v = ch - '0' + 52;
        else if (ch == '+' || ch == '-') v = 62;  // '-' and '_': the URL-safe alphabet
        else if (ch == '/' || ch == '_') v = 63;
        else if (ch == '=') break;                // padding ends the payload
        else if (ch == '\r' || ch == '\n' || ch == ' ') continue;
        else c.fail(where + ": invalid character in base64 data URI");
        acc = (acc << 6) | static_cast<uint32_t>(v);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out.push_back(static_cast<uint8_t>((acc >> bits) & 0xFF));
        }
    }
    return out;
}

std::filesystem::path resolveUri(const Context& c, const std::string& uri, const std::string& where) {
    // A scheme (http:, file:, ...) other than data: is nothing this importer
    // can fetch; say so instead of looking for a file named "http:".
    size_t colon = uri.find(':');
    if (colon != std::string::npos && colon > 1 && std::isalpha(static_cast<unsigned char>(uri[0])) &&
        uri.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789+.-") == colon)
        c.fail(where + ": URI '" + uri + "' has an unsupported scheme (only relative paths and data: URIs)");
    // URIs are percent-encoded (e.g. spaces as %20); file names are not.
    std::string decoded;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] != '%') {
            decoded.push_back(uri[i]);
            continue;
        }
        if (i + 2 >= uri.size() || !std::isxdigit(static_cast<unsigned char>(uri[i + 1])) ||
            !std::isxdigit(static_cast<unsigned char>(uri[i + 2])))
            c.fail(where + ": URI '" + uri + "' has a malformed percent escape");
        decoded.push_back(static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16)));
        i += 2;
    }
    std::string error;
    auto resolved = detail::confinedPath(c.dir, decoded, c.allowOutside, error);
    if (!resolved) c.fail(where + ": URI '" + uri + "' " + error);
    return *resolved;
}

namespace {

uint32_t readU32(const uint8_t* p) {
    uint32_t v;
    std::memcpy(&v, p, 4);
    return v;  // GLB is little-endian, as is every platform this project targets
}

// Splits a GLB container into its JSON text and optional BIN chunk.
std::string parseGlb(Context& c, const std::vector<uint8_t>& file) {
    if (file.size() < 20) c.fail("GLB file too short for its header");
    if (readU32(file.data() + 4) != 2) c.fail("unsupported GLB version " + std::to_string(readU32(file.data() + 4)));
    size_t total = readU32(file.data() + 8);
    if (total > file.size()) c.fail("GLB header length exceeds the file size");
    size_t pos = 12;
    std::string jsonText;
    bool haveJson = false;
    while (pos + 8 <= total) {
        size_t len = readU32(file.data() + pos);
        uint32_t type = readU32(file.data() + pos + 4);
        pos += 8;
        if (len > total - pos) c.fail("GLB chunk at byte " + std::to_string(pos - 8) + " runs past the end of the file");
        const uint8_t* data = file.data() + pos;
        if (!haveJson) {
            if (type != 0x4E4F534Au) c.fail("GLB first chunk is not JSON");
            jsonText.assign(reinterpret_cast<const char*>(data), len);
            haveJson = true;
        } else if (type == 0x004E4942u && !c.hasGlbBin) {
            c.glbBin.assign(data, data + len);
            c.hasGlbBin = true;
        }  // other chunk types are reserved: skip them, as the spec asks
        pos += len;
        pos = (pos + 3) & ~size_t(3);
    }
    if (!haveJson) c.fail("GLB file has no JSON chunk");
    return jsonText;
}

void loadBuffers(Context& c) {
    const json& arr = arrayOrEmpty(c, c.doc, "buffers", "document");
    for (size_t i = 0; i < arr.size(); ++i) {
        std::string where = "buffer " + std::to_string(i);
        const json& b = requireObject(c, arr, i, where);
        uint64_t byteLength = optUInt(c, b, "byteLength", UINT64_MAX, where);
        if (byteLength == UINT64_MAX) c.fail(where + ": missing required 'byteLength'");
        std::vector<uint8_t> data;
        if (!has(b, "uri")) {
            if (i != 0 || !c.hasGlbBin) c.fail(where + ": has no 'uri' and there is no GLB binary chunk");
            data = c.glbBin;
        } else {
            std::string uri = optString(c, b, "uri", "", where);
            if (uri.rfind("data:", 0) == 0) {
                data = decodeDataUri(c, uri, where);
            } else {
                auto bytes = detail::readFileBytes(resolveUri(c, uri, where));
                if (!bytes) c.fail(where + ": cannot read '" + uri + "'");
                data = std::move(*bytes);
            }
        }
        if (data.size() < byteLength)
            c.fail(where + ": has " + std::to_string(data.size()) + " bytes, less than its byteLength " +
                   std::to_string(byteLength));
        data.resize(static_cast<size_t>(byteLength));  // GLB pads the BIN chunk; views may not use the padding
        c.buffers.push_back(std::move(data));
    }
}

}  // namespace

}  // namespace dvsgi::scene::gltf

namespace dvsgi::scene {

namespace {

Scene parseGltf(gltf::Context& c, const std::vector<uint8_t>& file) {
    std::string jsonText;
    if (file.size() >= 4 && std::memcmp(file.data(), "glTF", 4) == 0) {
        jsonText = gltf::parseGlb(c, file);
    } else {
        jsonText.assign(file.begin(), file.end());
    }
    try {
        c.doc = gltf::json::parse(jsonText);
    } catch (const gltf::json::exception& e) {
        // parse_error and out_of_range (a number beyond double, e.g. 1e400)
        // alike: the reader must learn which file is at fault.
        c.fail(std::string("invalid JSON: ") + e.what());
    }
    if (!c.doc.is_object()) c.fail("invalid glTF: the top level is not a JSON object");
    if (!gltf::has(c.doc, "asset") || !c.doc["asset"].is_object()) c.fail("invalid glTF: missing 'asset'");
    std::string version = gltf::optString(c, c.doc["asset"], "version", "", "asset");
    if (version.rfind("2.", 0) != 0) c.fail("unsupported glTF version '" + version + "' (need 2.x)");
    for (const auto& ext : gltf::arrayOrEmpty(c, c.doc, "extensionsRequired", "document")) {
        std::string name = ext.is_string() ? ext.get<std::string>() : "?";
        // Quantized attributes need no code of their own: accessors of every
        // component type are read and converted to float.
        if (name != "KHR_lights_punctual" && name != "KHR_materials_emissive_strength" &&
            name != "KHR_mesh_quantization")
            c.fail("required extension '" + name + "' is not supported");
    }

    try {
        gltf::loadBuffers(c);
        gltf::loadMaterials(c);
        gltf::loadMeshes(c);
        gltf::loadCameras(c);
        gltf::loadLights(c);
        gltf::loadNodes(c);
        gltf::loadDefaultScene(c);
        gltf::loadAnimations(c);
    } catch (const LoadError&) {
        throw;
    } catch (const gltf::json::exception& e) {
        // Safety net: a JSON shape the explicit checks did not anticipate.
        c.fail(std::string("invalid glTF: ") + e.what());
    } catch (const std::bad_alloc&) {
        c.fail("out of memory (corrupt sizes?)");
    }
    return std::move(c.scene);
}

}  // namespace

Scene loadGltf(const std::string& path, const LoadOptions& options) {
    gltf::Context c;
    c.path = path;
    c.dir = std::filesystem::path(path).parent_path();
    c.scene.source = path;
    c.allowOutside = options.allowOutsideReferences;
    auto file = detail::readFileBytes(path);
    if (!file) c.fail("no such file");
    return parseGltf(c, *file);
}

Scene loadGltfFromMemory(const std::string& path, const std::vector<uint8_t>& bytes, const LoadOptions& options) {
    gltf::Context c;
    c.path = path;
    c.dir = std::filesystem::path(path).parent_path();
    c.scene.source = path;
    c.allowOutside = options.allowOutsideReferences;
    return parseGltf(c, bytes);
}

}  // namespace dvsgi::scene
