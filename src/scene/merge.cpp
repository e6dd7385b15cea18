#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "scene/scene.h"

namespace dvsgi::scene {

int appendScene(Scene& dst, const Scene& src, const std::string& rootName) {
    const uint32_t primBase = uint32_t(dst.primitives.size()), meshBase = uint32_t(dst.meshes.size());
    const int matBase = int(dst.materials.size()), texBase = int(dst.textures.size());
    const int nodeBase = int(dst.nodes.size());
    dst.textures.insert(dst.textures.end(), src.textures.begin(), src.textures.end());
    for (Material m : src.materials) {
        for (int* t : {&m.baseColorTexture, &m.emissiveTexture, &m.metallicRoughnessTexture, &m.normalTexture})
            if (*t >= 0) *t += texBase;
        dst.materials.push_back(m);
    }
    for (Primitive p : src.primitives) {
        p.material += uint32_t(matBase);
        dst.primitives.push_back(std::move(p));
    }
    for (Mesh m : src.meshes) {
        for (uint32_t& p : m.primitives) p += primBase;
        dst.meshes.push_back(m);
    }
    // A new root holds the source's root nodes, so the whole model moves as one.
    Node root;
    root.name = rootName;
    const int rootIndex = nodeBase + int(src.nodes.size());
    for (Node n : src.nodes) {
        if (n.mesh >= 0) n.mesh += int(meshBase);
        n.camera = -1;  // the model brings geometry only
        n.light = -1;
        for (int& c : n.children) c += nodeBase;
        n.parent = n.parent >= 0 ? n.parent + nodeBase : -1;
        dst.nodes.push_back(n);
    }
    for (int r : src.roots) {
        dst.nodes[size_t(nodeBase + r)].parent = rootIndex;
        root.children.push_back(nodeBase + r);
    }
    dst.nodes.push_back(root);
    dst.roots.push_back(rootIndex);
    return rootIndex;
}

void addCircularPath(Scene& scene, int node, glm::vec3 center, float radius, float period, uint32_t keys) {
    AnimationChannel translation, rotation;
    translation.node = rotation.node = node;
    translation.path = AnimPath::Translation;
    rotation.path = AnimPath::Rotation;
    for (uint32_t k = 0; k <= keys; ++k) {
        const float t = period * float(k) / float(keys);
        const float a = glm::two_pi<float>() * float(k) / float(keys);
        translation.times.push_back(t);
        translation.values.emplace_back(center + radius * glm::vec3(std::cos(a), 0.0f, std::sin(a)), 0.0f);
        // Face along the path: rotate about +Y by -a.
        const glm::quat q = glm::angleAxis(-a, glm::vec3(0, 1, 0));
        rotation.times.push_back(t);
        rotation.values.emplace_back(q.x, q.y, q.z, q.w);
    }
    Animation anim;
    anim.name = "circular path of " + scene.nodes[size_t(node)].name;
    anim.channels = {translation, rotation};
    scene.animations.push_back(anim);
    scene.nodes[size_t(node)].dynamic = true;
}

}  // namespace dvsgi::scene
