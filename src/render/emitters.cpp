#include "render/emitters.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "shared/scene_data.h"
#include "shared/voxel_data.h"

namespace dvsgi::render {

namespace {

namespace sh = dvsgi::shader;

struct Tri {
    glm::vec3 a, b, c;
    glm::vec3 radiance;  // emitted, W m^-2 sr^-1
    bool doubleSided;
    float area() const { return 0.5f * glm::length(glm::cross(b - a, c - a)); }
};

// One patch: power-weighted sums, so merged triangles keep their total power.
struct Patch {
    glm::vec3 power{0.0f};     // sum of radiance * area (W/sr at normal incidence)
    glm::vec3 centroid{0.0f};  // area-weighted
    glm::vec3 normal{0.0f};    // area-weighted
    float area = 0.0f;
    bool doubleSided = false;
    void add(const Tri& t) {
        const float a = t.area();
        power += t.radiance * a;
        centroid += (t.a + t.b + t.c) / 3.0f * a;
        normal += glm::normalize(glm::cross(t.b - t.a, t.c - t.a)) * a;
        area += a;
        doubleSided = doubleSided || t.doubleSided;
    }
};

sh::GpuLight toLight(const Patch& p) {
    const glm::vec3 centroid = p.centroid / p.area;
    const float len = glm::length(p.normal);
    // Opposite faces merged into one cluster cancel: emit both ways.
    const bool bothWays = p.doubleSided || len < 0.5f * p.area;
    const glm::vec3 n = len > 0.0f ? p.normal / len : glm::vec3(0.0f, 1.0f, 0.0f);
    sh::GpuLight l{};
    l.position = glm::vec4(centroid, float(sh::LIGHT_AREA));
    l.direction = glm::vec4(n, bothWays ? 1.0f : 0.0f);
    // Disk of the same area: r^2 = A / pi regularizes 1/d^2 near the patch.
    l.radiant = glm::vec4(p.power, p.area / 3.14159265f);
    l.shadow = glm::uvec4(0u, 0u, sh::OCCLUSION_RAYCAST_HARD, 0u);
    return l;
}

std::vector<Tri> emissiveTriangles(const scene::Scene& scene, const std::vector<scene::DrawItem>& items,
                                   bool& textured) {
    std::vector<Tri> tris;
    for (const scene::DrawItem& item : items) {
        const scene::Primitive& prim = scene.primitives[item.primitive];
        const scene::Material& m = scene.materials[prim.material];
        const glm::vec3 radiance = m.emissiveFactor * m.emissiveStrength;
        if (!(std::max({radiance.r, radiance.g, radiance.b}) > 0.0f)) continue;
        if (m.emissiveTexture >= 0) textured = true;
        // A mirroring transform turns counter-clockwise (front) into clockwise.
        const bool flip = glm::determinant(glm::mat3(item.world)) < 0.0f;
        for (size_t i = 0; i + 2 < prim.indices.size(); i += 3) {
            glm::vec3 p[3];
            for (int k = 0; k < 3; ++k)
                p[k] = glm::vec3(item.world * glm::vec4(prim.vertices[prim.indices[i + k]].position, 1.0f));
            Tri t{p[0], flip ? p[2] : p[1], flip ? p[1] : p[2], radiance, m.doubleSided};
            if (t.area() > 0.0f) tris.push_back(t);
        }
    }
    return tris;
}

}  // namespace

EmitterPatches emitterPatches(const scene::Scene& scene, const std::vector<scene::DrawItem>& items,
                              uint32_t maxPatches) {
    EmitterPatches out;
    bool textured = false;
    std::vector<Tri> tris = emissiveTriangles(scene, items, textured);
    if (textured) {
        out.complete = false;
        return out;
    }
    if (tris.empty() || maxPatches == 0) return out;
    if (tris.size() <= maxPatches) {
        // Few large triangles: split the largest along its longest edge until
        // the budget is used, so patches stay small against their distances.
        while (tris.size() < maxPatches) {
            auto big = std::max_element(tris.begin(), tris.end(),
                                        [](const Tri& x, const Tri& y) { return x.area() < y.area(); });
            Tri t = *big;
            const float ab = glm::length(t.b - t.a), bc = glm::length(t.c - t.b), ca = glm::length(t.a - t.c);
            Tri u = t, v = t;
            if (ab >= bc && ab >= ca) {
                const glm::vec3 m = 0.5f * (t.a + t.b);
                u.b = m;
                v.a = m;
            } else if (bc >= ca) {
                const glm::vec3 m = 0.5f * (t.b + t.c);
                u.c = m;
                v.b = m;
            } else {
                const glm::vec3 m = 0.5f * (t.c + t.a);
                u.a = m;
                v.c = m;
            }
            *big = u;
            tris.push_back(v);
        }
        for (const Tri& t : tris) {
            Patch p;
            p.add(t);
            out.lights.push_back(toLight(p));
        }
        return out;
    }
    // Many small triangles: cluster them on a grid of at most maxPatches cells
    // over the emitters' bounds.
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const Tri& t : tris) {
        const glm::vec3 c = (t.a + t.b + t.c) / 3.0f;
        lo = glm::min(lo, c);
        hi = glm::max(hi, c);
    }
    const int k = std::max(1, int(std::floor(std::cbrt(double(maxPatches)))));
    const glm::vec3 cell = glm::max((hi - lo) / float(k), glm::vec3(1e-6f));
    std::map<int, Patch> clusters;
    for (const Tri& t : tris) {
        const glm::ivec3 g = glm::clamp(glm::ivec3(((t.a + t.b + t.c) / 3.0f - lo) / cell), glm::ivec3(0),
                                        glm::ivec3(k - 1));
        clusters[(g.z * k + g.y) * k + g.x].add(t);
    }
    for (const auto& [key, p] : clusters) out.lights.push_back(toLight(p));
    return out;
}

}  // namespace dvsgi::render
