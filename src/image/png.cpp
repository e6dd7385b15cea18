// PNG preview. stb_image_write is compiled here with static linkage so it can
// never clash with another copy (Debian also ships a prebuilt libstb).
#include "image/image_io.h"

#include "image/file_util.h"

#include <algorithm>
#include <cmath>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO  // we write the bytes ourselves to report errors properly
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace dvsgi::image {

uint8_t encodeSrgb8(float linear) {
    // Double precision so the byte matches the reference tools' float64 maths.
    double v = std::isnan(linear) ? 0.0 : std::clamp(double(linear), 0.0, 1.0);
    const double s = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
    return uint8_t(std::clamp(std::lround(s * 255.0), 0L, 255L));
}

void writePng(const std::string& path, const ImageRGBA32F& img, float exposureEV) {
    if (img.width == 0 || img.height == 0) detail::fail(path, "cannot write an empty image");
    if (img.rgba.size() != img.pixelCount() * 4)
        detail::fail(path, "image has " + std::to_string(img.rgba.size()) + " floats, expected " +
                               std::to_string(img.pixelCount() * 4));
    if (img.width > 0x7fffffffu / 3 || img.height > 0x7fffffffu)
        detail::fail(path, "image too large for PNG");
    const double scale = std::exp2(double(exposureEV));
    std::vector<uint8_t> rgb(img.pixelCount() * 3);
    for (size_t i = 0; i < img.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c)
            rgb[i * 3 + c] = encodeSrgb8(float(double(img.rgba[i * 4 + c]) * scale));

    std::vector<uint8_t> png;
    auto sink = [](void* ctx, void* data, int size) {
        auto* out = static_cast<std::vector<uint8_t>*>(ctx);
        auto* p = static_cast<const uint8_t*>(data);
        out->insert(out->end(), p, p + size);
    };
    if (!stbi_write_png_to_func(sink, &png, int(img.width), int(img.height), 3, rgb.data(),
                                int(img.width * 3)))
        detail::fail(path, "PNG encoding failed");
    detail::writeFileBytes(path, png);
}

}  // namespace dvsgi::image
