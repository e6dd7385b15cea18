// validateScene: the format-independent checks loadScene runs after every
// importer. A value that passes here keeps every product the renderer forms
// (intensity x colour x albedo / distance^2, emission x strength) finite, and
// every camera invertible; docs/RELIABILITY.md lists the limits.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "scene/import_util.h"
#include "scene/load.h"

namespace dvsgi::scene {

namespace {

// Largest accepted light intensity x colour and emissive factor x strength.
// The brightest shared scene uses 200; 1e6 leaves room for any physical
// setup while products with albedos, areas and bounce sums stay far below
// the float maximum.
constexpr float kMaxRadiometric = 1e6f;
// World coordinates beyond this would overflow once squared (distances,
// bounds) in single precision.
constexpr float kMaxCoordinate = 1e18f;
constexpr float kPi = 3.14159265358979f;

std::string num(double v) {
    // Enough digits that a float just above a limit does not print as the limit.
    std::ostringstream s;
    s << std::setprecision(9) << v;
    return s.str();
}

class Validator {
public:
    explicit Validator(Scene& s) : s_(s) {
        std::string ext = detail::lowercase(std::filesystem::path(s.source).extension().string());
        mtl_ = ext == ".obj" || ext == ".ply";
    }

    void run() {
        for (size_t i = 0; i < s_.materials.size(); ++i) material(i);
        for (size_t i = 0; i < s_.lights.size(); ++i) light(i);
        for (size_t i = 0; i < s_.cameras.size(); ++i) camera(i);
        for (size_t i = 0; i < s_.primitives.size(); ++i) geometry(i);
        cameraTransforms();
        bounds();
        if (repairedNormals_ > 0)
            warn(std::to_string(repairedNormals_) +
                 " vertex normal(s) were zero or not finite; replaced by the face normal");
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw LoadError(detail::printable(s_.source + ": " + what));
    }
    void warn(const std::string& what) { s_.warnings.push_back(detail::printable(s_.source + ": " + what)); }

    static std::string label(const char* kind, size_t i, const std::string& name) {
        return std::string(kind) + " " + std::to_string(i) + (name.empty() ? "" : " ('" + name + "')");
    }

    // A radiometric value: finite and not negative.
    void radiometric(const std::string& where, const std::string& name, float v) const {
        if (!std::isfinite(v)) fail(where + ": " + name + " is not finite");
        if (v < 0.0f) fail(where + ": " + name + " " + num(v) + " is negative");
    }

    void material(size_t i) {
        Material& m = s_.materials[i];
        const std::string where = label("material", i, m.name);
        const char* base = mtl_ ? "diffuse colour (Kd)" : "baseColorFactor";
        const char* alpha = mtl_ ? "opacity (d/Tr)" : "baseColorFactor alpha";
        bool clamped = false;
        for (int k = 0; k < 4; ++k) {
            float& v = m.baseColorFactor[k];
            radiometric(where, k == 3 ? alpha : base, v);
            // A reflectance above 1 creates energy on every bounce.
            if (v > 1.0f) {
                v = 1.0f;
                clamped = true;
            }
        }
        if (clamped) warn(where + ": " + base + " above 1 clamped to 1");
        const char* emissive = mtl_ ? "emissive colour (Ke)" : "emissiveFactor";
        for (int k = 0; k < 3; ++k) radiometric(where, emissive, m.emissiveFactor[k]);
        radiometric(where, "emissiveStrength", m.emissiveStrength);
        float peak = std::max({m.emissiveFactor.x, m.emissiveFactor.y, m.emissiveFactor.z});
        double product = double(peak) * double(m.emissiveStrength);
        if (product > kMaxRadiometric)
            fail(where + ": " + emissive + " x emissiveStrength = " + num(product) + " exceeds the limit " +
                 num(kMaxRadiometric));
        for (auto [v, name] : {std::pair<float*, const char*>{&m.metallicFactor, "metallicFactor"},
                               {&m.roughnessFactor, "roughnessFactor"},
                               {&m.alphaCutoff, "alphaCutoff"}}) {
            if (!std::isfinite(*v)) fail(where + ": " + name + " is not finite");
            *v = std::clamp(*v, 0.0f, 1.0f);
        }
        if (!std::isfinite(m.normalScale)) fail(where + ": normalTexture scale is not finite");
    }

    void light(size_t i) {
        const Light& l = s_.lights[i];
        const std::string where = label("light", i, l.name);
        for (int k = 0; k < 3; ++k) radiometric(where, "color", l.color[k]);
        radiometric(where, "intensity", l.intensity);
        double product = double(l.intensity) * double(std::max({l.color.x, l.color.y, l.color.z}));
        if (product > kMaxRadiometric)
            fail(where + ": intensity x color = " + num(product) + " exceeds the limit " + num(kMaxRadiometric));
        if (l.type != LightType::Spot) return;
        const float inner = l.innerConeAngle, outer = l.outerConeAngle;
        if (!std::isfinite(inner) || !std::isfinite(outer) || inner < 0.0f || outer <= 0.0f || inner > outer ||
            outer > 0.5f * kPi + 1e-6f)
            fail(where + ": spot cone angles need 0 <= innerConeAngle <= outerConeAngle <= pi/2 and "
                         "outerConeAngle > 0 (got " + num(inner) + ", " + num(outer) + ")");
    }

    void camera(size_t i) {
        const Camera& c = s_.cameras[i];
        const std::string where = label("camera", i, c.name);
        if (!std::isfinite(c.yfov) || !(c.yfov > 0.0f) || !(c.yfov < kPi))
            fail(where + ": yfov " + num(c.yfov) + " must be in (0, pi)");
        if (!std::isfinite(c.znear) || !(c.znear > 0.0f))
            fail(where + ": znear " + num(c.znear) + " must be positive and finite");
        // The depth mapping divides by zfar - znear; values this close give
        // no usable depth precision (or a division by zero).
        if (!std::isfinite(c.zfar) || !(double(c.zfar) > double(c.znear) * (1.0 + 1e-6)))
            fail(where + ": zfar " + num(c.zfar) + " must be finite and greater than znear " + num(c.znear));
        if (!std::isfinite(c.aspectRatio) || c.aspectRatio < 0.0f)
            fail(where + ": aspectRatio " + num(c.aspectRatio) + " must be finite and not negative");
    }

    void geometry(size_t pi) {
        Primitive& p = s_.primitives[pi];
        const std::string where = "primitive " + std::to_string(pi);
        for (size_t v = 0; v < p.vertices.size(); ++v) {
            const glm::vec3& x = p.vertices[v].position;
            for (int k = 0; k < 3; ++k) {
                if (!std::isfinite(x[k])) fail(where + ": vertex " + std::to_string(v) + " position is not finite");
                if (std::abs(x[k]) > kMaxCoordinate)
                    fail(where + ": vertex " + std::to_string(v) + " position " + num(x[k]) + " exceeds " +
                         num(kMaxCoordinate));
            }
            const glm::vec2& uv = p.vertices[v].uv;
            if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
                fail(where + ": vertex " + std::to_string(v) + " texture coordinate is not finite");
        }
        repairNormals(p);
    }

    static bool usable(const glm::vec3& n) {
        float len2 = glm::dot(n, n);
        return std::isfinite(len2) && len2 > 1e-24f;
    }

    // A zero or non-finite normal turns shading black or NaN. Such a vertex
    // gets the geometric normal of its triangle; where several triangles
    // share it, their area-weighted sum (the face normal when they are
    // coplanar). Usable normals are only renormalized.
    void repairNormals(Primitive& p) {
        std::vector<uint32_t> bad;
        for (uint32_t v = 0; v < p.vertices.size(); ++v)
            if (!usable(p.vertices[v].normal)) bad.push_back(v);
        // Unit-length within rounding is left bit-exact (files round-trip).
        for (Vertex& v : p.vertices)
            if (usable(v.normal) && std::abs(glm::dot(v.normal, v.normal) - 1.0f) > 1e-4f)
                v.normal = glm::normalize(v.normal);
        if (bad.empty()) return;
        std::vector<glm::vec3> sum(p.vertices.size(), glm::vec3(0.0f));
        std::vector<bool> isBad(p.vertices.size(), false);
        for (uint32_t v : bad) isBad[v] = true;
        for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
            uint32_t a = p.indices[t], b = p.indices[t + 1], c = p.indices[t + 2];
            if (!isBad[a] && !isBad[b] && !isBad[c]) continue;
            glm::vec3 n = glm::cross(p.vertices[b].position - p.vertices[a].position,
                                     p.vertices[c].position - p.vertices[a].position);
            if (!usable(n)) continue;
            for (uint32_t v : {a, b, c}) sum[v] += n;
        }
        for (uint32_t v : bad) {
            // A vertex only on degenerate triangles shades nothing; any unit
            // vector keeps it finite.
            glm::vec3 n = usable(sum[v]) ? glm::normalize(sum[v]) : glm::vec3(0.0f, 0.0f, 1.0f);
            Vertex& vx = p.vertices[v];
            vx.normal = n;
            glm::vec3 t(vx.tangent);
            t -= n * glm::dot(n, t);
            if (!usable(t)) t = std::abs(n.x) < 0.9f ? glm::cross(n, glm::vec3(1, 0, 0)) : glm::cross(n, glm::vec3(0, 1, 0));
            vx.tangent = glm::vec4(glm::normalize(t), vx.tangent.w < 0.0f ? -1.0f : 1.0f);
            ++repairedNormals_;
        }
    }

    void cameraTransforms() {
        const std::vector<glm::mat4> world = worldMatrices(s_);
        for (size_t i = 0; i < s_.nodes.size(); ++i) {
            const Node& n = s_.nodes[i];
            if (n.camera < 0) continue;
            const glm::mat4& m = world[i];
            glm::vec3 cols[3] = {glm::vec3(m[0]), glm::vec3(m[1]), glm::vec3(m[2])};
            bool ok = true;
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) ok = ok && std::isfinite(m[c][r]);
            // Orientation independent of the overall scale: the determinant
            // of the normalized axes is 0 for a flattened camera, 1 for a
            // proper one.
            for (glm::vec3& col : cols) {
                ok = ok && usable(col);
                if (ok) col = glm::normalize(col);
            }
            if (ok) ok = std::abs(glm::dot(glm::cross(cols[0], cols[1]), cols[2])) > 1e-3f;
            if (!ok)
                fail(label("node", i, n.name) +
                     ": the camera's transform is singular or not finite (zero scale or a degenerate rotation)");
        }
    }

    void bounds() {
        const std::vector<glm::mat4> world = worldMatrices(s_);
        Bounds b = worldBounds(s_, drawItems(s_, world));
        if (!b.valid()) return;
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(b.min[k]) || !std::isfinite(b.max[k]) || std::abs(b.min[k]) > kMaxCoordinate ||
                std::abs(b.max[k]) > kMaxCoordinate)
                fail("scene extent is not finite or exceeds " + num(kMaxCoordinate) +
                     " m (node transforms x coordinates)");
    }

    Scene& s_;
    bool mtl_ = false;
    size_t repairedNormals_ = 0;
};

}  // namespace

void validateScene(Scene& scene) { Validator(scene).run(); }

}  // namespace dvsgi::scene
