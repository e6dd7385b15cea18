// The temporal accumulation pass (render/temporal_indirect.h) alone, on
// synthetic frames: a wall and a floating quad seen by two cameras, their depth
// and normals written analytically into a G-buffer, with made-up indirect
// terms and histories (and a floor seen at grazing angles). Checks the pass
// texel by texel against a CPU model of it, the running average under a still
// camera, that disoccluded pixels take no history and that a grazing floor
// keeps it.
#include <cmath>
#include <cstdio>
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

namespace dvsgi::test {
namespace {

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
glm::vec3 rayThrough(const Camera& c, uint32_t x, uint32_t y) {
    const glm::mat4 inv = glm::inverse(c.viewProj());
    const glm::vec2 ndc((float(x) + 0.5f) / kW * 2.0f - 1.0f, (float(y) + 0.5f) / kH * 2.0f - 1.0f);
    const glm::vec4 far = inv * glm::vec4(ndc, 1.0f, 1.0f);
    return glm::normalize(glm::vec3(far) / far.w - c.position);
}

Hit castPixel(const Scene& s, const Camera& c, uint32_t x, uint32_t y) {
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

Hit castFloor(const Camera& c, uint32_t x, uint32_t y) {
    const glm::vec3 d = rayThrough(c, x, y);
    if (d.y >= 0.0f) return {};
    const glm::vec3 q = c.position + d * ((kFloorY - c.position.y) / d.y);
    if (q.z < -60.0f || std::abs(q.x) > 50.0f) return {};
    return {true, q, 0};
}

float toHalf(float v) { return glm::unpackHalf1x16(glm::packHalf1x16(v)); }
glm::vec4 toHalf(glm::vec4 v) { return {toHalf(v.x), toHalf(v.y), toHalf(v.z), toHalf(v.w)}; }

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
Frame makeFrameOf(const Camera& c, const Cast& cast, glm::vec3 normal) {
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

Frame makeFrame(const Scene& s, const Camera& c) {
    return makeFrameOf(c, [&](uint32_t x, uint32_t y) { return castPixel(s, c, x, y); }, glm::vec3(0, 0, 1));
}

Frame makeFloorFrame(const Camera& c) {
    return makeFrameOf(c, [&](uint32_t x, uint32_t y) { return castFloor(c, x, y); }, glm::vec3(0, 1, 0));
}

struct Outputs {
    std::vector<glm::vec4> diffuse, history, surface;
};

std::vector<glm::vec4> halfTexels(const std::vector<uint8_t>& bytes) {
    std::vector<glm::vec4> out(bytes.size() / 8);
    for (size_t i = 0; i < out.size(); ++i)
        for (int c = 0; c < 4; ++c) {
            uint16_t h;
            std::memcpy(&h, bytes.data() + 8 * i + 2 * c, 2);
            out[i][c] = glm::unpackHalf1x16(h);
        }
    return out;
}

std::vector<uint16_t> packHalf(const std::vector<glm::vec4>& v) {
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
                                                state_.previousViewProj, state_.valid, state_.frames};
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
};

// The world point a camera `viewProj` saw at pixel t at view depth (clip w) `viewDepth`.
glm::dvec3 pointSeen(const glm::dmat4& invViewProj, const glm::dmat4& viewProj, glm::ivec2 t, double viewDepth) {
    const glm::dvec2 ndc((t.x + 0.5) / kW * 2.0 - 1.0, (t.y + 0.5) / kH * 2.0 - 1.0);
    const glm::dvec4 nearH = invViewProj * glm::dvec4(ndc, 0.0, 1.0), farH = invViewProj * glm::dvec4(ndc, 1.0, 1.0);
    const glm::dvec3 a = glm::dvec3(nearH) / nearH.w, b = glm::dvec3(farH) / farH.w;
    const double wa = (viewProj * glm::dvec4(a, 1.0)).w, wb = (viewProj * glm::dvec4(b, 1.0)).w;
    return a + (b - a) * ((viewDepth - wa) / (wb - wa));
}

// The CPU model of temporal_indirect.comp, in double precision, for a frame
// whose blend weight is `alpha`. kind: 0 no geometry, 1 no history (off
// screen or reset), 2 every history texel rejected, 3 blended. marginal:
// within rounding of a decision.
struct Reference {
    Outputs out;
    std::vector<int> kind;
    std::vector<bool> marginal;
};

Reference reference(const Frame& f, const std::vector<glm::vec4>& history, const std::vector<glm::vec4>& surface,
                    const glm::mat4& prevViewProj, double alpha) {
    const size_t n = size_t(kW) * kH;
    Reference r;
    r.out.diffuse = f.diffuse;
    r.out.history.assign(n, glm::vec4(0.0f));
    r.out.surface.assign(n, glm::vec4(0.0f));
    r.kind.assign(n, 0);
    r.marginal.assign(n, false);
    // The matrices the GPU gets (the inverse computed in float, as uploaded).
    const glm::dmat4 inv(glm::inverse(f.viewProj)), vp(f.viewProj), prev(prevViewProj);
    const glm::dmat4 prevInv = glm::inverse(prev);
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) {
            const size_t i = size_t(y) * kW + x;
            if (f.depth[i] >= 1.0f) continue;
            const glm::dvec2 ndc((x + 0.5) / kW * 2.0 - 1.0, (y + 0.5) / kH * 2.0 - 1.0);
            const glm::dvec4 w = inv * glm::dvec4(ndc, f.depth[i], 1.0);
            const glm::dvec4 p(glm::dvec3(w) / w.w, 1.0);
            const glm::dvec3 nrm = glm::normalize(glm::dvec3(f.normal[i]));
            r.out.surface[i] = glm::vec4(glm::vec3(nrm), float((vp * p).w));
            const glm::vec4 cur = f.diffuse[i];
            r.kind[i] = 1;
            r.out.history[i] = glm::vec4(glm::vec3(cur), 1.0f);
            const glm::dvec4 clip = prev * p;
            if (clip.w <= 0.0) continue;
            const glm::dvec2 q = (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * glm::dvec2(kW, kH);
            const double edge = std::min({q.x, q.y, kW - q.x, kH - q.y});
            r.marginal[i] = std::abs(edge) < 1e-3;
            if (edge < 0.0 || q.x >= kW || q.y >= kH) continue;
            const glm::dvec2 b = q - 0.5;
            const glm::ivec2 b0 = glm::ivec2(glm::floor(b));
            glm::dvec2 fr = b - glm::dvec2(b0);
            for (int c = 0; c < 2; ++c) {
                const double off = std::abs(fr[c] - std::round(fr[c]));
                if (std::abs(off - sh::TEMPORAL_SNAP) < 1e-5) r.marginal[i] = true;
                if (off < sh::TEMPORAL_SNAP) fr[c] = std::round(fr[c]);
            }
            glm::dvec3 sum(0.0);
            double count = 0.0, weight = 0.0;
            for (int j = 0; j < 2; ++j)
                for (int k = 0; k < 2; ++k) {
                    const glm::ivec2 t = b0 + glm::ivec2(k, j);
                    const double bw = (k == 0 ? 1.0 - fr.x : fr.x) * (j == 0 ? 1.0 - fr.y : fr.y);
                    if (bw <= 0.0 || t.x < 0 || t.y < 0 || t.x >= int(kW) || t.y >= int(kH)) continue;
                    const size_t ti = size_t(t.y) * kW + size_t(t.x);
                    const glm::dvec4 s(surface[ti]);
                    // How far off this pixel's tangent plane the point last frame saw at the tap lies.
                    const double dz = std::abs(glm::dot(pointSeen(prevInv, prev, t, s.w) - glm::dvec3(p), nrm)) / clip.w;
                    const double cosine = glm::dot(glm::dvec3(s), nrm);
                    if (s.w > 0.0 && (std::abs(dz - sh::TEMPORAL_DEPTH_TOLERANCE) < 1e-4 ||
                                      std::abs(cosine - sh::TEMPORAL_NORMAL_COSINE) < 1e-4))
                        r.marginal[i] = true;
                    if (s.w <= 0.0 || dz > sh::TEMPORAL_DEPTH_TOLERANCE || cosine < sh::TEMPORAL_NORMAL_COSINE)
                        continue;
                    const glm::dvec4 h(history[ti]);
                    if (h.a < 1.0 || !std::isfinite(h.r) || !std::isfinite(h.g) || !std::isfinite(h.b)) continue;
                    sum += bw * glm::dvec3(h);
                    count += bw * h.a;
                    weight += bw;
                }
            if (std::abs(weight - 1e-4) < 1e-5) r.marginal[i] = true;
            if (weight <= 1e-4) {
                r.kind[i] = 2;
                continue;
            }
            r.kind[i] = 3;
            const double samples = count / weight;
            const glm::dvec3 history = sum / weight;
            const glm::dvec3 result = history + alpha * (glm::dvec3(cur) - history);
            r.out.history[i] = glm::vec4(glm::vec3(result), float(std::min(samples + 1.0, 255.0)));
            r.out.diffuse[i] = glm::vec4(glm::vec3(result), cur.a);
        }
    return r;
}

bool close(float gpu, float ref, double relative) {
    return std::abs(double(gpu) - double(ref)) <= relative * std::max(std::abs(double(ref)), 1e-3);
}

// Each pixel's term: `wall` on the wall, `quad` on the quad.
void fill(Frame& fr, float wall, float quad) {
    for (size_t i = 0; i < fr.diffuse.size(); ++i)
        if (fr.surface[i] >= 0) fr.diffuse[i] = glm::vec4(fr.surface[i] == 0 ? wall : quad, 0.0f, 0.0f, 1.0f);
}

// Whether pixel (x, y)'s 3x3 neighbourhood sees one surface in frame f and
// one in frame g (so bilinear taps never straddle an edge).
bool sameSurfaceAround(const Frame& f, const Frame& g, uint32_t x, uint32_t y) {
    const size_t i = size_t(y) * kW + x;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const size_t j = size_t(int(y) + dy) * kW + size_t(int(x) + dx);
            if (f.surface[j] != f.surface[i] || g.surface[j] != g.surface[i]) return false;
        }
    return true;
}

class TemporalIndirect : public GpuTest {};

// A texel-by-texel comparison with the CPU model: the camera moves sideways
// and back (parallax at the quad's edges, a strip off screen), some history
// texels are empty (count 0) or not finite, and a patch of the stored
// normals is turned by 37 degrees.
TEST_F(TemporalIndirect, MatchesTheCpuModel) {
    const Scene scene;
    const Camera previous{{0.0f, 0.0f, 5.3f}}, current{{0.8f, 0.1f, 5.0f}};
    const Frame before = makeFrame(scene, previous);
    Frame now = makeFrame(scene, current);
    const size_t n = size_t(kW) * kH;
    std::vector<glm::vec4> history(n), surface(n, glm::vec4(0.0f));
    const float counts[6] = {0.0f, 1.0f, 2.0f, 4.0f, 9.0f, 40.0f};
    const glm::mat4 prevVp = previous.viewProj(), prevInv = glm::inverse(prevVp);
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) {
            const size_t i = size_t(y) * kW + x;
            // Smooth over the image: the GPU's float reprojection lands up to
            // about 2e-4 pixel away from the model's double one (measured:
            // the sample counts, which jump from block to block, then differ
            // by up to 6.5e-4 relative; colours by less).
            const float v = 1.0f + 0.5f * std::sin(0.3f * float(x)) * std::cos(0.2f * float(y));
            history[i] = glm::vec4(v, 0.5f * v, 2.0f - 0.7f * v, counts[(x / 7 + y / 5) % 6]);
            if ((x * 13 + y * 7) % 211 == 0) history[i].g = std::nanf("");
            now.diffuse[i] = toHalf(glm::vec4(float((x * 53 + y * 29) % 89) / 22.0f, 0.3f, float(y % 9) / 3.0f,
                                              float(x % 11) / 10.0f));
            if (before.depth[i] >= 1.0f) continue;
            // Last frame's view depth, as the pass stores it.
            const glm::vec2 ndc((x + 0.5f) / kW * 2.0f - 1.0f, (y + 0.5f) / kH * 2.0f - 1.0f);
            const glm::vec4 w = prevInv * glm::vec4(ndc, before.depth[i], 1.0f);
            const float depth = (prevVp * glm::vec4(glm::vec3(w) / w.w, 1.0f)).w;
            const bool turned = x >= 60 && x < 72 && y >= 36 && y < 48;
            surface[i] = toHalf(turned ? glm::vec4(0.6f, 0.0f, 0.8f, depth) : glm::vec4(0.0f, 0.0f, 1.0f, depth));
        }

    Harness h;
    // A history of three frames: this frame weighs 1/4 (above alphaMin), and
    // the texels' own counts (0 marks an empty one) no longer change it.
    h.setHistory(history, surface, prevVp, 3);
    const Outputs gpu = h.run(now, 0.1f);
    const Reference ref = reference(now, history, surface, prevVp, render::temporalBlendWeight(0.1f, 3));

    int kinds[4] = {0, 0, 0, 0}, marginal = 0, wrong = 0;
    double worst = 0.0;  // largest relative difference of the history
    for (size_t i = 0; i < n; ++i) {
        ++kinds[ref.kind[i]];
        if (ref.marginal[i]) {
            ++marginal;
            continue;
        }
        bool ok = true;
        for (int c = 0; c < 4; ++c) {
            // Diffuse is RGBA16F: the GPU and the model may round to neighbouring halves.
            ok &= close(gpu.diffuse[i][c], ref.out.diffuse[i][c], 1.5e-3);
            ok &= close(gpu.history[i][c], ref.out.history[i][c], 1e-3);
            worst = std::max(worst, std::abs(double(gpu.history[i][c]) - ref.out.history[i][c]) /
                                        std::max(std::abs(double(ref.out.history[i][c])), 1e-3));
            ok &= close(gpu.surface[i][c], ref.out.surface[i][c], 1.5e-3);
        }
        // Where no history was taken the term is left exactly as it was.
        if (ref.kind[i] < 3) ok &= std::memcmp(&gpu.diffuse[i], &now.diffuse[i], sizeof(glm::vec4)) == 0;
        if (!ok && ++wrong <= 5) {
            const glm::vec4 a = gpu.diffuse[i], b = ref.out.diffuse[i], ha = gpu.history[i], hb = ref.out.history[i];
            std::printf("  texel (%zu, %zu) kind %d: diffuse %g %g %g / %g %g %g, history %g %g %g %g / %g %g %g %g\n",
                        i % kW, i / kW, ref.kind[i], a.r, a.g, a.b, b.r, b.g, b.b, ha.r, ha.g, ha.b, ha.a, hb.r, hb.g,
                        hb.b, hb.a);
        }
    }
    std::printf("  %d background, %d without history (off screen), %d with every history texel rejected, %d "
                "blended; %d within rounding of a decision (not compared); %d differ; history within %.1e\n",
                kinds[0], kinds[1], kinds[2], kinds[3], marginal, wrong, worst);
    EXPECT_EQ(wrong, 0);
    EXPECT_LT(marginal, 20);
    EXPECT_GT(kinds[0], 200);
    EXPECT_GT(kinds[1], 100);
    EXPECT_GT(kinds[2], 300);
    EXPECT_GT(kinds[3], 2000);
}

// Under a still camera the output after k frames is the mean of the k terms
// while 1/k >= alphaMin, then an exponential average with weight alphaMin.
TEST_F(TemporalIndirect, StillCameraGivesTheRunningAverage) {
    constexpr float kMinAlpha = 0.1f;
    constexpr int kFrames = 16;
    const Scene scene;
    const Camera camera{{0.1f, 0.0f, 5.0f}};
    Frame f = makeFrame(scene, camera);
    const size_t n = size_t(kW) * kH;
    std::vector<glm::dvec3> mean(n, glm::dvec3(0.0)), average(n, glm::dvec3(0.0));
    Harness h;
    double worstMean = 0.0, worstAverage = 0.0;
    for (int k = 1; k <= kFrames; ++k) {
        for (size_t i = 0; i < n; ++i)
            f.diffuse[i] = toHalf(glm::vec4(1.0f + 0.8f * std::sin(1.3f * k + 0.1f * float(i % kW)),
                                            0.5f + 0.4f * std::cos(0.7f * k * k + float(i / kW)), 0.25f * (k % 3),
                                            0.5f));
        const Outputs o = h.run(f, kMinAlpha);
        const double alpha = std::max(1.0 / k, double(kMinAlpha));
        for (size_t i = 0; i < n; ++i) {
            if (f.depth[i] >= 1.0f) continue;
            const glm::dvec3 c(f.diffuse[i]);
            mean[i] += (c - mean[i]) / double(k);  // the plain mean of frames 1..k
            average[i] += alpha * (c - average[i]);
            for (int ch = 0; ch < 3; ++ch) {
                const double got = o.diffuse[i][ch];
                const double scale = std::max(std::abs(average[i][ch]), 0.05);
                worstAverage = std::max(worstAverage, std::abs(got - average[i][ch]) / scale);
                if (alpha * k == 1.0) worstMean = std::max(worstMean, std::abs(got - mean[i][ch]) / scale);
            }
            ASSERT_EQ(o.diffuse[i].a, f.diffuse[i].a);
            ASSERT_NEAR(o.history[i].a, std::min(double(k), 255.0), 1e-3) << "frame " << k;
        }
    }
    std::printf("  %d frames, alphaMin %.2f: largest relative difference to the running mean (frames 1-%d) %.2e, "
                "to the running average %.2e\n",
                kFrames, kMinAlpha, int(1.0f / kMinAlpha), worstMean, worstAverage);
    // Measured on lavapipe: both below 1e-3 (half rounding of the output).
    EXPECT_LT(worstMean, 2e-3);
    EXPECT_LT(worstAverage, 2e-3);
}

// The quad moves sideways between frames under a still camera: wall pixels it
// uncovered and pixels it newly covers take this frame's term alone; pixels
// that saw the same surface blend.
TEST_F(TemporalIndirect, DisocclusionRejectsHistory) {
    constexpr int kBefore = 5;
    const Camera camera{{0.0f, 0.0f, 5.0f}};
    const Scene a{-0.9f, 0.0f}, b{-0.4f, 0.5f};
    Harness h;
    Frame f = makeFrame(a, camera);
    fill(f, 1.0f, 10.0f);
    for (int k = 0; k < kBefore; ++k) h.run(f, 0.1f);
    Frame g = makeFrame(b, camera);
    fill(g, 2.0f, 20.0f);
    const Outputs o = h.run(g, 0.1f);
    const float alpha = 1.0f / (kBefore + 1);
    int counts[4] = {0, 0, 0, 0}, bad = 0;
    for (uint32_t y = 1; y + 1 < kH; ++y)
        for (uint32_t x = 1; x + 1 < kW; ++x) {
            // Pixels whose 3x3 neighbourhood sees one surface in both frames.
            const size_t i = size_t(y) * kW + x;
            if (!sameSurfaceAround(f, g, x, y) || g.surface[i] < 0) continue;
            const int was = f.surface[i], is = g.surface[i];
            const float cur = g.diffuse[i].r, old = f.diffuse[i].r;
            const float expected = was == is ? old + alpha * (cur - old) : cur;
            const int kind = (was == 0 ? 0 : 2) + (is == 0 ? 0 : 1);  // wall->wall, wall->quad, quad->wall, quad->quad
            ++counts[kind];
            if (!close(o.diffuse[i].r, expected, 1.5e-3) && ++bad <= 5)
                std::printf("  (%u, %u) kind %d: %g, expected %g\n", x, y, kind, o.diffuse[i].r, expected);
        }
    std::printf("  wall kept %d, newly covered %d, uncovered %d, quad kept %d pixels; %d wrong\n", counts[0],
                counts[1], counts[2], counts[3], bad);
    EXPECT_EQ(bad, 0);
    for (int c : counts) EXPECT_GT(c, 50);
}

// One blend weight for the whole frame: four frames in, the quad moves,
// uncovering part of the wall and covering another part; on the next frame
// the history holds five frames, and every pixel that saw the same surface
// last frame moves 1/6 of the way to the new term (the running mean of the
// frames since the history started), those just uncovered or covered too,
// whose own history holds one frame (weighing a pixel's own frames moved
// them half way: the flicker of newly visible surfaces), and not alphaMin.
TEST_F(TemporalIndirect, NewlyVisiblePixelsBlendAtTheFramesWeight) {
    constexpr int kBefore = 4;
    constexpr float kMinAlpha = 0.1f;
    const float alpha = render::temporalBlendWeight(kMinAlpha, kBefore + 1);
    ASSERT_FLOAT_EQ(alpha, 1.0f / 6.0f);
    const Camera camera{{0.0f, 0.0f, 5.0f}};
    const Scene a{-0.9f, 0.0f}, b{-0.4f, 0.5f};
    Harness h;
    Frame f = makeFrame(a, camera);
    fill(f, 1.0f, 10.0f);
    for (int k = 0; k < kBefore; ++k) h.run(f, kMinAlpha);
    Frame g = makeFrame(b, camera);
    fill(g, 2.0f, 20.0f);
    const Outputs moved = h.run(g, kMinAlpha);
    fill(g, 3.0f, 30.0f);
    const Outputs next = h.run(g, kMinAlpha);
    int uncovered = 0, covered = 0, kept = 0, bad = 0;
    for (uint32_t y = 1; y + 1 < kH; ++y)
        for (uint32_t x = 1; x + 1 < kW; ++x) {
            const size_t i = size_t(y) * kW + x;
            if (!sameSurfaceAround(f, g, x, y) || g.surface[i] < 0) continue;
            const float old = moved.diffuse[i].r, cur = g.diffuse[i].r;
            const float expected = old + alpha * (cur - old);
            if (f.surface[i] == g.surface[i]) ++kept;
            else if (g.surface[i] == 0) ++uncovered;
            else ++covered;
            if (!close(next.diffuse[i].r, expected, 1.5e-3) && ++bad <= 5)
                std::printf("  (%u, %u): %g, expected %g (last frame %g)\n", x, y, next.diffuse[i].r, expected, old);
        }
    std::printf("  uncovered %d, newly covered %d, kept %d pixels; %d wrong\n", uncovered, covered, kept, bad);
    EXPECT_EQ(bad, 0);
    EXPECT_GT(uncovered, 50);
    EXPECT_GT(covered, 50);
    EXPECT_GT(kept, 500);
}

// A floor seen at a grazing angle by a camera that walks forward: near the
// horizon the view depths of vertically neighbouring pixels differ by far more
// than the tolerance, yet every floor pixel that last frame saw takes its
// history, because a tap counts as the same surface when its point lies on
// the pixel's tangent plane. (Comparing each tap's depth with the point's
// rejected whole rows there, which then showed the raw gather.)
TEST_F(TemporalIndirect, GrazingFloorKeepsItsHistory) {
    constexpr int kBefore = 4;
    constexpr float kMinAlpha = 0.1f;
    const float alpha = render::temporalBlendWeight(kMinAlpha, kBefore);
    const Camera previous{{0.0f, 0.0f, 0.0f}}, current{{0.0f, 0.0f, -0.05f}};
    Frame f = makeFloorFrame(previous);
    fill(f, 1.0f, 0.0f);
    Harness h;
    for (int k = 0; k < kBefore; ++k) h.run(f, kMinAlpha);
    Frame g = makeFloorFrame(current);
    fill(g, 2.0f, 0.0f);
    const Outputs o = h.run(g, kMinAlpha);
    const glm::mat4 prevVp = previous.viewProj(), inv = glm::inverse(g.viewProj);
    int checked = 0, grazing = 0, bad = 0;
    for (uint32_t y = 1; y + 1 < kH; ++y)
        for (uint32_t x = 1; x + 1 < kW; ++x) {
            const size_t i = size_t(y) * kW + x;
            if (!sameSurfaceAround(f, g, x, y) || g.surface[i] < 0) continue;
            // Where last frame's camera saw this pixel's point: on screen, and
            // how much the view depth changes from one row to the next there.
            const glm::vec2 ndc((x + 0.5f) / kW * 2.0f - 1.0f, (y + 0.5f) / kH * 2.0f - 1.0f);
            const glm::vec4 w = inv * glm::vec4(ndc, g.depth[i], 1.0f);
            const glm::vec4 clip = prevVp * glm::vec4(glm::vec3(w) / w.w, 1.0f);
            const glm::vec2 q = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(kW, kH);
            if (q.x < 1.0f || q.y < 1.0f || q.x > kW - 1.0f || q.y > kH - 1.0f) continue;
            ++checked;
            const float below = (prevVp * glm::vec4(castFloor(previous, uint32_t(q.x), uint32_t(q.y) + 1).point, 1.0f)).w;
            if (std::abs(below - clip.w) > 2.0f * sh::TEMPORAL_DEPTH_TOLERANCE * clip.w) ++grazing;
            const float expected = 1.0f + alpha * (2.0f - 1.0f);
            if (!close(o.diffuse[i].r, expected, 1.5e-3) && ++bad <= 5)
                std::printf("  (%u, %u): %g, expected %g\n", x, y, o.diffuse[i].r, expected);
        }
    std::printf("  %d floor pixels checked, %d where the next row's view depth differs by more than twice the "
                "tolerance; %d wrong\n", checked, grazing, bad);
    EXPECT_EQ(bad, 0);
    EXPECT_GT(checked, 1000);
    EXPECT_GT(grazing, 200);
}

// The frame count behind the weight: a hold of three frames restarts it, and
// the first frame after the hold weighs 1/2, the next 1/3.
TEST(TemporalState, HistoryFramesRestartAfterAHold) {
    render::TemporalState s;
    const glm::mat4 vp(1.0f);
    for (int k = 0; k < 30; ++k) {
        s.beginFrame();
        s.advance(vp);
    }
    EXPECT_TRUE(s.valid);
    EXPECT_EQ(s.frames, 30u);
    s.drop(3);
    for (int k = 0; k < 3; ++k) {
        s.beginFrame();
        EXPECT_FALSE(s.valid) << "held frame " << k;
        s.advance(vp);
        EXPECT_EQ(s.frames, 1u);
    }
    s.beginFrame();
    ASSERT_TRUE(s.valid);
    EXPECT_FLOAT_EQ(render::temporalBlendWeight(0.05f, s.frames), 0.5f);
    s.advance(vp);
    s.beginFrame();
    EXPECT_FLOAT_EQ(render::temporalBlendWeight(0.05f, s.frames), 1.0f / 3.0f);
    for (int k = 0; k < 100; ++k) {
        s.advance(vp);
        s.beginFrame();
    }
    EXPECT_FLOAT_EQ(render::temporalBlendWeight(0.05f, s.frames), 0.05f);
}

}  // namespace
}  // namespace dvsgi::test
