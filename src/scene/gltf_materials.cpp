// glTF materials, textures and images. Images decode lazily, once per colour
// space they are used in, so an unused broken image costs nothing and warns
// about nothing.
#include <map>

#include "scene/gltf_internal.h"
#include "scene/import_util.h"

namespace dvsgi::scene::gltf {

namespace {

struct TextureCache {
    // (image index, srgb) -> Scene texture index, or -1 after a failed decode.
    std::map<std::pair<int, bool>, int> byImage;
};

std::string imageLabel(const json& img, int index) {
    std::string uri = has(img, "uri") && img["uri"].is_string() ? img["uri"].get<std::string>() : "";
    if (!uri.empty() && uri.rfind("data:", 0) != 0) return uri;
    return "<embedded " + std::to_string(index) + ">";
}

// Decodes image `index`; returns false (and a reason) for data that is
// missing or undecodable, which the caller turns into a warning. Malformed
// references inside the JSON are still errors.
bool decodeGltfImage(Context& c, int index, Texture& out, std::string& error) {
    const json& images = arrayOrEmpty(c, c.doc, "images", "document");
    std::string where = "image " + std::to_string(index);
    const json& img = requireObject(c, images, static_cast<size_t>(index), where);
    out.name = imageLabel(img, index);
    if (has(img, "bufferView")) {
        int view = reqIndex(c, img, "bufferView", arrayOrEmpty(c, c.doc, "bufferViews", "document").size(), where,
                            "buffer view");
        auto [bytes, len] = bufferViewBytes(c, view);
        return detail::decodeImage(bytes, len, out, error);
    }
    std::string uri = optString(c, img, "uri", "", where);
    if (uri.empty()) {
        error = "image has neither 'uri' nor 'bufferView'";
        return false;
    }
    if (uri.rfind("data:", 0) == 0) {
        std::vector<uint8_t> bytes;
        try {
            bytes = decodeDataUri(c, uri, where);
        } catch (const LoadError& e) {
            error = e.what();
            return false;
        }
        return detail::decodeImage(bytes.data(), bytes.size(), out, error);
    }
    return detail::decodeImageFile(resolveUri(c, uri, where), out, error);
}

class TextureResolver {
public:
    explicit TextureResolver(Context& c) : c_(c) {}

    // A textureInfo object (e.g. baseColorTexture) -> Scene texture index.
    int resolve(const json& mat, const char* key, bool srgb, const std::string& where) {
        if (!has(mat, key)) return -1;
        const json& info = mat.at(key);
        std::string w = where + " " + key;
        if (!info.is_object()) c_.fail(w + " must be a JSON object");
        const json& textures = arrayOrEmpty(c_, c_.doc, "textures", "document");
        int tex = reqIndex(c_, info, "index", textures.size(), w, "texture");
        if (optUInt(c_, info, "texCoord", 0, w) != 0)
            c_.warn(w + ": texCoord other than 0 is not supported; using TEXCOORD_0");
        std::string tw = "texture " + std::to_string(tex);
        const json& tj = requireObject(c_, textures, static_cast<size_t>(tex), tw);
        int image = optIndex(c_, tj, "source", arrayOrEmpty(c_, c_.doc, "images", "document").size(), tw, "image");
        if (image < 0) {
            c_.warn(tw + " has no image this importer can read (e.g. only an extension source); using the "
                    "material's factor");
            return -1;
        }
        return imageTexture(image, srgb);
    }

private:
    int imageTexture(int image, bool srgb) {
        auto key = std::make_pair(image, srgb);
        if (auto it = cache_.byImage.find(key); it != cache_.byImage.end()) return it->second;
        // Already decoded for the other colour space: the renderer needs a
        // separate texture (different format), but not a second decode.
        auto other = cache_.byImage.find(std::make_pair(image, !srgb));
        int result = -1;
        if (other != cache_.byImage.end() && other->second >= 0) {
            Texture t = c_.scene.textures[static_cast<size_t>(other->second)];
            t.srgb = srgb;
            result = push(std::move(t));
        } else if (other == cache_.byImage.end()) {
            Texture t;
            std::string error;
            if (decodeGltfImage(c_, image, t, error)) {
                t.srgb = srgb;
                result = push(std::move(t));
            } else {
                c_.warn("texture '" + t.name + "' (image " + std::to_string(image) + ") could not be loaded (" +
                        error + "); using the material's factor instead");
            }
        }  // else: the image already failed and was reported once
        cache_.byImage[key] = result;
        return result;
    }

    int push(Texture t) {
        c_.scene.textures.push_back(std::move(t));
        return static_cast<int>(c_.scene.textures.size()) - 1;
    }

    Context& c_;
    TextureCache cache_;
};

AlphaMode parseAlphaMode(const Context& c, const json& mj, const std::string& where) {
    std::string mode = optString(c, mj, "alphaMode", "OPAQUE", where);
    if (mode == "OPAQUE") return AlphaMode::Opaque;
    if (mode == "MASK") return AlphaMode::Mask;
    if (mode == "BLEND") return AlphaMode::Blend;
    c.fail(where + ": unknown alphaMode '" + mode + "'");
}

}  // namespace

void loadMaterials(Context& c) {
    const json& mats = arrayOrEmpty(c, c.doc, "materials", "document");
    TextureResolver textures(c);
    for (size_t i = 0; i < mats.size(); ++i) {
        std::string where = "material " + std::to_string(i);
        const json& mj = requireObject(c, mats, i, where);
        Material m;
        m.name = optString(c, mj, "name", "", where);
        if (has(mj, "pbrMetallicRoughness")) {
            const json& pbr = mj["pbrMetallicRoughness"];
            std::string pw = where + " pbrMetallicRoughness";
            if (!pbr.is_object()) c.fail(pw + " must be a JSON object");
            auto bc = optFloats(c, pbr, "baseColorFactor", 4, {1, 1, 1, 1}, pw);
            m.baseColorFactor = glm::vec4(bc[0], bc[1], bc[2], bc[3]);
            m.metallicFactor = static_cast<float>(optNumber(c, pbr, "metallicFactor", 1.0, pw));
            m.roughnessFactor = static_cast<float>(optNumber(c, pbr, "roughnessFactor", 1.0, pw));
            m.baseColorTexture = textures.resolve(pbr, "baseColorTexture", true, pw);
            m.metallicRoughnessTexture = textures.resolve(pbr, "metallicRoughnessTexture", false, pw);
        }
        if (has(mj, "normalTexture") && mj["normalTexture"].is_object())
            m.normalScale = static_cast<float>(optNumber(c, mj["normalTexture"], "scale", 1.0, where + " normalTexture"));
        m.normalTexture = textures.resolve(mj, "normalTexture", false, where);
        auto e = optFloats(c, mj, "emissiveFactor", 3, {0, 0, 0}, where);
        m.emissiveFactor = glm::vec3(e[0], e[1], e[2]);
        m.emissiveTexture = textures.resolve(mj, "emissiveTexture", true, where);
        if (has(mj, "extensions") && has(mj["extensions"], "KHR_materials_emissive_strength")) {
            const json& ext = mj["extensions"]["KHR_materials_emissive_strength"];
            std::string ew = where + " KHR_materials_emissive_strength";
            if (!ext.is_object()) c.fail(ew + " must be a JSON object");
            m.emissiveStrength = static_cast<float>(optNumber(c, ext, "emissiveStrength", 1.0, ew));
        }
        m.alphaMode = parseAlphaMode(c, mj, where);
        m.alphaCutoff = static_cast<float>(optNumber(c, mj, "alphaCutoff", 0.5, where));
        m.doubleSided = optBool(c, mj, "doubleSided", false, where);
        c.scene.materials.push_back(std::move(m));
    }
}

}  // namespace dvsgi::scene::gltf
