#include "bench/hausdorff.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace dvsgi::bench {

namespace {

// A k-d tree over the points (median splits along the widest axis): nearest()
// descends to the query's leaf and backs out through the subtrees whose
// splitting plane is nearer than the best distance so far. A uniform grid
// searched in growing shells was tried first; a sample far from every voxel
// (the side pv has not seen yet) made it visit millions of empty cells.
class NearestTree {
public:
    explicit NearestTree(const std::vector<glm::dvec3>& points) : points_(points), order_(points.size()) {
        for (size_t i = 0; i < order_.size(); ++i) order_[i] = uint32_t(i);
        if (!order_.empty()) build(0, order_.size());
    }

    double nearest(const glm::dvec3& q) const {
        double best2 = std::numeric_limits<double>::infinity();
        if (!nodes_.empty()) search(0, q, best2);
        return std::sqrt(best2);
    }

private:
    static constexpr size_t kLeaf = 8;
    struct Node {
        uint32_t begin, end;   // the points order_[begin, end)
        int axis = -1;         // -1: a leaf
        double split = 0.0;
        uint32_t left = 0, right = 0;
    };

    uint32_t build(size_t begin, size_t end) {
        const uint32_t id = uint32_t(nodes_.size());
        nodes_.push_back({uint32_t(begin), uint32_t(end)});
        if (end - begin <= kLeaf) return id;
        glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
        for (size_t i = begin; i < end; ++i) lo = glm::min(lo, points_[order_[i]]), hi = glm::max(hi, points_[order_[i]]);
        const glm::dvec3 extent = hi - lo;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        const size_t mid = (begin + end) / 2;
        std::nth_element(order_.begin() + long(begin), order_.begin() + long(mid), order_.begin() + long(end),
                         [&](uint32_t a, uint32_t b) { return points_[a][axis] < points_[b][axis]; });
        const double split = points_[order_[mid]][axis];
        const uint32_t left = build(begin, mid), right = build(mid, end);
        Node& n = nodes_[id];
        n.axis = axis;
        n.split = split;
        n.left = left;
        n.right = right;
        return id;
    }

    void search(uint32_t id, const glm::dvec3& q, double& best2) const {
        const Node& n = nodes_[id];
        if (n.axis < 0) {
            for (uint32_t i = n.begin; i < n.end; ++i) {
                const glm::dvec3 d = points_[order_[i]] - q;
                best2 = std::min(best2, glm::dot(d, d));
            }
            return;
        }
        const double d = q[n.axis] - n.split;
        search(d < 0.0 ? n.left : n.right, q, best2);
        if (d * d < best2) search(d < 0.0 ? n.right : n.left, q, best2);
    }

    const std::vector<glm::dvec3>& points_;
    std::vector<uint32_t> order_;
    std::vector<Node> nodes_;
};

double meanNearest(const std::vector<glm::dvec3>& from, const NearestTree& to) {
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

Hausdorff averageHausdorff(const std::vector<glm::dvec3>& surface, const std::vector<glm::dvec3>& voxelCentres) {
    Hausdorff h;
    if (surface.empty() || voxelCentres.empty()) {
        h.surfaceToVoxels = h.voxelsToSurface = std::numeric_limits<double>::infinity();
        return h;
    }
    h.surfaceToVoxels = meanNearest(surface, NearestTree(voxelCentres));
    h.voxelsToSurface = meanNearest(voxelCentres, NearestTree(surface));
    return h;
}

}  // namespace dvsgi::bench
