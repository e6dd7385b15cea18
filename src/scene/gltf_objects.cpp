// glTF cameras, KHR_lights_punctual lights, the node hierarchy, the default
// scene and animations.
#include <cmath>
#include <cstdint>

#include "scene/gltf_internal.h"
#include "scene/import_util.h"

namespace dvsgi::scene::gltf {

void loadCameras(Context& c) {
    const json& cams = arrayOrEmpty(c, c.doc, "cameras", "document");
    for (size_t i = 0; i < cams.size(); ++i) {
        std::string where = "camera " + std::to_string(i);
        const json& cj = requireObject(c, cams, i, where);
        std::string type = optString(c, cj, "type", "", where);
        if (type != "perspective") {
            // The renderer has only a perspective camera; a scene with an
            // orthographic one still renders from the next (or default) camera.
            c.warn(where + ": camera type '" + type + "' is not supported; camera skipped");
            c.cameraMap.push_back(-1);
            continue;
        }
        if (!has(cj, "perspective") || !cj["perspective"].is_object()) c.fail(where + ": missing 'perspective'");
        const json& p = cj["perspective"];
        Camera cam;
        cam.name = optString(c, cj, "name", "", where);
        cam.yfov = static_cast<float>(reqNumber(c, p, "yfov", where));
        cam.znear = static_cast<float>(reqNumber(c, p, "znear", where));
        // An absent zfar means an infinite projection; keep the finite default.
        cam.zfar = static_cast<float>(optNumber(c, p, "zfar", cam.zfar, where));
        cam.aspectRatio = static_cast<float>(optNumber(c, p, "aspectRatio", 0.0, where));
        if (!(cam.yfov > 0.0f) || !(cam.znear > 0.0f) || !(cam.zfar > cam.znear))
            c.fail(where + ": needs yfov > 0 and 0 < znear < zfar");
        c.cameraMap.push_back(static_cast<int>(c.scene.cameras.size()));
        c.scene.cameras.push_back(cam);
    }
}

void loadLights(Context& c) {
    if (!has(c.doc, "extensions") || !has(c.doc["extensions"], "KHR_lights_punctual")) return;
    const json& ext = c.doc["extensions"]["KHR_lights_punctual"];
    const json& lights = arrayOrEmpty(c, ext, "lights", "KHR_lights_punctual");
    for (size_t i = 0; i < lights.size(); ++i) {
        std::string where = "light " + std::to_string(i);
        const json& lj = requireObject(c, lights, i, where);
        Light l;
        l.name = optString(c, lj, "name", "", where);
        std::string type = optString(c, lj, "type", "", where);
        if (type == "directional") l.type = LightType::Directional;
        else if (type == "point") l.type = LightType::Point;
        else if (type == "spot") l.type = LightType::Spot;
        else c.fail(where + ": unknown light type '" + type + "'");
        auto col = optFloats(c, lj, "color", 3, {1, 1, 1}, where);
        l.color = glm::vec3(col[0], col[1], col[2]);
        l.intensity = static_cast<float>(optNumber(c, lj, "intensity", 1.0, where));
        // `range` is deliberately ignored: lights follow pure inverse-square
        // falloff (CONVENTIONS.md).
        if (l.type == LightType::Spot && has(lj, "spot")) {
            const json& s = lj["spot"];
            if (!s.is_object()) c.fail(where + ": 'spot' must be a JSON object");
            l.innerConeAngle = static_cast<float>(optNumber(c, s, "innerConeAngle", 0.0, where));
            l.outerConeAngle = static_cast<float>(optNumber(c, s, "outerConeAngle", 0.78539816339744831, where));
        }
        c.scene.lights.push_back(l);
    }
}

void loadNodes(Context& c) {
    const json& nodes = arrayOrEmpty(c, c.doc, "nodes", "document");
    c.scene.nodes.resize(nodes.size());
    for (size_t i = 0; i < nodes.size(); ++i) {
        std::string where = "node " + std::to_string(i);
        const json& nj = requireObject(c, nodes, i, where);
        Node& n = c.scene.nodes[i];
        n.name = optString(c, nj, "name", "", where);
        if (has(nj, "matrix")) {
            auto m = optFloats(c, nj, "matrix", 16, {}, where);
            glm::mat4 mat;
            for (int col = 0; col < 4; ++col)
                for (int row = 0; row < 4; ++row) mat[col][row] = m[static_cast<size_t>(col * 4 + row)];
            detail::decomposeMatrix(mat, n);
        } else {
            auto t = optFloats(c, nj, "translation", 3, {0, 0, 0}, where);
            auto r = optFloats(c, nj, "rotation", 4, {0, 0, 0, 1}, where);
            auto s = optFloats(c, nj, "scale", 3, {1, 1, 1}, where);
            n.translation = glm::vec3(t[0], t[1], t[2]);
            // In double: the squared length of a quaternion near FLT_MAX
            // overflows float and would turn the rotation into zeros.
            double len = std::sqrt(double(r[0]) * r[0] + double(r[1]) * r[1] + double(r[2]) * r[2] +
                                   double(r[3]) * r[3]);
            n.rotation = len > 0.0 && std::isfinite(len)
                             ? glm::quat(float(r[3] / len), float(r[0] / len), float(r[1] / len), float(r[2] / len))
                             : glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
            n.scale = glm::vec3(s[0], s[1], s[2]);
        }
        n.mesh = optIndex(c, nj, "mesh", c.scene.meshes.size(), where, "mesh");
        int cam = optIndex(c, nj, "camera", c.cameraMap.size(), where, "camera");
        n.camera = cam >= 0 ? c.cameraMap[static_cast<size_t>(cam)] : -1;
        if (has(nj, "extensions") && has(nj["extensions"], "KHR_lights_punctual")) {
            n.light = reqIndex(c, nj["extensions"]["KHR_lights_punctual"], "light", c.scene.lights.size(),
                               where + " KHR_lights_punctual", "light");
        }
        for (const json& ch : arrayOrEmpty(c, nj, "children", where)) {
            n.children.push_back(checkIndex(c, ch, "children", nodes.size(), where, "node"));
        }
    }
    for (size_t i = 0; i < nodes.size(); ++i) {
        for (int ch : c.scene.nodes[i].children) {
            Node& child = c.scene.nodes[static_cast<size_t>(ch)];
            if (child.parent >= 0 || static_cast<size_t>(ch) == i)
                c.fail("node " + std::to_string(ch) + " has more than one parent or is its own child");
            child.parent = static_cast<int>(i);
        }
    }
    // With one parent per node, a cycle is a chain of parents that never
    // ends. Each chain is walked only until it meets a node already known to
    // reach a root, so the whole check is linear in the node count (a long
    // parent chain walked from every node would be quadratic).
    enum : uint8_t { Unknown, OnPath, ReachesRoot };
    std::vector<uint8_t> state(nodes.size(), Unknown);
    std::vector<size_t> path;
    for (size_t i = 0; i < nodes.size(); ++i) {
        path.clear();
        int p = static_cast<int>(i);
        while (p >= 0 && state[static_cast<size_t>(p)] == Unknown) {
            state[static_cast<size_t>(p)] = OnPath;
            path.push_back(static_cast<size_t>(p));
            p = c.scene.nodes[static_cast<size_t>(p)].parent;
        }
        if (p >= 0 && state[static_cast<size_t>(p)] == OnPath)
            c.fail("node " + std::to_string(p) + " is part of a cycle in the hierarchy");
        for (size_t n : path) state[n] = ReachesRoot;
    }
}

void loadDefaultScene(Context& c) {
    const json& scenes = arrayOrEmpty(c, c.doc, "scenes", "document");
    if (scenes.empty()) {
        for (size_t i = 0; i < c.scene.nodes.size(); ++i)
            if (c.scene.nodes[i].parent < 0) c.scene.roots.push_back(static_cast<int>(i));
        return;
    }
    int s = optIndex(c, c.doc, "scene", scenes.size(), "document", "scene");
    if (s < 0) s = 0;
    std::string where = "scene " + std::to_string(s);
    const json& sj = requireObject(c, scenes, static_cast<size_t>(s), where);
    for (const json& nj : arrayOrEmpty(c, sj, "nodes", where)) {
        c.scene.roots.push_back(checkIndex(c, nj, "nodes", c.scene.nodes.size(), where, "node"));
    }
}

void loadAnimations(Context& c) {
    const json& anims = arrayOrEmpty(c, c.doc, "animations", "document");
    for (size_t a = 0; a < anims.size(); ++a) {
        std::string where = "animation " + std::to_string(a);
        const json& aj = requireObject(c, anims, a, where);
        Animation anim;
        anim.name = optString(c, aj, "name", "", where);
        const json& samplers = arrayOrEmpty(c, aj, "samplers", where);
        const json& channels = arrayOrEmpty(c, aj, "channels", where);
        for (size_t k = 0; k < channels.size(); ++k) {
            std::string cw = where + " channel " + std::to_string(k);
            const json& cj = requireObject(c, channels, k, cw);
            int si = reqIndex(c, cj, "sampler", samplers.size(), cw, "sampler");
            if (!has(cj, "target") || !cj["target"].is_object()) c.fail(cw + ": missing 'target'");
            const json& target = cj["target"];
            int node = optIndex(c, target, "node", c.scene.nodes.size(), cw, "node");
            std::string path = optString(c, target, "path", "", cw);
            if (node < 0) continue;  // glTF allows targets defined only by extensions
            AnimationChannel ch;
            ch.node = node;
            if (path == "translation") ch.path = AnimPath::Translation;
            else if (path == "rotation") ch.path = AnimPath::Rotation;
            else if (path == "scale") ch.path = AnimPath::Scale;
            else {
                c.warn(cw + ": animating '" + path + "' is not supported; channel skipped");
                continue;
            }
            std::string sw = where + " sampler " + std::to_string(si);
            const json& sj = requireObject(c, samplers, static_cast<size_t>(si), sw);
            std::string interp = optString(c, sj, "interpolation", "LINEAR", sw);
            if (interp == "LINEAR") ch.interpolation = Interpolation::Linear;
            else if (interp == "STEP") ch.interpolation = Interpolation::Step;
            else if (interp == "CUBICSPLINE") ch.interpolation = Interpolation::CubicSpline;
            else c.fail(sw + ": unknown interpolation '" + interp + "'");
            int in = reqIndex(c, sj, "input", accessorCount(c), sw, "accessor");
            int out = reqIndex(c, sj, "output", accessorCount(c), sw, "accessor");
            for (const glm::vec4& t : readFloatAccessor(c, in, {"SCALAR"}, sw + " input")) ch.times.push_back(t.x);
            for (size_t i = 1; i < ch.times.size(); ++i)
                if (ch.times[i] < ch.times[i - 1]) c.fail(sw + ": input times are not ascending");
            bool rot = ch.path == AnimPath::Rotation;
            ch.values = readFloatAccessor(c, out, {rot ? "VEC4" : "VEC3"}, sw + " output");
            size_t expected = ch.times.size() * (ch.interpolation == Interpolation::CubicSpline ? 3 : 1);
            if (ch.values.size() != expected)
                c.fail(sw + ": output has " + std::to_string(ch.values.size()) + " values, expected " +
                       std::to_string(expected));
            c.scene.nodes[static_cast<size_t>(node)].dynamic = true;
            anim.channels.push_back(std::move(ch));
        }
        c.scene.animations.push_back(std::move(anim));
    }
}

}  // namespace dvsgi::scene::gltf
