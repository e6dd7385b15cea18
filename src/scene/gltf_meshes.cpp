// glTF meshes: each primitive becomes one indexed triangle list.
#include "scene/gltf_internal.h"

namespace dvsgi::scene::gltf {

namespace {

// glTF leaves normals to the client when NORMAL is absent and asks for flat
// shading; that needs one vertex per triangle corner, so the mesh is unwelded.
void makeFlatNormals(Primitive& p) {
    std::vector<Vertex> flat;
    flat.reserve(p.indices.size());
    for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
        Vertex a = p.vertices[p.indices[t]], b = p.vertices[p.indices[t + 1]], c = p.vertices[p.indices[t + 2]];
        glm::vec3 n = glm::cross(b.position - a.position, c.position - a.position);
        float len = glm::length(n);
        n = len > 0.0f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
        a.normal = b.normal = c.normal = n;
        flat.push_back(a);
        flat.push_back(b);
        flat.push_back(c);
    }
    p.vertices = std::move(flat);
    for (size_t i = 0; i < p.indices.size(); ++i) p.indices[i] = static_cast<uint32_t>(i);
}

uint32_t defaultMaterial(Context& c, int& cached) {
    if (cached < 0) {
        Material m;  // glTF's default material: white, metallic 1, roughness 1
        m.name = "default";
        c.scene.materials.push_back(m);
        cached = static_cast<int>(c.scene.materials.size()) - 1;
    }
    return static_cast<uint32_t>(cached);
}

Primitive loadPrimitive(Context& c, const json& pj, const std::string& where, size_t materialCount,
                        int& defaultMat) {
    uint64_t mode = optUInt(c, pj, "mode", 4, where);
    if (mode != 4)
        c.fail(where + ": unsupported primitive mode " + std::to_string(mode) + " (only triangles, mode 4)");
    if (!has(pj, "attributes") || !pj["attributes"].is_object()) c.fail(where + ": missing 'attributes'");
    const json& attrs = pj["attributes"];
    if (!has(attrs, "POSITION")) c.fail(where + ": missing POSITION attribute");

    auto attribute = [&](const char* name, std::initializer_list<const char*> types) {
        int idx = reqIndex(c, attrs, name, accessorCount(c), where, "accessor");
        // A NaN normal shades nothing; validateScene swaps in the face normal.
        const bool normal = std::string(name) == "NORMAL";
        return readFloatAccessor(c, idx, types, where + " " + name, normal);
    };

    Primitive p;
    std::vector<glm::vec4> pos = attribute("POSITION", {"VEC3"});
    p.vertices.resize(pos.size());
    for (size_t i = 0; i < pos.size(); ++i) p.vertices[i].position = glm::vec3(pos[i]);
    auto sameCount = [&](const std::vector<glm::vec4>& v, const char* name) {
        if (v.size() != pos.size())
            c.fail(where + ": " + name + " has " + std::to_string(v.size()) + " elements, POSITION has " +
                   std::to_string(pos.size()));
    };
    bool hasNormals = has(attrs, "NORMAL");
    if (hasNormals) {
        auto n = attribute("NORMAL", {"VEC3"});
        sameCount(n, "NORMAL");
        for (size_t i = 0; i < n.size(); ++i) p.vertices[i].normal = glm::vec3(n[i]);
    }
    if (has(attrs, "TEXCOORD_0")) {
        auto uv = attribute("TEXCOORD_0", {"VEC2"});
        sameCount(uv, "TEXCOORD_0");
        for (size_t i = 0; i < uv.size(); ++i) p.vertices[i].uv = glm::vec2(uv[i]);
    }
    if (has(attrs, "TANGENT")) {
        auto tg = attribute("TANGENT", {"VEC4"});
        sameCount(tg, "TANGENT");
        for (size_t i = 0; i < tg.size(); ++i) p.vertices[i].tangent = tg[i];
        p.hasTangents = true;
    }

    if (has(pj, "indices")) {
        int idx = reqIndex(c, pj, "indices", accessorCount(c), where, "accessor");
        p.indices = readIndexAccessor(c, idx, where + " indices");
    } else {
        p.indices.resize(pos.size());
        for (size_t i = 0; i < pos.size(); ++i) p.indices[i] = static_cast<uint32_t>(i);
    }
    if (p.indices.size() % 3 != 0)
        c.fail(where + ": " + std::to_string(p.indices.size()) + " indices is not a whole number of triangles");
    for (uint32_t i : p.indices)
        if (i >= p.vertices.size())
            c.fail(where + ": vertex index " + std::to_string(i) + " out of range (" +
                   std::to_string(p.vertices.size()) + " vertices)");
    if (!hasNormals) makeFlatNormals(p);

    int mat = optIndex(c, pj, "material", materialCount, where, "material");
    p.material = mat >= 0 ? static_cast<uint32_t>(mat) : defaultMaterial(c, defaultMat);
    return p;
}

}  // namespace

void loadMeshes(Context& c) {
    const json& meshes = arrayOrEmpty(c, c.doc, "meshes", "document");
    // Material indices refer to the file's materials only, not to a default
    // material appended below.
    const size_t materialCount = c.scene.materials.size();
    int defaultMat = -1;
    for (size_t m = 0; m < meshes.size(); ++m) {
        std::string where = "mesh " + std::to_string(m);
        const json& mj = requireObject(c, meshes, m, where);
        Mesh mesh;
        mesh.name = optString(c, mj, "name", "", where);
        const json& prims = arrayOrEmpty(c, mj, "primitives", where);
        if (prims.empty()) c.fail(where + ": has no primitives");
        for (size_t p = 0; p < prims.size(); ++p) {
            std::string pw = where + " primitive " + std::to_string(p);
            Primitive prim = loadPrimitive(c, requireObject(c, prims, p, pw), pw, materialCount, defaultMat);
            mesh.primitives.push_back(static_cast<uint32_t>(c.scene.primitives.size()));
            c.scene.primitives.push_back(std::move(prim));
        }
        c.scene.meshes.push_back(std::move(mesh));
    }
}

}  // namespace dvsgi::scene::gltf
