// limitTextureSize: shrinks textures the device cannot hold. A valid image
// wider than maxImageDimension2D (e.g. a 70000x1 PNG) otherwise reaches
// vkCreateImage and takes the driver down.
#include <algorithm>
#include <array>
#include <cmath>

#include "scene/scene.h"

namespace dvsgi::scene {

namespace {

const std::array<float, 256>& srgbToLinearTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) {
            float c = i / 255.0f;
            t[i] = c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
        }
        return t;
    }();
    return table;
}

uint8_t linearToSrgb8(float v) {
    v = std::clamp(v, 0.0f, 1.0f);
    float c = v <= 0.0031308f ? v * 12.92f : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
    return static_cast<uint8_t>(std::lround(c * 255.0f));
}

// Source texel range [begin, end) that destination texel `d` of `dstSize`
// covers; never empty, so every destination texel averages something.
std::pair<uint32_t, uint32_t> span(uint32_t d, uint32_t dstSize, uint32_t srcSize) {
    uint32_t b = static_cast<uint32_t>(uint64_t(d) * srcSize / dstSize);
    uint32_t e = static_cast<uint32_t>(uint64_t(d + 1) * srcSize / dstSize);
    return {b, std::max(e, b + 1)};
}

// Box filter: each destination texel is the mean of the source texels it
// covers. Colour channels of sRGB textures are averaged in linear light so
// bright and dark texels mix as they would on screen; alpha is linear.
Texture boxDownsample(const Texture& src, uint32_t w, uint32_t h) {
    const auto& lut = srgbToLinearTable();
    Texture out;
    out.name = src.name;
    out.srgb = src.srgb;
    out.width = w;
    out.height = h;
    out.rgba8.resize(size_t(w) * h * 4);
    for (uint32_t y = 0; y < h; ++y) {
        auto [y0, y1] = span(y, h, src.height);
        for (uint32_t x = 0; x < w; ++x) {
            auto [x0, x1] = span(x, w, src.width);
            double acc[4] = {0, 0, 0, 0};
            for (uint32_t sy = y0; sy < y1; ++sy) {
                const uint8_t* row = &src.rgba8[(size_t(sy) * src.width + x0) * 4];
                for (uint32_t sx = x0; sx < x1; ++sx, row += 4) {
                    for (int k = 0; k < 3; ++k) acc[k] += src.srgb ? lut[row[k]] : row[k] / 255.0f;
                    acc[3] += row[3] / 255.0f;
                }
            }
            const double n = double(y1 - y0) * double(x1 - x0);
            uint8_t* dst = &out.rgba8[(size_t(y) * w + x) * 4];
            for (int k = 0; k < 3; ++k) {
                float v = static_cast<float>(acc[k] / n);
                dst[k] = src.srgb ? linearToSrgb8(v) : static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
            }
            dst[3] = static_cast<uint8_t>(std::lround(std::clamp(acc[3] / n, 0.0, 1.0) * 255.0));
        }
    }
    return out;
}

}  // namespace

void limitTextureSize(Scene& scene, uint32_t maxDim, std::vector<std::string>* warnings) {
    if (maxDim == 0) return;
    for (Texture& t : scene.textures) {
        if (t.width <= maxDim && t.height <= maxDim) continue;
        if (t.rgba8.size() != size_t(t.width) * t.height * 4) continue;  // not decoded data; nothing to filter
        // One scale for both axes keeps the aspect ratio; each side keeps at
        // least one texel (a 70000x1 strip stays one texel tall).
        const double s = double(maxDim) / double(std::max(t.width, t.height));
        const uint32_t w = std::clamp<uint32_t>(static_cast<uint32_t>(std::lround(t.width * s)), 1, maxDim);
        const uint32_t h = std::clamp<uint32_t>(static_cast<uint32_t>(std::lround(t.height * s)), 1, maxDim);
        if (warnings)
            warnings->push_back("texture '" + t.name + "' is " + std::to_string(t.width) + "x" +
                                std::to_string(t.height) + ", larger than the device limit " +
                                std::to_string(maxDim) + "; downsampled to " + std::to_string(w) + "x" +
                                std::to_string(h));
        t = boxDownsample(t, w, h);
    }
}

}  // namespace dvsgi::scene
