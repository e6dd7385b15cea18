// The temporal accumulation pass's test harness (tests/render/temporal_indirect*_test.cpp):
// a wall and a floating quad, or a floor, seen by cameras that look down -z,
// their depth and normals written analytically into a G-buffer, and the pass
// run outside a Renderer one frame at a time.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>

#include "gpu/context.h"
#include "gpu/transfer.h"
#include "gpu_fixture.h"
#include "render/temporal_indirect.h"
#include "shared/scene_data.h"
#include "shared/temporal_indirect_pass.h"

namespace dvsgi::test::temporal {

namespace sh = dvsgi::shader;

constexpr uint32_t kW = 96, kH = 64;

// The scene: a wall in z = 0 (|y| <= 2, normal +z; background above and
// below) and a quad in z = 2 over [x0, x1] x [-0.5, 0.5] facing +z. Cameras
// look down -z, so view depth is the camera's z minus the surface's.
struct Scene {
    float x0 = -0.5f, x1 = 0.3f;
};

struct Camera {
    glm::vec3 position;
    glm::mat4 viewProj() const {
        glm::mat4 p = glm::perspective(glm::radians(60.0f), float(kW) / float(kH), 0.1f, 100.0f);
        p[1][1] *= -1.0f;
        return p * glm::lookAt(position, position + glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
    }
};

struct Hit {
    bool found = false;
    glm::vec3 point{0.0f};
    int surface = -1;  // 0 wall, 1 quad
};

// The direction of the ray through pixel (x, y)'s centre.
inline glm::vec3 rayThrough(const Camera& c, uint32_t x, uint32_t y) {
    const glm::mat4 inv = glm::inverse(c.viewProj());
    const glm::vec2 ndc((float(x) + 0.5f) / kW * 2.0f - 1.0f, (float(y) + 0.5f) / kH * 2.0f - 1.0f);
    const glm::vec4 far = inv * glm::vec4(ndc, 1.0f, 1.0f);
    return glm::normalize(glm::vec3(far) / far.w - c.position);
}

inline Hit castPixel(const Scene& s, const Camera& c, uint32_t x, uint32_t y) {
    const glm::vec3 d = rayThrough(c, x, y);
    Hit h;
    const glm::vec3 q = c.position + d * ((2.0f - c.position.z) / d.z);
    if (q.x >= s.x0 && q.x <= s.x1 && std::abs(q.y) <= 0.5f) return {true, q, 1};
    const glm::vec3 w = c.position + d * (-c.position.z / d.z);
    if (std::abs(w.y) <= 2.0f) return {true, w, 0};
    return h;
}

// A floor, y = kFloorY (normal +y), out to z = -60, seen by the same cameras
// (which look horizontally): near the horizon it is seen at grazing angles.
constexpr float kFloorY = -0.25f;

inline Hit castFloor(const Camera& c, uint32_t x, uint32_t y) {
    const glm::vec3 d = rayThrough(c, x, y);
    if (d.y >= 0.0f) return {};
    const glm::vec3 q = c.position + d * ((kFloorY - c.position.y) / d.y);
    if (q.z < -60.0f || std::abs(q.x) > 50.0f) return {};
    return {true, q, 0};
}

inline float toHalf(float v) { return glm::unpackHalf1x16(glm::packHalf1x16(v)); }
inline glm::vec4 toHalf(glm::vec4 v) { return {toHalf(v.x), toHalf(v.y), toHalf(v.z), toHalf(v.w)}; }

// One frame's inputs as the pass sees them (half values already rounded).
struct Frame {
    std::vector<float> depth;        // D32
    std::vector<glm::vec4> normal;   // G-buffer normal (RGBA16F)
    std::vector<glm::vec4> diffuse;  // this frame's term (RGBA16F), a = AO
    std::vector<int> surface;        // which surface each pixel sees (-1: none), for the tests
    glm::mat4 viewProj{1.0f};
};

// The frame a camera sees of whatever `cast` hits, every surface facing `normal`.
template <typename Cast>
inline Frame makeFrameOf(const Camera& c, const Cast& cast, glm::vec3 normal) {
    Frame f;
    f.viewProj = c.viewProj();
    const size_t n = size_t(kW) * kH;
    f.depth.assign(n, 1.0f);
    f.normal.assign(n, glm::vec4(0.0f));
    f.diffuse.assign(n, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    f.surface.assign(n, -1);
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) {
            const Hit h = cast(x, y);
            if (!h.found) continue;
            const glm::vec4 clip = f.viewProj * glm::vec4(h.point, 1.0f);
            const size_t i = size_t(y) * kW + x;
            f.depth[i] = clip.z / clip.w;
            f.normal[i] = toHalf(glm::vec4(normal, 1.0f));
            f.surface[i] = h.surface;
        }
    return f;
}

inline Frame makeFrame(const Scene& s, const Camera& c) {
    return makeFrameOf(c, [&](uint32_t x, uint32_t y) { return castPixel(s, c, x, y); }, glm::vec3(0, 0, 1));
}

inline Frame makeFloorFrame(const Camera& c) {
    return makeFrameOf(c, [&](uint32_t x, uint32_t y) { return castFloor(c, x, y); }, glm::vec3(0, 1, 0));
}

// The world point frame f saw at pixel (x, y), rebuilt from its depth in float
// as the pass rebuilds it (the pixel must hold geometry).
inline glm::vec3 pointAt(const Frame& f, uint32_t x, uint32_t y) {
    const glm::vec2 ndc((x + 0.5f) / kW * 2.0f - 1.0f, (y + 0.5f) / kH * 2.0f - 1.0f);
    const glm::vec4 w = glm::inverse(f.viewProj) * glm::vec4(ndc, f.depth[size_t(y) * kW + x], 1.0f);
    return glm::vec3(w) / w.w;
}

struct Outputs {
    std::vector<glm::vec4> diffuse, history, surface;
};

inline std::vector<glm::vec4> halfTexels(const std::vector<uint8_t>& bytes) {
    std::vector<glm::vec4> out(bytes.size() / 8);
    for (size_t i = 0; i < out.size(); ++i)
        for (int c = 0; c < 4; ++c) {
            uint16_t h;
            std::memcpy(&h, bytes.data() + 8 * i + 2 * c, 2);
            out[i][c] = glm::unpackHalf1x16(h);
        }
    return out;
}

inline std::vector<uint16_t> packHalf(const std::vector<glm::vec4>& v) {
    std::vector<uint16_t> out;
    for (const glm::vec4& t : v)
        for (int c = 0; c < 4; ++c) out.push_back(glm::packHalf1x16(t[c]));
    return out;
}

// The pass's images outside a Renderer, one frame at a time.
class Harness {
public:
    Harness()
        : frame_(context(), sizeof(sh::FrameConstants),
                 VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Device,
                 "frame constants"),
          samplers_(render::createSamplers(context())),
          pass_(context()) {
        const VkImageUsageFlags io = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        g_.normal = image(VK_FORMAT_R16G16B16A16_SFLOAT, VK_IMAGE_USAGE_SAMPLED_BIT | io, "normal");
        g_.depth = image(VK_FORMAT_D32_SFLOAT, VK_IMAGE_USAGE_SAMPLED_BIT | io, "depth");
        diffuse_ = image(VK_FORMAT_R16G16B16A16_SFLOAT, VK_IMAGE_USAGE_STORAGE_BIT | io, "diffuse");
        for (int i = 0; i < 2; ++i) {
            history_[i] = image(VK_FORMAT_R32G32B32A32_SFLOAT, VK_IMAGE_USAGE_STORAGE_BIT | io, "history");
            surface_[i] = image(VK_FORMAT_R16G16B16A16_SFLOAT, VK_IMAGE_USAGE_STORAGE_BIT | io, "surface");
        }
    }

    // Replaces the history the next frame reads (for the CPU comparison), as
    // one that holds `frames` frames.
    void setHistory(const std::vector<glm::vec4>& color, const std::vector<glm::vec4>& surface,
                    const glm::mat4& viewProj, uint32_t frames) {
        const int p = int(state_.previous);
        gpu::uploadImage(context(), history_[p], color.data(), color.size() * sizeof(glm::vec4),
                         gpu::use::ComputeRead);
        tracker_.assume(history_[p], gpu::use::ComputeRead);
        const std::vector<uint16_t> s = packHalf(surface);
        gpu::uploadImage(context(), surface_[p], s.data(), s.size() * 2, gpu::use::ComputeRead);
        tracker_.assume(surface_[p], gpu::use::ComputeRead);
        state_.valid = true;
        state_.frames = frames;
        state_.previousViewProj = viewProj;
    }

    void resetHistory() { state_.reset(); }
    // Whether the pass is told that the voxel light still climbs (the
    // running mean after a restart, render::temporalBlendWeight).
    void setLightClimbs(bool climbs) { lightClimbs_ = climbs; }

    Outputs run(const Frame& f, float minAlpha) {
        sh::FrameConstants fc{};
        fc.viewProj = f.viewProj;
        fc.invViewProj = glm::inverse(f.viewProj);
        fc.sizes = glm::uvec4(kW, kH, 0, 0);
        gpu::uploadBuffer(context(), frame_, &fc, sizeof(fc));
        upload(g_.depth, f.depth.data(), f.depth.size() * 4, gpu::use::DepthRead);
        const std::vector<uint16_t> n = packHalf(f.normal), d = packHalf(f.diffuse);
        upload(g_.normal, n.data(), n.size() * 2, gpu::use::ShaderRead);
        upload(diffuse_, d.data(), d.size() * 2, gpu::use::ComputeReadWrite);
        const int p = int(state_.previous);
        const render::TemporalIndirectInputs in{g_, samplers_, frame_, history_[p], surface_[p],
                                                state_.previousViewProj, state_.valid, state_.frames,
                                                lightClimbs_};
        const render::TemporalIndirectTargets out{diffuse_, history_[1 - p], surface_[1 - p]};
        render::TemporalSettings s;
        s.minAlpha = minAlpha;
        context().submitAndWait([&](VkCommandBuffer cmd) { pass_.record(cmd, tracker_, in, out, s, nullptr); });
        state_.advance(f.viewProj);
        Outputs o;
        o.diffuse = halfTexels(gpu::readbackImage(context(), diffuse_, gpu::use::ComputeReadWrite));
        const std::vector<uint8_t> h = gpu::readbackImage(context(), history_[1 - p], gpu::use::ComputeWrite);
        o.history.resize(h.size() / sizeof(glm::vec4));
        std::memcpy(o.history.data(), h.data(), h.size());
        o.surface = halfTexels(gpu::readbackImage(context(), surface_[1 - p], gpu::use::ComputeWrite));
        return o;
    }

private:
    gpu::Image image(VkFormat format, VkImageUsageFlags usage, const char* name) {
        gpu::ImageDesc d;
        d.format = format;
        d.extent = {kW, kH, 1};
        d.usage = usage;
        d.name = name;
        return gpu::Image(context(), d);
    }
    void upload(const gpu::Image& img, const void* data, size_t bytes, gpu::ImageUse use) {
        gpu::uploadImage(context(), img, data, bytes, use);
        tracker_.assume(img, use);
    }

    gpu::Buffer frame_;
    render::Samplers samplers_;
    render::TemporalIndirectPass pass_;
    render::GBuffer g_;
    gpu::Image diffuse_, history_[2], surface_[2];
    gpu::Tracker tracker_;
    render::TemporalState state_;
    bool lightClimbs_ = true;  // the tests of the running mean; setLightClimbs(false) for a settled light
};

inline bool close(float gpu, float ref, double relative) {
    return std::abs(double(gpu) - double(ref)) <= relative * std::max(std::abs(double(ref)), 1e-3);
}

// Each pixel's term: `wall` on the wall, `quad` on the quad.
inline void fill(Frame& fr, float wall, float quad) {
    for (size_t i = 0; i < fr.diffuse.size(); ++i)
        if (fr.surface[i] >= 0) fr.diffuse[i] = glm::vec4(fr.surface[i] == 0 ? wall : quad, 0.0f, 0.0f, 1.0f);
}

// Whether pixel (x, y)'s 3x3 neighbourhood sees one surface in frame f and
// one in frame g (so bilinear taps never straddle an edge).
inline bool sameSurfaceAround(const Frame& f, const Frame& g, uint32_t x, uint32_t y) {
    const size_t i = size_t(y) * kW + x;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const size_t j = size_t(int(y) + dy) * kW + size_t(int(x) + dx);
            if (f.surface[j] != f.surface[i] || g.surface[j] != g.surface[i]) return false;
        }
    return true;
}

class TemporalIndirect : public GpuTest {};

}  // namespace dvsgi::test::temporal
