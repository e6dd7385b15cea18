// Derived world-space views of a Scene: matrices, draw list, placed lights and
// cameras, bounds, and the defaults added to files without camera or light.
#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/matrix_decompose.hpp>
#include <glm/gtx/quaternion.hpp>

#include "scene/scene.h"

namespace dvsgi::scene {

namespace {

glm::mat4 localMatrix(const Node& n) {
    glm::mat4 t = glm::translate(glm::mat4(1.0f), n.translation);
    glm::mat4 r = glm::mat4_cast(glm::normalize(n.rotation));
    glm::mat4 s = glm::scale(glm::mat4(1.0f), n.scale);
    return t * r * s;
}

bool validNode(const Scene& scene, int i) {
    return i >= 0 && i < static_cast<int>(scene.nodes.size());
}

// Walks the hierarchy from the roots. A node is visited at most once, so a
// malformed (cyclic or multiply-parented) graph can neither loop forever nor
// place the same node twice.
std::vector<bool> reachable(const Scene& scene) {
    std::vector<bool> seen(scene.nodes.size(), false);
    std::vector<int> stack;
    for (int r : scene.roots) stack.push_back(r);
    while (!stack.empty()) {
        int i = stack.back();
        stack.pop_back();
        if (!validNode(scene, i) || seen[i]) continue;
        seen[i] = true;
        for (int c : scene.nodes[i].children) stack.push_back(c);
    }
    return seen;
}

glm::vec3 columnXYZ(const glm::mat4& m, int c) { return glm::vec3(m[c]); }

}  // namespace

std::vector<glm::mat4> worldMatrices(const Scene& scene) {
    std::vector<glm::mat4> world(scene.nodes.size(), glm::mat4(1.0f));
    std::vector<bool> seen(scene.nodes.size(), false);
    // Parents are always finished before their children are pushed, so each
    // child can multiply onto its parent's final matrix.
    std::vector<std::pair<int, glm::mat4>> stack;
    for (int r : scene.roots) stack.emplace_back(r, glm::mat4(1.0f));
    while (!stack.empty()) {
        auto [i, parentWorld] = stack.back();
        stack.pop_back();
        if (!validNode(scene, i) || seen[i]) continue;
        seen[i] = true;
        world[i] = parentWorld * localMatrix(scene.nodes[i]);
        for (int c : scene.nodes[i].children) stack.emplace_back(c, world[i]);
    }
    return world;
}

std::vector<DrawItem> drawItems(const Scene& scene, const std::vector<glm::mat4>& world) {
    std::vector<DrawItem> items;
    std::vector<bool> seen = reachable(scene);
    for (size_t i = 0; i < scene.nodes.size(); ++i) {
        const Node& n = scene.nodes[i];
        if (!seen[i] || n.mesh < 0 || n.mesh >= static_cast<int>(scene.meshes.size())) continue;
        glm::mat4 m = i < world.size() ? world[i] : glm::mat4(1.0f);
        for (uint32_t p : scene.meshes[n.mesh].primitives) {
            if (p >= scene.primitives.size()) continue;
            items.push_back(DrawItem{p, static_cast<int>(i), m});
        }
    }
    return items;
}

std::vector<PlacedLight> placedLights(const Scene& scene, const std::vector<glm::mat4>& world) {
    std::vector<PlacedLight> out;
    std::vector<bool> seen = reachable(scene);
    for (size_t i = 0; i < scene.nodes.size(); ++i) {
        const Node& n = scene.nodes[i];
        if (!seen[i] || n.light < 0 || n.light >= static_cast<int>(scene.lights.size())) continue;
        glm::mat4 m = i < world.size() ? world[i] : glm::mat4(1.0f);
        PlacedLight pl;
        pl.light = scene.lights[n.light];
        pl.position = columnXYZ(m, 3);
        glm::vec3 d = glm::vec3(m * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
        // A degenerate (zero-scale) node has no direction; keep the glTF default.
        float len = glm::length(d);
        pl.direction = len > 1e-20f ? d / len : glm::vec3(0.0f, 0.0f, -1.0f);
        out.push_back(pl);
    }
    return out;
}

std::vector<PlacedCamera> placedCameras(const Scene& scene, const std::vector<glm::mat4>& world) {
    std::vector<PlacedCamera> out;
    std::vector<bool> seen = reachable(scene);
    for (size_t i = 0; i < scene.nodes.size(); ++i) {
        const Node& n = scene.nodes[i];
        if (!seen[i] || n.camera < 0 || n.camera >= static_cast<int>(scene.cameras.size())) continue;
        out.push_back(PlacedCamera{scene.cameras[n.camera], i < world.size() ? world[i] : glm::mat4(1.0f)});
    }
    return out;
}

int placedCameraNode(const Scene& scene, int index) {
    const std::vector<bool> seen = reachable(scene);
    int placed = 0;
    for (size_t i = 0; i < scene.nodes.size(); ++i) {
        const Node& n = scene.nodes[i];
        if (!seen[i] || n.camera < 0 || n.camera >= static_cast<int>(scene.cameras.size())) continue;
        if (placed++ == index) return int(i);
    }
    return -1;
}

void setNodeWorld(Scene& scene, int i, const glm::mat4& world) {
    const std::vector<glm::mat4> all = worldMatrices(scene);
    Node& n = scene.nodes[size_t(i)];
    const glm::mat4 parent = n.parent >= 0 ? all[size_t(n.parent)] : glm::mat4(1.0f);
    glm::vec3 scale, translation, skew;
    glm::vec4 perspective;
    glm::quat rotation;
    if (!glm::decompose(glm::inverse(parent) * world, scale, rotation, translation, skew, perspective)) return;
    n.translation = translation;
    n.rotation = rotation;
}

Bounds worldBounds(const Scene& scene, const std::vector<DrawItem>& items) {
    Bounds b;
    for (const DrawItem& it : items) {
        if (it.primitive >= scene.primitives.size()) continue;
        for (const Vertex& v : scene.primitives[it.primitive].vertices) {
            glm::vec3 p = glm::vec3(it.world * glm::vec4(v.position, 1.0f));
            b.min = glm::min(b.min, p);
            b.max = glm::max(b.max, p);
        }
    }
    return b;
}

namespace {

// True when some placed surface emits light: such a scene is meant to be lit
// by its emitters (e.g. cornell-emissive.gltf), and an invented sun would add
// energy the reference images do not have.
bool hasEmissiveSurface(const Scene& scene, const std::vector<DrawItem>& items) {
    for (const DrawItem& it : items) {
        uint32_t m = scene.primitives[it.primitive].material;
        if (m >= scene.materials.size()) continue;
        const Material& mat = scene.materials[m];
        glm::vec3 e = mat.emissiveFactor * mat.emissiveStrength;
        if (std::max({e.x, e.y, e.z}) > 0.0f) return true;
    }
    return false;
}

int appendRootNode(Scene& scene, Node n) {
    int idx = static_cast<int>(scene.nodes.size());
    n.parent = -1;
    scene.nodes.push_back(std::move(n));
    scene.roots.push_back(idx);
    return idx;
}

}  // namespace

void addDefaults(Scene& scene) {
    std::vector<glm::mat4> world = worldMatrices(scene);
    std::vector<DrawItem> items = drawItems(scene, world);

    if (placedCameras(scene, world).empty()) {
        Bounds b = worldBounds(scene, items);
        if (!b.valid()) {
            b.min = glm::vec3(-1.0f);
            b.max = glm::vec3(1.0f);
        }
        glm::vec3 center = 0.5f * (b.min + b.max);
        float radius = std::max(0.5f * glm::length(b.max - b.min), 1e-3f);
        Camera cam;
        cam.name = "default_camera";
        cam.yfov = 0.6860478f;
        // The bounding sphere fits the vertical field of view at this distance,
        // and the horizontal one too for any image at least as wide as tall.
        float dist = radius / std::sin(0.5f * cam.yfov);
        cam.znear = std::max(1e-4f, 0.01f * radius);
        cam.zfar = 2.0f * (dist + radius);
        scene.cameras.push_back(cam);
        Node n;
        n.name = "default_camera";
        // Identity rotation: the camera looks down -Z, i.e. from +Z at the centre.
        n.translation = center + glm::vec3(0.0f, 0.0f, dist);
        n.camera = static_cast<int>(scene.cameras.size()) - 1;
        appendRootNode(scene, std::move(n));
    }

    if (placedLights(scene, world).empty() && !hasEmissiveSurface(scene, items)) {
        Light sun;
        sun.name = "default_sun";
        sun.type = LightType::Directional;
        sun.color = glm::vec3(1.0f);
        sun.intensity = 3.0f;  // irradiance, W/m^2
        scene.lights.push_back(sun);
        Node n;
        n.name = "default_sun";
        // Mostly down, and travelling away from the default camera (which sits
        // on +Z), so floors and the faces the camera sees are lit.
        glm::vec3 dir = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.5f));
        n.rotation = glm::rotation(glm::vec3(0.0f, 0.0f, -1.0f), dir);
        n.light = static_cast<int>(scene.lights.size()) - 1;
        appendRootNode(scene, std::move(n));
    }
}

}  // namespace dvsgi::scene
