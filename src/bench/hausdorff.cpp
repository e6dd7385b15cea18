#include "bench/hausdorff.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace dvsgi::bench {

namespace {

// Points binned in cubes of edge `cell`; nearest() searches shells of cells
// around the query until no closer point can lie further out.
class NearestGrid {
public:
    NearestGrid(const std::vector<glm::dvec3>& points, double cell) : points_(points), cell_(cell) {
        for (size_t i = 0; i < points.size(); ++i) cells_[key(cellOf(points[i]))].push_back(uint32_t(i));
        for (const glm::dvec3& p : points) {
            lo_ = glm::min(lo_, cellOf(p));
            hi_ = glm::max(hi_, cellOf(p));
        }
    }

    double nearest(const glm::dvec3& q) const {
        const glm::i64vec3 c = cellOf(q);
        double best = std::numeric_limits<double>::infinity();
        // Shell r holds the cells at Chebyshev distance r; a point in it is at
        // least (r - 1) cells away.
        const int64_t maxR = std::max({std::abs(c.x - lo_.x), std::abs(c.x - hi_.x), std::abs(c.y - lo_.y),
                                       std::abs(c.y - hi_.y), std::abs(c.z - lo_.z), std::abs(c.z - hi_.z)});
        for (int64_t r = 0; r <= maxR; ++r) {
            if (double(r - 1) * cell_ > best) break;
            for (int64_t z = c.z - r; z <= c.z + r; ++z)
                for (int64_t y = c.y - r; y <= c.y + r; ++y)
                    for (int64_t x = c.x - r; x <= c.x + r; ++x) {
                        if (std::max({std::abs(x - c.x), std::abs(y - c.y), std::abs(z - c.z)}) != r) continue;
                        const auto it = cells_.find(key({x, y, z}));
                        if (it == cells_.end()) continue;
                        for (uint32_t i : it->second) best = std::min(best, glm::distance(points_[i], q));
                    }
        }
        return best;
    }

private:
    glm::i64vec3 cellOf(const glm::dvec3& p) const { return glm::i64vec3(glm::floor(p / cell_)); }
    static uint64_t key(const glm::i64vec3& c) {
        const uint64_t mask = (1ull << 21) - 1;
        return (uint64_t(c.x) & mask) | ((uint64_t(c.y) & mask) << 21) | ((uint64_t(c.z) & mask) << 42);
    }

    const std::vector<glm::dvec3>& points_;
    double cell_;
    std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
    glm::i64vec3 lo_{std::numeric_limits<int64_t>::max()}, hi_{std::numeric_limits<int64_t>::min()};
};

double meanNearest(const std::vector<glm::dvec3>& from, const NearestGrid& to) {
    if (from.empty()) return std::numeric_limits<double>::infinity();
    double sum = 0.0;
    for (const glm::dvec3& p : from) sum += to.nearest(p);
    return sum / double(from.size());
}

}  // namespace

std::vector<glm::dvec3> surfaceSamples(const scene::Scene& s, size_t count) {
    const std::vector<scene::DrawItem> items = scene::drawItems(s, scene::worldMatrices(s));
    struct Tri {
        glm::dvec3 a, b, c;
        double area;
    };
    std::vector<Tri> tris;
    double total = 0.0;
    for (const scene::DrawItem& it : items) {
        const scene::Primitive& p = s.primitives[it.primitive];
        for (size_t i = 0; i + 2 < p.indices.size(); i += 3) {
            Tri t;
            t.a = glm::dvec3(it.world * glm::vec4(p.vertices[p.indices[i]].position, 1.0f));
            t.b = glm::dvec3(it.world * glm::vec4(p.vertices[p.indices[i + 1]].position, 1.0f));
            t.c = glm::dvec3(it.world * glm::vec4(p.vertices[p.indices[i + 2]].position, 1.0f));
            t.area = 0.5 * glm::length(glm::cross(t.b - t.a, t.c - t.a));
            total += t.area;
            tris.push_back(t);
        }
    }
    std::vector<glm::dvec3> out;
    if (total <= 0.0 || count == 0) return out;
    out.reserve(count + tris.size());
    // Each triangle gets its share of the samples, the fractions carried on so
    // the total comes out right; points from the R2 sequence folded into it.
    double carry = 0.0;
    constexpr double g = 1.32471795724474602596;  // plastic number
    for (const Tri& t : tris) {
        carry += double(count) * t.area / total;
        const size_t n = size_t(carry);
        carry -= double(n);
        for (size_t k = 0; k < n; ++k) {
            double u = std::fmod(0.5 + double(k + 1) / g, 1.0), v = std::fmod(0.5 + double(k + 1) / (g * g), 1.0);
            if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
            out.push_back(t.a + u * (t.b - t.a) + v * (t.c - t.a));
        }
    }
    return out;
}

Hausdorff averageHausdorff(const std::vector<glm::dvec3>& surface, const std::vector<glm::dvec3>& voxelCentres,
                           double cell) {
    Hausdorff h;
    if (surface.empty() || voxelCentres.empty()) {
        h.surfaceToVoxels = h.voxelsToSurface = std::numeric_limits<double>::infinity();
        return h;
    }
    h.surfaceToVoxels = meanNearest(surface, NearestGrid(voxelCentres, cell));
    h.voxelsToSurface = meanNearest(voxelCentres, NearestGrid(surface, cell));
    return h;
}

}  // namespace dvsgi::bench
