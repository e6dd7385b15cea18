#include "scene/import_util.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstring>
#include <fstream>
#include <string>

// stb_image is compiled here with static linkage: the binary also links
// Debian's libstb (for imgui), whose global stbi_* symbols would otherwise
// win the link and bypass this configuration. It decodes PNG (glTF's other
// format) and BMP and TGA (common in OBJ material libraries); JPEG goes to
// libjpeg-turbo, and stb's remaining decoders stay out of reach of hostile
// files.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#define STBI_ONLY_PNG
#define STBI_ONLY_BMP
#define STBI_ONLY_TGA
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include "scene/precheck.h"

namespace dvsgi::scene::detail {

std::optional<std::vector<uint8_t>> readFileBytes(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) return std::nullopt;
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    in.seekg(0, std::ios::end);
    std::streamoff size = in.tellg();
    if (size < 0) return std::nullopt;
    in.seekg(0, std::ios::beg);
    std::vector<uint8_t> bytes(static_cast<size_t>(size));
    if (size > 0 && !in.read(reinterpret_cast<char*>(bytes.data()), size)) return std::nullopt;
    return bytes;
}

bool decodeImage(const uint8_t* data, size_t size, Texture& out, std::string& error) {
    // stb takes an int length; larger inputs cannot be valid images for it.
    if (size == 0 || size > static_cast<size_t>(INT_MAX)) {
        error = size == 0 ? "empty image data" : "image data too large";
        return false;
    }
    // stb keeps its flip flag in a global; make sure another user of the
    // library cannot leave it set and turn our images upside down.
    if (isJpeg(data, size)) return decodeJpeg(data, size, out, error);
    stbi_set_flip_vertically_on_load(0);
    const std::vector<uint8_t> cleaned = withoutEmptyPngIdat(data, size);
    if (!cleaned.empty()) {
        data = cleaned.data();
        size = cleaned.size();
    }
    int w = 0, h = 0, channels = 0;
    // The header alone gives the size: a small file can claim a huge image,
    // and the decoder would allocate it before noticing the data is short.
    if (stbi_info_from_memory(data, static_cast<int>(size), &w, &h, &channels)) {
        if (static_cast<uint64_t>(w) * static_cast<uint64_t>(h) > kMaxImageTexels) {
            error = "image size " + std::to_string(w) + "x" + std::to_string(h) + " exceeds the limit of " +
                    std::to_string(kMaxImageTexels) + " texels";
            return false;
        }
        if (!precheckImageData(data, size, static_cast<uint64_t>(w), static_cast<uint64_t>(h), error)) return false;
    }
    stbi_uc* pixels = stbi_load_from_memory(data, static_cast<int>(size), &w, &h, &channels, 4);
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        error = reason ? reason : "unknown decoder error";
        return false;
    }
    if (w <= 0 || h <= 0) {
        stbi_image_free(pixels);
        error = "image has no texels";
        return false;
    }
    out.width = static_cast<uint32_t>(w);
    out.height = static_cast<uint32_t>(h);
    size_t bytes = static_cast<size_t>(w) * static_cast<size_t>(h) * 4;
    out.rgba8.assign(pixels, pixels + bytes);
    stbi_image_free(pixels);
    return true;
}

bool decodeImageFile(const std::filesystem::path& file, Texture& out, std::string& error) {
    auto bytes = readFileBytes(file);
    if (!bytes) {
        error = "cannot read file";
        return false;
    }
    return decodeImage(bytes->data(), bytes->size(), out, error);
}

std::optional<std::filesystem::path> confinedPath(const std::filesystem::path& dir, const std::string& rel,
                                                  bool allowOutside, std::string& error) {
    namespace fs = std::filesystem;
    // A NUL would silently cut the name at the C library boundary.
    if (rel.find('\0') != std::string::npos) {
        error = "contains a NUL byte";
        return std::nullopt;
    }
    if (rel.empty()) {
        error = "is empty";
        return std::nullopt;
    }
    fs::path p(rel);
    fs::path base = dir.empty() ? fs::path(".") : dir;
    if (allowOutside) return base / p;
    if (p.has_root_path()) {
        error = "is an absolute path; only files inside the scene's folder may be referenced";
        return std::nullopt;
    }
    std::error_code ec1, ec2;
    fs::path root = fs::weakly_canonical(base, ec1);
    fs::path target = fs::weakly_canonical(base / p, ec2);
    if (ec1 || ec2) {
        error = "cannot be resolved";
        return std::nullopt;
    }
    // weakly_canonical follows every symlink that exists, so a link inside
    // the folder that points elsewhere shows up here as well.
    fs::path inside = target.lexically_relative(root);
    if (inside.empty() || *inside.begin() == "..") {
        error = "points outside the scene's folder; only files inside it may be referenced";
        return std::nullopt;
    }
    return target;
}

std::string printable(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    static const char* hex = "0123456789abcdef";
    for (unsigned char ch : s) {
        if (ch < 0x20 || ch == 0x7f) {
            out += "\\x";
            out.push_back(hex[ch >> 4]);
            out.push_back(hex[ch & 15]);
        } else {
            out.push_back(static_cast<char>(ch));
        }
    }
    return out;
}

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

void decomposeMatrix(const glm::mat4& m, Node& n) {
    n.translation = glm::vec3(m[3]);
    glm::vec3 cols[3] = {glm::vec3(m[0]), glm::vec3(m[1]), glm::vec3(m[2])};
    glm::vec3 s(glm::length(cols[0]), glm::length(cols[1]), glm::length(cols[2]));
    // A mirroring matrix has a negative determinant; put the flip into scale
    // so the remaining rotation is proper.
    if (glm::dot(glm::cross(cols[0], cols[1]), cols[2]) < 0.0f) s.x = -s.x;
    n.scale = s;
    if (s.x == 0.0f || s.y == 0.0f || s.z == 0.0f) {
        n.rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
        return;
    }
    glm::mat3 r(cols[0] / s.x, cols[1] / s.y, cols[2] / s.z);
    n.rotation = glm::normalize(glm::quat_cast(r));
}

}  // namespace dvsgi::scene::detail
