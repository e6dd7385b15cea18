#include "gpu_fixture.h"

#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/quaternion.hpp>

namespace dvsgi::test {

gpu::Context& context() {
    static std::unique_ptr<gpu::Context> ctx = [] {
        gpu::ContextOptions o;
        o.validation = true;
        return std::make_unique<gpu::Context>(o);
    }();
    return *ctx;
}

int addUniformTexture(scene::Scene& s, uint8_t r, uint8_t g, uint8_t b) {
    scene::Texture t;
    t.name = "uniform" + std::to_string(s.textures.size());
    t.width = t.height = 2;
    for (int i = 0; i < 4; ++i) t.rgba8.insert(t.rgba8.end(), {r, g, b, 255});
    t.srgb = false;
    s.textures.push_back(t);
    return int(s.textures.size() - 1);
}

int addMaterial(scene::Scene& s, glm::vec3 albedo, glm::vec3 emission, bool doubleSided) {
    scene::Material m;
    m.name = "m" + std::to_string(s.materials.size());
    m.baseColorFactor = glm::vec4(albedo, 1.0f);
    m.emissiveFactor = emission;
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 1.0f;
    m.doubleSided = doubleSided;
    s.materials.push_back(m);
    return int(s.materials.size() - 1);
}

int addQuad(scene::Scene& s, int material, glm::vec3 center, float h, glm::quat rotation) {
    scene::Primitive p;
    const glm::vec3 corners[4] = {{-h, 0, -h}, {-h, 0, h}, {h, 0, h}, {h, 0, -h}};  // CCW seen from +Y
    for (const glm::vec3& c : corners) {
        scene::Vertex v;
        v.position = c;
        v.normal = glm::vec3(0, 1, 0);
        v.uv = glm::vec2(c.x / (2 * h) + 0.5f, c.z / (2 * h) + 0.5f);
        p.vertices.push_back(v);
    }
    p.indices = {0, 1, 2, 0, 2, 3};
    p.material = uint32_t(material);
    s.primitives.push_back(p);
    scene::Mesh mesh;
    mesh.primitives = {uint32_t(s.primitives.size() - 1)};
    s.meshes.push_back(mesh);
    scene::Node n;
    n.name = "quad" + std::to_string(s.nodes.size());
    n.mesh = int(s.meshes.size() - 1);
    n.translation = center;
    n.rotation = rotation;
    s.nodes.push_back(n);
    s.roots.push_back(int(s.nodes.size() - 1));
    return int(s.nodes.size() - 1);
}

void addTopDownCamera(scene::Scene& s, float height, float yfov) {
    scene::Camera c;
    c.name = "top";
    c.yfov = yfov;
    c.znear = 0.01f;
    c.zfar = 100.0f;
    s.cameras.push_back(c);
    scene::Node n;
    n.name = "camera";
    n.camera = int(s.cameras.size() - 1);
    n.translation = glm::vec3(0, height, 0);
    n.rotation = glm::angleAxis(-glm::half_pi<float>(), glm::vec3(1, 0, 0));  // -Z looks down -Y
    s.nodes.push_back(n);
    s.roots.push_back(int(s.nodes.size() - 1));
}

void addLight(scene::Scene& s, scene::Light light, glm::vec3 position, glm::vec3 direction) {
    s.lights.push_back(light);
    scene::Node n;
    n.name = light.name;
    n.light = int(s.lights.size() - 1);
    n.translation = position;
    // Rotate the node's -Z onto `direction`.
    const glm::vec3 from(0, 0, -1), to = glm::normalize(direction);
    const float c = glm::dot(from, to);
    if (c < -0.9999f)
        n.rotation = glm::angleAxis(glm::pi<float>(), glm::vec3(0, 1, 0));
    else
        n.rotation = glm::rotation(from, to);
    s.nodes.push_back(n);
    s.roots.push_back(int(s.nodes.size() - 1));
}

image::ImageRGBA32F render(const scene::Scene& s, const render::RenderSettings& settings) {
    render::Renderer r(context(), s, settings);
    r.renderFrame();
    return r.readOutput();
}

glm::vec3 pixelOnPlane(const scene::Scene& s, const render::RenderSettings& settings, uint32_t x, uint32_t y,
                       float planeY) {
    const std::vector<glm::mat4> world = scene::worldMatrices(s);
    const scene::PlacedCamera cam = scene::placedCameras(s, world).at(size_t(settings.camera));
    const glm::mat4 inv = glm::inverse(render::projectionMatrix(cam, settings.width, settings.height) *
                                       render::viewMatrix(cam));
    const glm::vec2 ndc = (glm::vec2(x, y) + 0.5f) / glm::vec2(settings.width, settings.height) * 2.0f - 1.0f;
    glm::vec4 a = inv * glm::vec4(ndc, 0.0f, 1.0f), b = inv * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
    const float t = (planeY - p0.y) / (p1.y - p0.y);
    return p0 + (p1 - p0) * t;
}

scene::Primitive icosphere(int subdivisions) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<glm::dvec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                 {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    std::vector<glm::uvec3> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (glm::dvec3& p : v) p = glm::normalize(p);
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            v.push_back(glm::normalize(v[a] + v[b]));
            return mid[key] = uint32_t(v.size() - 1);
        };
        std::vector<glm::uvec3> next;
        for (const glm::uvec3& tri : f) {
            const uint32_t a = midpoint(tri.x, tri.y), b = midpoint(tri.y, tri.z), c = midpoint(tri.z, tri.x);
            next.insert(next.end(), {{tri.x, a, c}, {tri.y, b, a}, {tri.z, c, b}, {a, b, c}});
        }
        f = next;
    }
    scene::Primitive p;
    for (const glm::dvec3& q : v) {
        scene::Vertex vert;
        vert.position = glm::vec3(q);
        vert.normal = glm::vec3(q);
        p.vertices.push_back(vert);
    }
    for (const glm::uvec3& tri : f) p.indices.insert(p.indices.end(), {tri.x, tri.y, tri.z});
    return p;
}


int addMeshNode(scene::Scene& s, scene::Primitive p, int material, glm::vec3 t, glm::quat r, glm::vec3 scale) {
    p.material = uint32_t(material);
    s.primitives.push_back(std::move(p));
    s.meshes.push_back(scene::Mesh{"mesh", {uint32_t(s.primitives.size() - 1)}});
    scene::Node n;
    n.mesh = int(s.meshes.size() - 1);
    n.translation = t;
    n.rotation = r;
    n.scale = scale;
    s.nodes.push_back(n);
    s.roots.push_back(int(s.nodes.size() - 1));
    return int(s.nodes.size() - 1);
}

gpu::Tracker volumeTracker(const vxgi::VoxelVolumes& volumes) {
    gpu::Tracker tracker;
    for (const gpu::Image* v : volumes.all()) tracker.assume(*v, gpu::use::ComputeReadWrite);
    return tracker;
}

}  // namespace dvsgi::test
