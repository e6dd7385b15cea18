// libFuzzer target: the EXR readers (header checks, then OpenEXR) on bytes in
// memory. IoError is the expected answer to a bad file; any other exception
// escapes and counts as a finding, because the CLI and the tests rely on one
// IoError line naming the file.
#include <cmath>
#include <cstdint>

#include "image/exr_detail.h"

namespace {

void readPlain(const uint8_t* data, size_t size) {
    using namespace dvsgi::image;
    try {
        const ImageRGBA32F img = detail::readExrBytes("fuzz.exr", std::vector<uint8_t>(data, data + size));
        if (img.width == 0 || img.height == 0 || img.rgba.size() != img.pixelCount() * 4) __builtin_trap();
    } catch (const IoError&) {
    }
}

void readLayers(const uint8_t* data, size_t size) {
    using namespace dvsgi::image;
    try {
        const ExrLayerFile f = detail::readExrLayersBytes("fuzz.exr", std::vector<uint8_t>(data, data + size));
        if (f.width == 0 || f.height == 0 || f.types.size() != f.layers.size()) __builtin_trap();
        for (const ExrLayer& l : f.layers)
            if (l.channels.empty() || l.pixels.size() != size_t(f.width) * f.height * l.channels.size())
                __builtin_trap();
    } catch (const IoError&) {
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    // Both readers: they share the header checks but set up different frame
    // buffers (RGBA with a filled alpha, and one slice per channel of any name).
    readPlain(data, size);
    readLayers(data, size);
    return 0;
}
