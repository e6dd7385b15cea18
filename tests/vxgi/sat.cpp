#include "sat.h"

#include <algorithm>
#include <cmath>

namespace dvsgi::test {

namespace {

// Separated along `axis` when the triangle's projection interval and the
// box's lie strictly apart; equal end points mean touching, i.e. overlap.
bool separated(const glm::dvec3& axis, const glm::dvec3 (&v)[3], const glm::dvec3& half) {
    const double p0 = glm::dot(axis, v[0]), p1 = glm::dot(axis, v[1]), p2 = glm::dot(axis, v[2]);
    const double r = half.x * std::abs(axis.x) + half.y * std::abs(axis.y) + half.z * std::abs(axis.z);
    return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
}

}  // namespace

bool triangleBoxOverlap(const Triangle& t, const glm::dvec3& boxMin, const glm::dvec3& boxMax) {
    // Centre the box so each axis test compares against a symmetric interval.
    return triangleBoxOverlapCentred(t, (boxMin + boxMax) * 0.5, (boxMax - boxMin) * 0.5);
}

bool triangleBoxOverlapCentred(const Triangle& t, const glm::dvec3& c, const glm::dvec3& half) {
    const glm::dvec3 v[3] = {t.v[0] - c, t.v[1] - c, t.v[2] - c};
    const glm::dvec3 e[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    const glm::dvec3 unit[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

    for (const glm::dvec3& u : unit)
        if (separated(u, v, half)) return false;
    // A zero axis (a degenerate normal or parallel edges) projects everything
    // to 0 and cannot separate, so it needs no special case.
    if (separated(glm::cross(e[0], e[1]), v, half)) return false;
    for (const glm::dvec3& ei : e)
        for (const glm::dvec3& u : unit)
            if (separated(glm::cross(ei, u), v, half)) return false;
    return true;
}

size_t VoxelSet::count() const {
    return size_t(std::count_if(bits.begin(), bits.end(), [](uint8_t b) { return b != 0; }));
}

void referenceVoxelize(const Triangle& t, VoxelSet& out, double growth) {
    glm::dvec3 lo = glm::min(t.v[0], glm::min(t.v[1], t.v[2]));
    glm::dvec3 hi = glm::max(t.v[0], glm::max(t.v[1], t.v[2]));
    // Closed boxes: a coordinate on a voxel boundary also touches the voxel below.
    const int n = int(out.n);
    glm::ivec3 a, b;
    for (int i = 0; i < 3; ++i) {
        a[i] = std::max(int(std::ceil(lo[i] - growth)) - 1, 0);
        b[i] = std::min(int(std::floor(hi[i] + growth)), n - 1);
    }
    // The centre is exact (integer + 0.5) and the half-size the one the
    // compute voxelizer uses, so both decide every case alike.
    const glm::dvec3 half(0.5 + growth);
    for (int z = a.z; z <= b.z; ++z)
        for (int y = a.y; y <= b.y; ++y)
            for (int x = a.x; x <= b.x; ++x) {
                if (out.get(x, y, z)) continue;
                const glm::dvec3 centre = glm::dvec3(x, y, z) + 0.5;
                if (triangleBoxOverlapCentred(t, centre, half)) out.set(x, y, z);
            }
}

VoxelSet referenceVoxelize(const std::vector<Triangle>& tris, uint32_t n, double growth) {
    VoxelSet s(n);
    for (const Triangle& t : tris) referenceVoxelize(t, s, growth);
    return s;
}

CoverageReport compareCoverage(const VoxelSet& ref, const VoxelSet& gpu) {
    CoverageReport r;
    const int n = int(ref.n);
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const bool inRef = ref.get(x, y, z), inGpu = gpu.get(x, y, z);
                r.reference += inRef;
                r.gpu += inGpu;
                if (inRef && !inGpu) {
                    ++r.misses;
                    if (r.missList.size() < 8) r.missList.emplace_back(x, y, z);
                }
                if (inGpu && !inRef) {
                    ++r.extras;
                    bool near = false;
                    for (int dz = -1; dz <= 1 && !near; ++dz)
                        for (int dy = -1; dy <= 1 && !near; ++dy)
                            for (int dx = -1; dx <= 1 && !near; ++dx) near = ref.get(x + dx, y + dy, z + dz);
                    if (!near) {
                        ++r.farExtras;
                        if (r.farList.size() < 8) r.farList.emplace_back(x, y, z);
                    }
                }
            }
    return r;
}

}  // namespace dvsgi::test
