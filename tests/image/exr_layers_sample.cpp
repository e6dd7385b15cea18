// Writes the AOV sample layers for exr_layers_oiio.py, so the Python test
// judges files from our writer: exr_layers_sample <out.exr> float|half
#include "aov_sample.h"

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
    using namespace dvsgi::image;
    const std::string type = argc == 3 ? argv[2] : "";
    if (type != "float" && type != "half") {
        std::fprintf(stderr, "usage: exr_layers_sample <out.exr> float|half\n");
        return 2;
    }
    try {
        writeExrLayers(argv[1], test::kAovWidth, test::kAovHeight, test::makeAovLayers(),
                       type == "half" ? PixelType::Half : PixelType::Float);
    } catch (const IoError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
