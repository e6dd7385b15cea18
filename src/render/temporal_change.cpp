#include "render/temporal_change.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "render/renderer.h"
#include "shared/composite_pass.h"

namespace dvsgi::render {

namespace {

// Without normals, a tap is the same surface within this many times the
// depth tolerance (a slanted floor's depth changes by a few per cent per pixel).
constexpr float kTapTolerance = 4.0f;
constexpr float kSameNormal = 0.9f;  // cos of about 25 degrees

// The world point a camera saw at pixel (x, y) at depth `depth` along its axis.
glm::vec3 pointSeen(const scene::PlacedCamera& camera, const glm::mat4& invProj, uint32_t w, uint32_t h, uint32_t x,
                    uint32_t y, float depth) {
    const glm::vec2 ndc((float(x) + 0.5f) / float(w) * 2.0f - 1.0f, (float(y) + 0.5f) / float(h) * 2.0f - 1.0f);
    const glm::vec4 ray = invProj * glm::vec4(ndc, 1.0f, 1.0f);
    glm::vec3 pc = glm::vec3(ray) / ray.w;
    pc *= depth / -pc.z;
    return glm::vec3(camera.world * glm::vec4(pc, 1.0f));
}

float luminance(const float* p) { return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]; }

// Luminance of `img` at continuous pixel coordinates (pixel centres at +0.5),
// bilinear over the taps `sees` accepts (weights renormalized): beside a
// silhouette the taps that saw another surface stay out, or the figure would
// count the resampling of an edge as change. Negative when no tap is accepted.
template <typename Sees>
float sampleLuminance(const image::ImageRGBA32F& img, glm::vec2 p, const Sees& sees) {
    const glm::vec2 q = p - 0.5f;
    const int x0 = int(std::floor(q.x)), y0 = int(std::floor(q.y));
    const float fx = q.x - float(x0), fy = q.y - float(y0);
    float sum = 0.0f, weight = 0.0f;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            const uint32_t x = uint32_t(std::clamp(x0 + i, 0, int(img.width) - 1));
            const uint32_t y = uint32_t(std::clamp(y0 + j, 0, int(img.height) - 1));
            const float w = (i ? fx : 1.0f - fx) * (j ? fy : 1.0f - fy);
            if (w <= 0.0f || !sees(x, y)) continue;
            sum += w * luminance(img.at(x, y));
            weight += w;
        }
    return weight > 0.0f ? sum / weight : -1.0f;
}

}  // namespace

TemporalChange temporalChange(const TemporalFrame& before, const TemporalFrame& after, float depthTolerance,
                              TemporalTerm which) {
    const image::ImageRGBA32F& termB = which == TemporalTerm::Irradiance ? before.irradiance : before.term;
    const image::ImageRGBA32F& termA = which == TemporalTerm::Irradiance ? after.irradiance : after.term;
    const uint32_t w = termA.width, h = termA.height;
    if (termB.width != w || termB.height != h || after.depth.width != w || after.depth.height != h ||
        before.depth.width != w || before.depth.height != h)
        throw std::invalid_argument("temporalChange: the frames' images differ in size");
    const glm::mat4 projA = projectionMatrix(after.camera, w, h), projB = projectionMatrix(before.camera, w, h);
    const glm::mat4 invProjA = glm::inverse(projA), invProjB = glm::inverse(projB);
    const glm::mat4 viewB = viewMatrix(before.camera);

    struct Pair {
        float before, after;
    };
    std::vector<Pair> pairs;
    pairs.reserve(size_t(w) * h);
    TemporalChange out;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const float d = after.depth.at(x, y)[0];
            if (!std::isfinite(d) || d <= 0.0f) continue;
            const glm::vec3 world = pointSeen(after.camera, invProjA, w, h, x, y, d);
            // Where frame t saw that point, and how far its surface was there.
            const glm::vec3 inB = glm::vec3(viewB * glm::vec4(world, 1.0f));
            const glm::vec4 clip = projB * glm::vec4(inB, 1.0f);
            if (clip.w <= 0.0f) {
                ++out.rejected;
                continue;
            }
            const glm::vec2 nb = glm::vec2(clip) / clip.w;
            const glm::vec2 pb((nb.x + 1.0f) * 0.5f * float(w), (nb.y + 1.0f) * 0.5f * float(h));
            if (pb.x < 0.0f || pb.y < 0.0f || pb.x >= float(w) || pb.y >= float(h)) {
                ++out.rejected;
                continue;
            }
            // Frame t saw this surface at the pixel holding pb if its depth
            // matches. Its bilinear taps (up to 1.5 pixels away) count when
            // they saw the same surface: their points lie on this pixel's
            // tangent plane (within the same tolerance, however slanted the
            // surface) and, where normals were captured, face the same way
            // (a crease is on both planes). A silhouette's or crease's other
            // side stays out, or the figure would count resampling an edge as change.
            const float expected = -inB.z;
            const float seenHere = before.depth.at(uint32_t(pb.x), uint32_t(pb.y))[0];
            if (!std::isfinite(seenHere) || std::abs(seenHere - expected) > depthTolerance * expected) {
                ++out.rejected;
                continue;
            }
            const bool normals = !after.normal.rgba.empty() && !before.normal.rgba.empty();
            const glm::vec3 n = normals ? glm::make_vec3(after.normal.at(x, y)) : glm::vec3(0.0f);
            auto sees = [&](uint32_t px, uint32_t py) {
                const float seen = before.depth.at(px, py)[0];
                if (!std::isfinite(seen)) return false;
                if (!normals) return std::abs(seen - expected) <= kTapTolerance * depthTolerance * expected;
                if (glm::dot(glm::make_vec3(before.normal.at(px, py)), n) < kSameNormal) return false;
                const glm::vec3 tap = pointSeen(before.camera, invProjB, w, h, px, py, seen);
                return std::abs(glm::dot(tap - world, n)) <= depthTolerance * expected;
            };
            const float valueB = sampleLuminance(termB, pb, sees);
            if (valueB < 0.0f) {
                ++out.rejected;
                continue;
            }
            pairs.push_back({valueB, luminance(termA.at(x, y))});
        }
    out.compared = pairs.size();
    if (pairs.empty()) return out;
    double sumB = 0.0, sumA = 0.0;
    for (const Pair& p : pairs) {
        sumB += p.before;
        sumA += p.after;
    }
    out.meanLuminanceBefore = sumB / double(pairs.size());
    out.meanLuminanceAfter = sumA / double(pairs.size());
    const double floor = std::max(0.01 * out.meanLuminanceBefore, 1e-12);
    std::vector<double> rel;
    rel.reserve(pairs.size());
    double sum = 0.0;
    for (const Pair& p : pairs) {
        rel.push_back(std::abs(double(p.after) - double(p.before)) / std::max(double(p.before), floor));
        sum += rel.back();
    }
    out.meanRelative = sum / double(rel.size());
    const size_t k = std::min(rel.size() - 1, size_t(std::ceil(0.99 * double(rel.size()))) - 1);
    std::nth_element(rel.begin(), rel.begin() + std::ptrdiff_t(k), rel.end());
    out.p99Relative = rel[k];
    return out;
}

TemporalFrame captureIndirect(const Renderer& renderer) {
    TemporalFrame f;
    f.term = renderer.readTerm(shader::TERM_INDIRECT);
    f.irradiance = renderer.readTerm(shader::TERM_IRRADIANCE);
    Renderer::SurfaceImages surface = renderer.readSurface();
    f.depth = std::move(surface.depth);
    f.normal = std::move(surface.normal);
    f.camera = renderer.camera();
    return f;
}

}  // namespace dvsgi::render
