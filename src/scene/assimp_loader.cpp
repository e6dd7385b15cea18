// OBJ(+MTL) and PLY import through assimp.
//
// Units: positions are taken exactly as written in the file and interpreted as
// metres; no rescaling is applied (the shared cornell_box.obj is in
// centimetres and therefore comes out 100x larger than cornell-lights.gltf).
// OBJ/PLY carry no cameras or lights; loadScene adds the defaults.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "scene/import_util.h"
#include "scene/load.h"
#include "scene/precheck.h"

namespace dvsgi::scene {

namespace {

class AssimpImport {
public:
    AssimpImport(const std::string& path, const aiScene& ai, bool allowOutside)
        : path_(path), dir_(std::filesystem::path(path).parent_path()), ai_(ai), allowOutside_(allowOutside) {}

    Scene run() {
        scene_.source = path_;
        for (unsigned i = 0; i < ai_.mNumMaterials; ++i) scene_.materials.push_back(material(*ai_.mMaterials[i]));
        meshToPrimitive_.assign(ai_.mNumMeshes, -1);
        for (unsigned i = 0; i < ai_.mNumMeshes; ++i) primitive(i);
        if (scene_.primitives.empty()) throw LoadError(path_ + ": no triangles");
        if (ai_.mRootNode) scene_.roots.push_back(node(*ai_.mRootNode, -1, 0));
        return std::move(scene_);
    }

private:
    // Converts aiMesh `index` if it has triangles (lines and points are dropped).
    void primitive(unsigned index) {
        const aiMesh& m = *ai_.mMeshes[index];
        Primitive p;
        for (unsigned f = 0; f < m.mNumFaces; ++f) {
            const aiFace& face = m.mFaces[f];
            if (face.mNumIndices != 3) continue;
            bool ok = face.mIndices[0] < m.mNumVertices && face.mIndices[1] < m.mNumVertices &&
                      face.mIndices[2] < m.mNumVertices;
            if (ok) p.indices.insert(p.indices.end(), face.mIndices, face.mIndices + 3);
        }
        if (p.indices.empty()) return;
        p.vertices.resize(m.mNumVertices);
        const bool tangents = m.mTangents && m.mBitangents && m.mNormals;
        for (unsigned v = 0; v < m.mNumVertices; ++v) {
            Vertex& out = p.vertices[v];
            out.position = glm::vec3(m.mVertices[v].x, m.mVertices[v].y, m.mVertices[v].z);
            if (m.mNormals) out.normal = glm::vec3(m.mNormals[v].x, m.mNormals[v].y, m.mNormals[v].z);
            if (m.mTextureCoords[0]) out.uv = glm::vec2(m.mTextureCoords[0][v].x, m.mTextureCoords[0][v].y);
            if (tangents) {
                glm::vec3 t(m.mTangents[v].x, m.mTangents[v].y, m.mTangents[v].z);
                glm::vec3 b(m.mBitangents[v].x, m.mBitangents[v].y, m.mBitangents[v].z);
                // glTF stores only the bitangent's handedness: B = w * cross(N, T).
                float w = glm::dot(glm::cross(out.normal, t), b) < 0.0f ? -1.0f : 1.0f;
                out.tangent = glm::vec4(t, w);
            }
        }
        p.hasTangents = tangents;
        // Out-of-range materials are redirected to the default one by loadScene.
        p.material = m.mMaterialIndex;
        meshToPrimitive_[index] = static_cast<int>(scene_.primitives.size());
        scene_.primitives.push_back(std::move(p));
    }

    int node(const aiNode& an, int parent, int depth) {
        int idx = static_cast<int>(scene_.nodes.size());
        scene_.nodes.emplace_back();
        {
            Node& n = scene_.nodes.back();
            n.name = an.mName.C_Str();
            n.parent = parent;
            const aiMatrix4x4& t = an.mTransformation;  // row-major, translation in a4/b4/c4
            glm::mat4 m;
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c) m[c][r] = t[r][c];
            detail::decomposeMatrix(m, n);
        }
        Mesh mesh;
        mesh.name = an.mName.C_Str();
        for (unsigned i = 0; i < an.mNumMeshes; ++i) {
            unsigned mi = an.mMeshes[i];
            if (mi < meshToPrimitive_.size() && meshToPrimitive_[mi] >= 0)
                mesh.primitives.push_back(static_cast<uint32_t>(meshToPrimitive_[mi]));
        }
        if (!mesh.primitives.empty()) {
            scene_.nodes[idx].mesh = static_cast<int>(scene_.meshes.size());
            scene_.meshes.push_back(std::move(mesh));
        }
        // assimp hierarchies from OBJ/PLY are shallow; the limit only guards
        // against a pathological file exhausting the stack.
        if (depth < 256) {
            for (unsigned i = 0; i < an.mNumChildren; ++i) {
                int child = node(*an.mChildren[i], idx, depth + 1);
                scene_.nodes[idx].children.push_back(child);
            }
        }
        return idx;
    }

    Material material(const aiMaterial& am) {
        Material m;
        aiString name;
        if (am.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) m.name = name.C_Str();
        aiColor3D kd(1, 1, 1), ke(0, 0, 0), ks(0, 0, 0);
        am.Get(AI_MATKEY_COLOR_DIFFUSE, kd);
        am.Get(AI_MATKEY_COLOR_EMISSIVE, ke);
        bool haveKs = am.Get(AI_MATKEY_COLOR_SPECULAR, ks) == AI_SUCCESS;
        float opacity = 1.0f;
        am.Get(AI_MATKEY_OPACITY, opacity);
        m.baseColorFactor = glm::vec4(kd.r, kd.g, kd.b, std::clamp(opacity, 0.0f, 1.0f));
        m.emissiveFactor = glm::vec3(ke.r, ke.g, ke.b);
        m.metallicFactor = 0.0f;
        // Blinn-Phong exponent Ns -> GGX: Walter et al. 2007 match the lobes
        // with alpha = sqrt(2 / (Ns + 2)). That value is stored directly as
        // roughness (the project's rule), so with glTF's alpha = roughness^2
        // the lobe comes out somewhat sharper than the strict fit; the
        // Lambertian renderer ignores roughness, so only its order matters.
        // Clamped to [0.02, 1]. No specular colour (Ks = 0): purely diffuse,
        // roughness 1.
        float ns = 0.0f;
        bool haveNs = am.Get(AI_MATKEY_SHININESS, ns) == AI_SUCCESS;
        bool noSpecular = !haveKs || (ks.r == 0.0f && ks.g == 0.0f && ks.b == 0.0f);
        if (noSpecular || !haveNs) {
            m.roughnessFactor = 1.0f;
        } else {
            m.roughnessFactor = std::clamp(std::sqrt(2.0f / (std::max(ns, 0.0f) + 2.0f)), 0.02f, 1.0f);
        }

        std::string kdMap = texturePath(am, aiTextureType_DIFFUSE);
        std::string dMap = texturePath(am, aiTextureType_OPACITY);
        if (!dMap.empty()) {
            // A cut-out map (leaves, chains): the renderer only knows base
            // colour alpha, so the mask is multiplied into it.
            m.alphaMode = AlphaMode::Mask;
            m.baseColorTexture = combinedTexture(kdMap, dMap);
        } else {
            if (opacity < 1.0f) m.alphaMode = AlphaMode::Mask;
            if (!kdMap.empty()) m.baseColorTexture = fileTexture(kdMap);
        }
        return m;
    }

    static std::string texturePath(const aiMaterial& am, aiTextureType type) {
        aiString s;
        if (am.GetTextureCount(type) == 0 || am.GetTexture(type, 0, &s) != AI_SUCCESS) return {};
        std::string p = s.C_Str();
        std::replace(p.begin(), p.end(), '\\', '/');  // MTL files written on Windows
        return p;
    }

    // Decoded texel data by relative path; nullptr after a failed load (which
    // has then been reported once).
    const Texture* decoded(const std::string& rel) {
        auto it = images_.find(rel);
        if (it == images_.end()) {
            Texture t;
            t.name = rel;
            std::string error;
            std::optional<Texture> result;
            auto file = detail::confinedPath(dir_, rel, allowOutside_, error);
            if (!file) throw LoadError(detail::printable(path_ + ": texture '" + rel + "' " + error));
            if (detail::decodeImageFile(*file, t, error)) {
                result = std::move(t);
            } else {
                scene_.warnings.push_back(detail::printable(path_ + ": texture '" + rel + "' could not be loaded (" +
                                                            error + "); using the material's factor instead"));
            }
            it = images_.emplace(rel, std::move(result)).first;
        }
        return it->second ? &*it->second : nullptr;
    }

    int fileTexture(const std::string& rel) {
        if (auto it = sceneTexture_.find(rel); it != sceneTexture_.end()) return it->second;
        const Texture* t = decoded(rel);
        int idx = -1;
        if (t) {
            scene_.textures.push_back(*t);
            scene_.textures.back().srgb = true;
            idx = static_cast<int>(scene_.textures.size()) - 1;
        }
        sceneTexture_[rel] = idx;
        return idx;
    }

    // Base colour (or white) with the opacity map in its alpha channel.
    int combinedTexture(const std::string& kdRel, const std::string& dRel) {
        std::string key = kdRel + "|" + dRel;
        if (auto it = sceneTexture_.find(key); it != sceneTexture_.end()) return it->second;
        const Texture* mask = decoded(dRel);
        const Texture* base = kdRel.empty() ? nullptr : decoded(kdRel);
        int idx = -1;
        if (!mask) {
            idx = kdRel.empty() ? -1 : fileTexture(kdRel);
        } else {
            Texture out;
            if (base) {
                out = *base;
            } else {
                out.width = mask->width;
                out.height = mask->height;
                out.rgba8.assign(size_t(out.width) * out.height * 4, 255);
            }
            out.name = (kdRel.empty() ? std::string("<white>") : kdRel) + " + " + dRel;
            out.srgb = true;
            // Masks are usually grey images without alpha: then grey is the
            // opacity; an image with a real alpha channel carries it there.
            bool maskHasAlpha = false;
            for (size_t i = 3; i < mask->rgba8.size() && !maskHasAlpha; i += 4) maskHasAlpha = mask->rgba8[i] != 255;
            for (uint32_t y = 0; y < out.height; ++y) {
                for (uint32_t x = 0; x < out.width; ++x) {
                    // Nearest texel of the mask, which may have another size.
                    uint32_t mx = static_cast<uint32_t>(uint64_t(x) * mask->width / out.width);
                    uint32_t my = static_cast<uint32_t>(uint64_t(y) * mask->height / out.height);
                    const uint8_t* mt = &mask->rgba8[(size_t(my) * mask->width + mx) * 4];
                    uint8_t a = maskHasAlpha ? mt[3] : mt[0];
                    uint8_t& dst = out.rgba8[(size_t(y) * out.width + x) * 4 + 3];
                    dst = static_cast<uint8_t>((unsigned(dst) * a + 127) / 255);
                }
            }
            scene_.textures.push_back(std::move(out));
            idx = static_cast<int>(scene_.textures.size()) - 1;
        }
        sceneTexture_[key] = idx;
        return idx;
    }

    std::string path_;
    std::filesystem::path dir_;
    const aiScene& ai_;
    bool allowOutside_;
    Scene scene_;
    std::vector<int> meshToPrimitive_;
    std::map<std::string, std::optional<Texture>> images_;
    std::map<std::string, int> sceneTexture_;
};

}  // namespace

namespace {

// Vertex colours, bones and animations are not used by the renderer.
void configure(Assimp::Importer& importer) {
    importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_COLORS | aiComponent_BONEWEIGHTS |
                                                            aiComponent_ANIMATIONS | aiComponent_LIGHTS |
                                                            aiComponent_CAMERAS);
}

// FlipUVs: OBJ puts v = 0 at the bottom of the image, the renderer (like
// glTF) at the top row. SortByPType splits off line/point meshes, which are
// then dropped. GenSmoothNormals only fills in missing normals.
constexpr unsigned kFlags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_GenSmoothNormals |
                            aiProcess_CalcTangentSpace | aiProcess_SortByPType | aiProcess_FlipUVs |
                            aiProcess_RemoveComponent | aiProcess_ValidateDataStructure;

void precheck(const std::string& path, const std::string& ext, const uint8_t* data, size_t size,
              const std::filesystem::path* dir, bool allowOutside) {
    if (ext == ".ply") {
        detail::precheckPly(path, data, size);
        return;
    }
    std::vector<std::string> mtllibs = detail::precheckObj(path, data, size);
    if (!dir) return;
    for (const std::string& name : mtllibs) {
        std::string error;
        auto file = detail::confinedPath(*dir, name, allowOutside, error);
        if (!file) throw LoadError(detail::printable(path + ": mtllib '" + name + "' " + error));
        // A missing MTL only costs the materials; assimp warns and goes on.
        auto bytes = detail::readFileBytes(*file);
        if (bytes) detail::precheckMtl(file->string(), bytes->data(), bytes->size());
    }
}

Scene convert(const std::string& path, Assimp::Importer& importer, const aiScene* ai, bool allowOutside) {
    if (!ai) throw LoadError(detail::printable(path + ": " + importer.GetErrorString()));
    if (ai->mNumMeshes == 0) throw LoadError(path + ": no triangles");
    return AssimpImport(path, *ai, allowOutside).run();
}

}  // namespace

Scene loadWithAssimp(const std::string& path, const LoadOptions& options) {
    std::string ext = detail::lowercase(std::filesystem::path(path).extension().string());
    auto bytes = detail::readFileBytes(path);
    if (!bytes) throw LoadError(path + ": cannot read the file");
    const std::filesystem::path dir = std::filesystem::path(path).parent_path();
    precheck(path, ext, bytes->data(), bytes->size(), &dir, options.allowOutsideReferences);
    Assimp::Importer importer;
    configure(importer);
    // PLY has no external references: parse exactly the bytes that were checked.
    const aiScene* ai = ext == ".ply" ? importer.ReadFileFromMemory(bytes->data(), bytes->size(), kFlags, "ply")
                                      : importer.ReadFile(path, kFlags);
    return convert(path, importer, ai, options.allowOutsideReferences);
}

Scene loadWithAssimpFromMemory(const std::string& path, const std::string& ext, const uint8_t* data, size_t size) {
    precheck(path, ext, data, size, nullptr, false);
    // assimp's in-memory IO system crashes (SIGSEGV, found by fuzz_objply)
    // when the OBJ parser asks it for an mtllib; there is no folder to find
    // one in anyway, so such lines become comments.
    std::vector<uint8_t> copy;
    if (ext == ".obj") {
        copy.assign(data, data + size);
        bool lineStart = true;
        for (size_t i = 0; i < copy.size(); ++i) {
            const char ch = static_cast<char>(copy[i]);
            if (lineStart && ch != ' ' && ch != '\t') {
                if (i + 3 <= copy.size() && std::memcmp(&copy[i], "mtl", 3) == 0) copy[i] = '#';
                lineStart = false;
            }
            if (ch == '\n') lineStart = true;
        }
        data = copy.data();
        size = copy.size();
    }
    Assimp::Importer importer;
    configure(importer);
    const aiScene* ai = importer.ReadFileFromMemory(data, size, kFlags, ext.c_str() + 1);
    return convert(path, importer, ai, false);
}

}  // namespace dvsgi::scene
