// The seven AOV layers the layer tests write, with values that
// exr_layers_oiio.py recomputes exactly: k / 7 in float32 (a correctly
// rounded division in both languages, and not representable as half).
#pragma once

#include "image/image_io.h"

#include <cstdint>
#include <vector>

namespace dvsgi::image::test {

inline constexpr uint32_t kAovWidth = 13, kAovHeight = 9;

inline float aovValue(int layer, int channel, uint32_t x, uint32_t y) {
    const int k = (layer * 131 + channel * 17 + int(x) * 3 + int(y) * 5) % 1000 - 300;
    return float(k) / 7.0f;
}

inline std::vector<ExrLayer> makeAovLayers(uint32_t w = kAovWidth, uint32_t h = kAovHeight) {
    std::vector<ExrLayer> layers = {
        {"direct", {"R", "G", "B"}, {}},   {"indirect", {"R", "G", "B"}, {}},
        {"specular", {"R", "G", "B"}, {}}, {"ao", {"Y"}, {}},
        {"albedo", {"R", "G", "B"}, {}},   {"normal", {"X", "Y", "Z"}, {}},
        {"depth", {"Z"}, {}},
    };
    for (size_t l = 0; l < layers.size(); ++l) {
        ExrLayer& layer = layers[l];
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x)
                for (size_t c = 0; c < layer.channels.size(); ++c)
                    layer.pixels.push_back(aovValue(int(l), int(c), x, y));
    }
    return layers;
}

}  // namespace dvsgi::image::test
