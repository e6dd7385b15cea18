// Writes the fuzz_exr seeds with the project's own EXR writer: what the
// reader meets in practice (float and half frames, with and without alpha,
// and an --aov style multi-layer file), kept tiny so mutations stay fast.
//   exr_seeds OUTDIR
#include <cstdio>
#include <string>

#include "image/image_io.h"

using namespace dvsgi::image;

namespace {

ImageRGBA32F ramp(uint32_t w, uint32_t h) {
    ImageRGBA32F img = ImageRGBA32F::blank(w, h);
    for (size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = float(i % 7) * 0.25f + (i % 4 == 3 ? 0.5f : 0.0f);
    return img;
}

ExrLayer layer(const std::string& name, std::vector<std::string> channels, uint32_t w, uint32_t h, float scale) {
    ExrLayer l{name, std::move(channels), {}};
    l.pixels.resize(size_t(w) * h * l.channels.size());
    for (size_t i = 0; i < l.pixels.size(); ++i) l.pixels[i] = scale * float(i % 5);
    return l;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: exr_seeds OUTDIR\n");
        return 2;
    }
    const std::string dir = argv[1];
    try {
        writeExr(dir + "/float_rgb_4x3.exr", ramp(4, 3));
        writeExr(dir + "/half_rgba_5x2.exr", ramp(5, 2), ExrOptions{PixelType::Half, true});
        writeExr(dir + "/float_rgba_1x1.exr", ramp(1, 1), ExrOptions{PixelType::Float, true});
        const uint32_t w = 3, h = 3;
        std::vector<ExrLayer> aov = {layer("direct", {"R", "G", "B"}, w, h, 0.5f),
                                     layer("ao", {"Y"}, w, h, 0.2f),
                                     layer("normal", {"X", "Y", "Z"}, w, h, -0.3f),
                                     layer("depth", {"Z"}, w, h, 2.0f)};
        writeExrLayers(dir + "/layers_float_3x3.exr", w, h, aov, PixelType::Float);
        writeExrLayers(dir + "/layers_half_3x3.exr", w, h, aov, PixelType::Half);
        // An unprefixed RGB layer beside named ones, as readExr and viewers see first.
        aov.insert(aov.begin(), layer("", {"R", "G", "B"}, w, h, 1.0f));
        writeExrLayers(dir + "/layers_default_3x3.exr", w, h, aov, PixelType::Half);
    } catch (const IoError& e) {
        std::fprintf(stderr, "exr_seeds: %s\n", e.what());
        return 1;
    }
    return 0;
}
