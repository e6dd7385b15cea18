// A CPU model of the rays of shaders/lib/voxel_rays.glsl (the voxel bounce's
// and the per-pixel gather's): a ray walks the grid cell by cell and takes the
// radiance of the first occupied voxel that is not on the surface it leaves
// and that it does not pass in front of.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "light_helpers.h"
#include "shared/bounce_pass.h"
#include "shared/voxel_data.h"
#include "vox_helper.h"
#include "vxgi/voxel_storage_io.h"

namespace dvsgi::test {

// voxelNormal of the voxel at c from the read-back attribute sums, packed as
// the rays read it (BIND_BOUNCE_RAY_NORMALS: each axis in steps of 1/RAY_NORMAL_SCALE).
inline glm::vec3 rayNormalOf(const VoxelReadback& attributes, glm::ivec3 c) {
    glm::vec3 n(0.0f);
    for (int a = 0; a < 3; ++a)
        n[a] = std::sqrt(attributes.at(c.x, c.y, c.z, shader::CH_NORMAL_POS_X + 2 * a)) -
               std::sqrt(attributes.at(c.x, c.y, c.z, shader::CH_NORMAL_NEG_X + 2 * a));
    const float len = glm::length(n);
    if (len <= 1e-6f) return glm::vec3(0.0f);
    const float scale = shader::RAY_NORMAL_SCALE;
    return glm::floor(glm::clamp(n / len, -1.0f, 1.0f) * scale + 0.5f) / scale;
}

// passesInFront: the ray p + d t, inside voxel c, leaves it (at tExit) before
// the plane through c's centre across c's normal nc.
inline bool rayPassesInFront(glm::ivec3 c, glm::vec3 nc, glm::vec3 p, glm::vec3 d, float t, float tExit) {
    if (!shader::alongAnAxis(nc)) return false;  // edges, corners, tilted surfaces: solid
    const float ahead = glm::dot(glm::vec3(c) + 0.5f - (p + d * t), nc), along = glm::dot(d, nc);
    if (ahead * along <= 0.0f) return false;
    return t + ahead / along > tExit;
}

// What the rays read of a voxel besides its radiance and normal: its extents
// (the extents buffer's word, 0 = not known) and side texel. A thin wall's
// voxel shows the side a ray meets and lets a ray pass beside the wall's end
// with either setting; with --edge-voxels faces (`faces`) a ray also passes
// beside the part of any voxel its surface does not reach, and a voxel that
// shows its faces shows a ray along d what facesSeen gives from its radiance
// texel.
struct EdgeModel {
    std::function<uint32_t(glm::ivec3)> extents;
    std::function<bool(glm::ivec3)> showsFaces;
    std::function<glm::vec3(glm::ivec3, glm::vec3 nc, glm::vec3 d, glm::vec4 r)> facesSeen;
    std::function<glm::uvec4(glm::ivec3)> sides;
    bool faces = true;
    bool thinWallEnds = true;  // rays pass beside thin walls' ends (off: as before that rule, to measure it)
};

// lib/voxel_attributes.glsl's voxelShowsFaces from the read-back sums.
inline bool showsFaces(const VoxelReadback& a, glm::ivec3 c) {
    glm::dvec3 pos(0.0), neg(0.0), first(0.0);
    for (int k = 0; k < 3; ++k) {
        pos[k] = a.average(c.x, c.y, c.z, shader::CH_NORMAL_POS_X + 2 * k);
        neg[k] = a.average(c.x, c.y, c.z, shader::CH_NORMAL_NEG_X + 2 * k);
        first[k] = a.average(c.x, c.y, c.z, shader::CH_FIRST_X + k);
        if (std::min(pos[k], neg[k]) >= shader::TWO_SIDED_MIN_WEIGHT) return false;
    }
    return planeShareOf(pos, neg, first) < shader::FACES_BELOW_PLANE_SHARE;
}

// lib/voxel_rays.glsl's facesSeen, from a voxel's side texel t: its reflected
// light, and each face's direct light weighted by how much it turns toward the ray.
inline glm::vec3 facesSeen(glm::uvec4 t, glm::vec3 nc, glm::vec3 d, glm::vec4 r) {
    const glm::vec3 reflected = glm::max(glm::vec3(r) - vxgi::unpackRgb9e5(t.w), glm::vec3(0.0f));
    const glm::vec3 w = nc * nc * glm::max(-d * glm::sign(nc), glm::vec3(0.0f));
    const float total = w.x + w.y + w.z;
    if (total < 1e-6f) return reflected;
    return reflected +
           (w.x * vxgi::unpackRgb9e5(t.x) + w.y * vxgi::unpackRgb9e5(t.y) + w.z * vxgi::unpackRgb9e5(t.z)) / total;
}

// The model from what was read back: the attribute sums, the extents and the
// side light per grid voxel (readExtents, vxgi::readSideLight), for
// --edge-voxels faces or not. The model keeps copies.
inline EdgeModel edgeModel(const VoxelReadback& attributes, std::vector<uint32_t> extents,
                           std::vector<glm::uvec4> sides, bool faces = true) {
    const uint32_t n = attributes.n;
    auto e = std::make_shared<std::vector<uint32_t>>(std::move(extents));
    auto s = std::make_shared<std::vector<glm::uvec4>>(std::move(sides));
    auto a = std::make_shared<VoxelReadback>(attributes);
    return {[e, n](glm::ivec3 c) { return (*e)[voxelIndex(n, c.x, c.y, c.z)]; },
            [a](glm::ivec3 c) { return showsFaces(*a, c); },
            [s, n](glm::ivec3 c, glm::vec3 nc, glm::vec3 d, glm::vec4 r) {
                return facesSeen((*s)[voxelIndex(n, c.x, c.y, c.z)], nc, d, r);
            },
            [s, n](glm::ivec3 c) { return (*s)[voxelIndex(n, c.x, c.y, c.z)]; }, faces};
}
// The same, read from the volumes.
inline EdgeModel edgeModel(const gpu::Context& ctx, const vxgi::VoxelVolumes& v, const VoxelReadback& attributes,
                           bool faces = true) {
    return edgeModel(attributes, readExtents(v), vxgi::readSideLight(ctx, v), faces);
}

// passesBeside: the ray p + d t, inside voxel c (leaving it at tExit), misses
// the box its extents give: for a plane along an axis where it crosses the
// plane through c's centre (or where it enters, if it does not cross it in c),
// otherwise anywhere along its path through c.
inline bool rayPassesBeside(glm::ivec3 c, glm::vec3 nc, uint32_t bits, glm::vec3 p, glm::vec3 d, float t, float tExit) {
    if (bits == 0u || bits == shader::VOXEL_EXTENT_ALL) return false;
    glm::vec3 lo, hi;
    for (int k = 0; k < 3; ++k) {
        uint32_t m = (bits >> (shader::VOXEL_EXTENT_STEPS * k)) & 0xffu;
        if (m == 0u) m = 0xffu;
        int first = 0, last = 7;
        while (!(m & (1u << first))) ++first;
        while (!(m & (1u << last))) --last;
        lo[k] = float(c[k]) + float(first) / 8.0f;
        hi[k] = float(c[k]) + float(last + 1) / 8.0f;
    }
    if (shader::alongAnAxis(nc)) {
        const int a = shader::largestAxis(glm::abs(nc));
        const float tp = std::fabs(d[a]) > 1e-7f ? (float(c[a]) + 0.5f - p[a]) / d[a] : -1.0f;
        const glm::vec3 q = p + d * (tp >= t && tp <= tExit ? tp : t);
        for (int k = 0; k < 3; ++k)
            if (k != a && (q[k] < lo[k] - 1e-4f || q[k] > hi[k] + 1e-4f)) return true;
        return false;
    }
    float enter = t, leave = tExit;
    for (int k = 0; k < 3; ++k) {
        if (d[k] == 0.0f) {
            if (p[k] < lo[k] || p[k] > hi[k]) return true;
            continue;
        }
        const float t0 = (lo[k] - p[k]) / d[k], t1 = (hi[k] - p[k]) / d[k];
        enter = std::max(enter, std::min(t0, t1));
        leave = std::min(leave, std::max(t0, t1));
    }
    return enter > leave + 1e-4f;
}

// passesThinWallEnd: the ray p + d t, inside voxel c (leaving it at tExit),
// which holds a thin wall's two sides across `axis`, does not cross the plane
// through c's centre across it there and misses c's extents box.
inline bool rayPassesThinWallEnd(glm::ivec3 c, int axis, uint32_t bits, glm::vec3 p, glm::vec3 d, float t,
                                 float tExit) {
    const float ahead = float(c[axis]) + 0.5f - (p[axis] + d[axis] * t);
    bool crosses;
    if (std::fabs(d[axis]) < 1e-7f) {
        crosses = std::fabs(ahead) <= 1e-4f;
    } else {
        const float tp = t + ahead / d[axis];
        crosses = tp >= t - 1e-4f && tp <= tExit + 1e-4f;
    }
    return !crosses && rayPassesBeside(c, glm::vec3(0.0f), bits, p, d, t, tExit);
}

// The axis (0-2) across which a voxel whose radiance opacity is `opacity` holds
// a thin wall's two sides, or -1.
inline int thinWallAxis(float opacity) { return shader::twoSidedAxis(shader::sideCodeOfOpacity(opacity)); }

// radianceSeen: a thin wall's voxel shows a ray along d the side it meets
// (direct + reflected), from its side texel t.
inline glm::vec3 thinWallSideSeen(glm::uvec4 t, int axis, glm::vec3 d) {
    const bool plusSide = d[axis] < 0.0f;
    return vxgi::unpackRgb9e5(plusSide ? t.x : t.y) + vxgi::unpackRgb9e5(plusSide ? t.z : t.w);
}

// lib/voxel_rays.glsl's pixelRayOffset: how far off surface point p (voxel
// units, normal n) a pixel's rays start, `offset` voxels or just before the
// first voxel past p's own, within that stretch, whose surface faces back
// toward p (one-sided and turned toward it, or a thin wall across an axis
// near n, or thin walls along several axes).
template <typename NormalAt>
float pixelRayOffset(const Rgba16Volume& radiance, NormalAt&& normalAt, glm::vec3 p, glm::vec3 n, float offset) {
    const int size = int(radiance.n);
    const auto exitOf = [&](glm::ivec3 c) {
        float t = INFINITY;
        for (int a = 0; a < 3; ++a) {
            if (std::fabs(n[a]) < 1e-7f) continue;
            t = std::min(t, ((n[a] > 0.0f ? float(c[a] + 1) : float(c[a])) - p[a]) / n[a]);
        }
        return t;
    };
    float t = exitOf(glm::ivec3(glm::floor(p))) + 1e-3f;
    for (int k = 0; k < 3 * int(std::ceil(offset)) + 1 && t < offset; ++k) {
        const glm::ivec3 c = glm::ivec3(glm::floor(p + n * t));
        if (glm::any(glm::lessThan(c, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(c, glm::ivec3(size)))) break;
        const glm::vec4 r = radiance.at(c.x, c.y, c.z);
        if (r.a > 0.0f) {
            const int axis = thinWallAxis(r.a);
            const bool facing = shader::sideCodeOfOpacity(r.a) == shader::SIDE_ONE ? glm::dot(normalAt(c), n) < -0.5f
                                                                               : (axis < 0 || std::fabs(n[axis]) > 0.7f);
            if (facing) return std::max(t - shader::RAY_GAP_MARGIN, 0.0f);
        }
        t = exitOf(c) + 1e-3f;
    }
    return offset;
}

// Where a ray starts: a voxel's rays that start inside another surface's voxel
// meet its back (no light); a pixel's pass that voxel when they move away from
// its plane and start in front of it (up to half a voxel behind it for a
// one-sided voxel with a normal), and otherwise meet it; having passed it they
// pass that surface's voxels (within a voxel and a half of its plane, facing
// its way) as their own.
enum class RayStart { Voxel, Pixel };

// What a ray from p along d (voxel units) meets in `radiance`: `own(c)` says
// whether occupied voxel c is on the surface the ray leaves, `normalAt(c)`
// gives c's normal as the rays read it. Black where it leaves the grid. With
// `backsDark` a one-sided voxel met from behind shows part of its light or none
// (seenFromFront in lib/voxel_sides.glsl).
// `tHit` (optional) receives where the ray entered the voxel it stopped at
// (infinity where it left the grid), as ambient occlusion weighs it.
// `edges` (optional): the voxels' extents and side light (EdgeModel), with
// its `faces` setting.
template <typename Own, typename NormalAt>
glm::vec3 marchRay(const Rgba16Volume& radiance, glm::vec3 p, glm::vec3 d, Own&& own, NormalAt&& normalAt,
                   RayStart start, bool backsDark = true, float* tHit = nullptr, const EdgeModel* edges = nullptr) {
    const int n = int(radiance.n);
    glm::ivec3 c = glm::ivec3(glm::floor(p));
    glm::ivec3 step(0);
    glm::vec3 tMax(1e30f), tDelta(1e30f);
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0f) continue;
        step[a] = d[a] > 0.0f ? 1 : -1;
        tDelta[a] = 1.0f / std::fabs(d[a]);
        tMax[a] = ((d[a] > 0.0f ? float(c[a] + 1) : float(c[a])) - p[a]) / d[a];
    }
    float t = 0.0f;  // where the ray entered cell c
    if (tHit) *tHit = INFINITY;
    glm::vec3 besideAt(0.0f), besideN(0.0f);  // the surface a pixel's ray started beside
    const auto beside = [&](glm::ivec3 v, glm::vec3 nv) {
        return std::fabs(glm::dot(glm::vec3(v) + 0.5f - besideAt, besideN)) < 1.5f && glm::dot(nv, besideN) > 0.8f;
    };
    for (bool first = true;; first = false) {
        for (int a = 0; a < 3; ++a)
            if (c[a] < 0 || c[a] >= n) return glm::vec3(0.0f);
        const glm::vec4 r = radiance.at(c.x, c.y, c.z);
        const int a = tMax.x <= tMax.y && tMax.x <= tMax.z ? 0 : (tMax.y <= tMax.z ? 1 : 2);
        const bool passes =
            r.a > 0.0f && edges && edges->faces && rayPassesBeside(c, normalAt(c), edges->extents(c), p, d, t, tMax[a]);
        const int wallAxis = r.a > 0.0f && edges ? thinWallAxis(r.a) : -1;
        const bool thinEnds = wallAxis >= 0 && edges->thinWallEnds;
        if (r.a > 0.0f && !own(c) && !beside(c, normalAt(c)) && !(passes && !(first && start == RayStart::Pixel))) {
            const glm::vec3 nc = normalAt(c);
            if (tHit) *tHit = t;
            if (first && start == RayStart::Voxel) return glm::vec3(0.0f);
            const float behind = r.a >= 1.0f && glm::dot(nc, nc) > 0.25f ? -0.5f : 0.0f;
            const bool leaves = first && glm::dot(p - (glm::vec3(c) + 0.5f), nc) > behind && glm::dot(d, nc) >= 0.0f;
            if (leaves) {
                besideAt = glm::vec3(c) + 0.5f;
                besideN = nc;
            }
            if (leaves || rayPassesInFront(c, nc, p, d, t, tMax[a]) || passes ||
                (thinEnds && rayPassesThinWallEnd(c, wallAxis, edges->extents(c), p, d, t, tMax[a]))) {
                if (tHit) *tHit = INFINITY;
            } else {
                // A voxel that shows its faces weighs them itself, unfaded.
                if (edges && edges->faces && r.a >= 1.0f && edges->showsFaces(c)) return edges->facesSeen(c, nc, d, r);
                if (wallAxis >= 0) return thinWallSideSeen(edges->sides(c), wallAxis, d);
                // Without a model, two-sided voxels (r.a < 1) show their radiance, the darker side.
                if (!backsDark || r.a < 1.0f) return glm::vec3(r);
                const float fade = (shader::VOXEL_BACK_FADE_END - glm::dot(nc, d)) /
                                   (shader::VOXEL_BACK_FADE_END - shader::VOXEL_BACK_FADE_START);
                return glm::vec3(r) * std::clamp(fade, 0.0f, 1.0f);
            }
        }
        t = tMax[a];
        c[a] += step[a];
        tMax[a] += tDelta[a];
    }
}

// lib/voxel_rays.glsl's sheetAcross: whether voxel c holds a sheet across
// axis a that a pixel facing n meets (one-sided along a, turned n's way, or a
// thin wall across a), with its extents along a known; those in `bits`.
template <typename NormalAt>
bool sheetAcross(const Rgba16Volume& radiance, NormalAt&& normalAt, const EdgeModel& edges, glm::ivec3 c,
                 glm::vec3 n, int a, uint32_t& bits) {
    bits = 0u;
    const int size = int(radiance.n);
    if (glm::any(glm::lessThan(c, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(c, glm::ivec3(size))))
        return false;
    const glm::vec4 r = radiance.at(c.x, c.y, c.z);
    if (r.a <= 0.0f) return false;
    bits = (edges.extents(c) >> (shader::VOXEL_EXTENT_STEPS * a)) & 0xffu;
    if (bits == 0u || bits == 0xffu) return false;
    if (shader::sideCodeOfOpacity(r.a) != shader::SIDE_ONE) return thinWallAxis(r.a) == a;
    const glm::vec3 nc = normalAt(c);
    return std::fabs(nc[a]) >= shader::RAY_PLANE_AXIS_COS && nc[a] * n[a] > 0.0f;
}

// lib/voxel_rays.glsl's sheetAhead: the plane along axis `a` of a sheet in
// front of surface point p (normal n) nearer than `start`, or -1.
template <typename NormalAt>
float sheetAhead(const Rgba16Volume& radiance, NormalAt&& normalAt, const EdgeModel& edges, glm::vec3 p, glm::vec3 n,
                 float start, int& a) {
    const glm::vec3 m = glm::abs(n);
    a = shader::largestAxis(m);
    if (m[a] < 0.7f) return -1.0f;
    const int dir = n[a] > 0.0f ? 1 : -1;
    glm::ivec3 c = glm::ivec3(glm::floor(p));
    uint32_t bits;
    float plane = -1.0f;
    if (sheetAcross(radiance, normalAt, edges, c, n, a, bits)) {
        int own = std::clamp(int(std::floor((p[a] - float(c[a])) * 8.0f)), 0, 7);
        for (int e = own + dir; e >= 0 && e < 8 && (bits & (1u << e)); e += dir) {
            if ((float(c[a]) + float(dir > 0 ? e : e + 1) / 8.0f - p[a]) * float(dir) >= 0.125f) break;
            own = e;
        }
        const int next = own + dir;
        if (next >= 0 && next < 8 && !(bits & (1u << next)))
            for (int e = next + dir; e >= 0 && e < 8; e += dir)
                if (bits & (1u << e)) {
                    plane = float(c[a]) + float(dir > 0 ? e : e + 1) / 8.0f;
                    break;
                }
    }
    if (plane < 0.0f) {
        c[a] += dir;
        if (sheetAcross(radiance, normalAt, edges, c, n, a, bits)) {
            int first = 0, last = 7;
            while (!(bits & (1u << first))) ++first;
            while (!(bits & (1u << last))) --last;
            plane = float(c[a]) + float(dir > 0 ? first : last + 1) / 8.0f;
            if ((plane - p[a]) * float(dir) < shader::RAY_SHEET_GAP) plane = -1.0f;
        }
    }
    return plane >= 0.0f && (plane - p[a]) * float(dir) < start ? plane : -1.0f;
}

// lib/voxel_rays.glsl's sheetCells, meetsSheet and sheetSeen for one ray:
// whether the ray from p along d meets the sheet sheetAhead found (plane
// along a), with what it sees there.
template <typename NormalAt>
bool meetsSheet(const Rgba16Volume& radiance, NormalAt&& normalAt, const EdgeModel& edges, glm::vec3 p, glm::vec3 n,
                glm::vec3 d, int a, float plane, bool backsDark, glm::vec3& seen) {
    seen = glm::vec3(0.0f);
    if (d[a] * n[a] <= 1e-4f) return false;
    const float t = (plane - p[a]) / d[a];
    glm::ivec3 c = glm::ivec3(glm::floor(p + d * t));
    c[a] = int(std::floor(plane + (n[a] > 0.0f ? 1e-4f : -1e-4f)));
    glm::ivec3 off = glm::abs(c - glm::ivec3(glm::floor(p)));
    off[a] = 0;
    if (std::max({off.x, off.y, off.z}) > shader::RAY_SHEET_REACH) return false;
    uint32_t bits;
    if (!sheetAcross(radiance, normalAt, edges, c, n, a, bits)) return false;
    const int eighth = int(std::round((plane - float(c[a])) * 8.0f)) - (n[a] > 0.0f ? 0 : 1);
    if (eighth < 0 || eighth > 7 || !(bits & (1u << eighth))) return false;
    const glm::vec4 r = radiance.at(c.x, c.y, c.z);
    const int axis = thinWallAxis(r.a);
    if (axis >= 0) {
        seen = thinWallSideSeen(edges.sides(c), axis, d);
        return true;
    }
    seen = glm::vec3(r);
    if (backsDark) {
        const float fade = (shader::VOXEL_BACK_FADE_END - glm::dot(normalAt(c), d)) /
                           (shader::VOXEL_BACK_FADE_END - shader::VOXEL_BACK_FADE_START);
        seen *= std::clamp(fade, 0.0f, 1.0f);
    }
    return true;
}

// A pixel's ray as pixelRaysCosine casts it: it meets a sheet closer than its
// start (sheetAhead, meetsSheet), or else is marched from `start` voxels off p.
template <typename Own, typename NormalAt>
glm::vec3 pixelRay(const Rgba16Volume& radiance, glm::vec3 p, glm::vec3 n, float start, glm::vec3 d, Own&& own,
                   NormalAt&& normalAt, const EdgeModel& edges, bool backsDark = true) {
    int axis;
    const float plane = sheetAhead(radiance, normalAt, edges, p, n, start, axis);
    glm::vec3 seen;
    if (plane >= 0.0f && meetsSheet(radiance, normalAt, edges, p, n, d, axis, plane, backsDark, seen)) return seen;
    return marchRay(radiance, p + n * start, d, own, normalAt, RayStart::Pixel, backsDark, nullptr, &edges);
}

// The i-th of a set of rays cosine-distributed about n (frame t, b), the R2
// sequence shifted by `seed`, as voxelRaysCosine and pixelRaysCosine cast them.
inline glm::vec3 cosineRay(glm::vec3 n, uint32_t seed, uint32_t i) {
    const glm::vec3 t = glm::normalize(std::fabs(n.x) < 0.9f ? glm::cross(n, glm::vec3(1, 0, 0))
                                                             : glm::cross(n, glm::vec3(0, 1, 0)));
    const glm::vec3 b = glm::cross(n, t);
    const glm::vec2 shift(float(seed & 0xffffu) / 65536.0f, float(seed >> 16) / 65536.0f);
    const glm::vec2 u = glm::fract(shift + float(i) * glm::vec2(shader::RAY_R2_U, shader::RAY_R2_V));
    const float rad = std::sqrt(u.x), phi = 6.28318530717959f * u.y;
    return glm::normalize(t * (rad * std::cos(phi)) + b * (rad * std::sin(phi)) +
                          n * std::sqrt(std::max(1.0f - u.x, 0.0f)));
}

}  // namespace dvsgi::test
