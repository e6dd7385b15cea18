// glTF accessors and buffer views: every byte range is checked before it is
// read, so a corrupt file ends in a LoadError instead of an out-of-bounds read.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "scene/gltf_internal.h"

namespace dvsgi::scene::gltf {

namespace {

size_t componentSize(int type) {
    switch (type) {
    case 5120: case 5121: return 1;  // (unsigned) byte
    case 5122: case 5123: return 2;  // (unsigned) short
    case 5125: case 5126: return 4;  // unsigned int, float
    default: return 0;
    }
}

int componentCount(const std::string& type) {
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4") return 4;
    if (type == "MAT2") return 4;
    if (type == "MAT3") return 9;
    if (type == "MAT4") return 16;
    return 0;
}

struct View {
    const uint8_t* data = nullptr;  // first element
    size_t count = 0;
    size_t stride = 0;
    int componentType = 0;
    int components = 0;
    bool normalized = false;
    std::string type;
    bool zeros = false;  // no bufferView: all elements are zero (glTF 3.6.2.3)
};

View resolve(const Context& c, int index, const std::string& use) {
    const json& accessors = arrayOrEmpty(c, c.doc, "accessors", "document");
    if (index < 0 || static_cast<size_t>(index) >= accessors.size())
        c.fail(use + ": accessor index " + std::to_string(index) + " out of range (" +
               std::to_string(accessors.size()) + " accessors)");
    std::string where = "accessor " + std::to_string(index);
    const json& a = requireObject(c, accessors, static_cast<size_t>(index), where);
    if (has(a, "sparse")) c.fail(where + ": sparse accessors are not supported");

    View v;
    v.componentType = static_cast<int>(optUInt(c, a, "componentType", 0, where));
    size_t csize = componentSize(v.componentType);
    if (csize == 0) c.fail(where + ": invalid or missing componentType");
    v.type = optString(c, a, "type", "", where);
    v.components = componentCount(v.type);
    if (v.components == 0) c.fail(where + ": invalid or missing type '" + v.type + "'");
    v.normalized = optBool(c, a, "normalized", false, where);
    uint64_t count = optUInt(c, a, "count", 0, where);
    if (count == 0) c.fail(where + ": missing or zero 'count'");
    uint64_t elemSize = csize * static_cast<uint64_t>(v.components);

    if (!has(a, "bufferView")) {
        // Bounded so that zero-filled data from a tiny file cannot demand gigabytes.
        if (count > (uint64_t(1) << 20)) c.fail(where + ": count too large for an accessor without bufferView");
        v.zeros = true;
        v.count = static_cast<size_t>(count);
        v.stride = static_cast<size_t>(elemSize);
        return v;
    }
    int viewIndex = reqIndex(c, a, "bufferView", arrayOrEmpty(c, c.doc, "bufferViews", "document").size(), where,
                             "buffer view");
    auto [bytes, viewLength] = bufferViewBytes(c, viewIndex);
    const json& bv = c.doc["bufferViews"][static_cast<size_t>(viewIndex)];
    uint64_t stride = optUInt(c, bv, "byteStride", 0, "buffer view " + std::to_string(viewIndex));
    if (stride == 0) stride = elemSize;
    if (stride < elemSize)
        c.fail(where + ": byteStride " + std::to_string(stride) + " of buffer view " + std::to_string(viewIndex) +
               " is smaller than the element size " + std::to_string(elemSize));
    uint64_t offset = optUInt(c, a, "byteOffset", 0, where);
    // count <= viewLength keeps stride * (count - 1) far from overflow.
    int bufferIndex = static_cast<int>(optUInt(c, bv, "buffer", 0, "buffer view"));
    if (count > viewLength || offset > viewLength || stride * (count - 1) + elemSize > viewLength - offset)
        c.fail(where + " reads past the end of buffer view " + std::to_string(viewIndex) + " (buffer " +
               std::to_string(bufferIndex) + ")");
    v.data = bytes + offset;
    v.count = static_cast<size_t>(count);
    v.stride = static_cast<size_t>(stride);
    return v;
}

template <typename T>
T load(const uint8_t* p) {
    T v;
    std::memcpy(&v, p, sizeof(T));
    return v;
}

// One component as float; normalized integers follow the glTF 3.11 formulas.
float component(const View& v, const uint8_t* p) {
    switch (v.componentType) {
    case 5120: { float x = load<int8_t>(p); return v.normalized ? std::max(x / 127.0f, -1.0f) : x; }
    case 5121: { float x = load<uint8_t>(p); return v.normalized ? x / 255.0f : x; }
    case 5122: { float x = load<int16_t>(p); return v.normalized ? std::max(x / 32767.0f, -1.0f) : x; }
    case 5123: { float x = load<uint16_t>(p); return v.normalized ? x / 65535.0f : x; }
    case 5125: return static_cast<float>(load<uint32_t>(p));
    default: return load<float>(p);
    }
}

}  // namespace

size_t accessorCount(const Context& c) { return arrayOrEmpty(c, c.doc, "accessors", "document").size(); }

std::pair<const uint8_t*, size_t> bufferViewBytes(const Context& c, int index) {
    const json& views = arrayOrEmpty(c, c.doc, "bufferViews", "document");
    if (index < 0 || static_cast<size_t>(index) >= views.size())
        c.fail("buffer view index " + std::to_string(index) + " out of range");
    std::string where = "buffer view " + std::to_string(index);
    const json& bv = requireObject(c, views, static_cast<size_t>(index), where);
    int buffer = reqIndex(c, bv, "buffer", c.buffers.size(), where, "buffer");
    uint64_t offset = optUInt(c, bv, "byteOffset", 0, where);
    uint64_t length = optUInt(c, bv, "byteLength", 0, where);
    if (!has(bv, "byteLength")) c.fail(where + ": missing required 'byteLength'");
    uint64_t stride = optUInt(c, bv, "byteStride", 0, where);
    if (stride != 0 && (stride < 4 || stride > 252)) c.fail(where + ": byteStride must be in [4, 252]");
    const auto& buf = c.buffers[static_cast<size_t>(buffer)];
    if (offset > buf.size() || length > buf.size() - offset)
        c.fail(where + " reads past the end of buffer " + std::to_string(buffer));
    return {buf.data() + offset, static_cast<size_t>(length)};
}

std::vector<glm::vec4> readFloatAccessor(const Context& c, int index, std::initializer_list<const char*> types,
                                         const std::string& use, bool allowNonFinite) {
    View v = resolve(c, index, use);
    bool typeOk = false;
    for (const char* t : types) typeOk = typeOk || v.type == t;
    if (!typeOk) {
        std::string expected;
        for (const char* t : types) expected += (expected.empty() ? "" : " or ") + std::string(t);
        c.fail(use + ": accessor " + std::to_string(index) + " has type " + v.type + ", expected " + expected);
    }
    std::vector<glm::vec4> out(v.count, glm::vec4(0.0f));
    if (v.zeros) return out;
    int n = std::min(v.components, 4);
    size_t csize = componentSize(v.componentType);
    for (size_t i = 0; i < v.count; ++i) {
        const uint8_t* e = v.data + i * v.stride;
        for (int k = 0; k < n; ++k) out[i][k] = component(v, e + k * csize);
        // NaN or infinity in a position would poison the scene bounds and
        // with them the voxel grid; no valid attribute contains one.
        if (!allowNonFinite && (!std::isfinite(out[i].x) || !std::isfinite(out[i].y) || !std::isfinite(out[i].z) ||
            !std::isfinite(out[i].w)))
            c.fail(use + ": accessor " + std::to_string(index) + " element " + std::to_string(i) +
                   " is not a finite number");
    }
    return out;
}

std::vector<uint32_t> readIndexAccessor(const Context& c, int index, const std::string& use) {
    View v = resolve(c, index, use);
    if (v.type != "SCALAR") c.fail(use + ": index accessor " + std::to_string(index) + " must be SCALAR");
    if (v.componentType != 5121 && v.componentType != 5123 && v.componentType != 5125)
        c.fail(use + ": index accessor " + std::to_string(index) +
               " must use unsigned byte, short or int components");
    std::vector<uint32_t> out(v.count, 0);
    if (v.zeros) return out;
    for (size_t i = 0; i < v.count; ++i) {
        const uint8_t* e = v.data + i * v.stride;
        switch (v.componentType) {
        case 5121: out[i] = load<uint8_t>(e); break;
        case 5123: out[i] = load<uint16_t>(e); break;
        default: out[i] = load<uint32_t>(e); break;
        }
    }
    return out;
}

}  // namespace dvsgi::scene::gltf
