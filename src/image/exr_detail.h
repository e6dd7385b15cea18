// The EXR readers on bytes already in memory, for the fuzz target and tests:
// readExr/readExrLayers are these after one read of the whole file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image_io.h"

namespace dvsgi::image::detail {

// `path` only names the input in IoError messages; nothing is opened.
ImageRGBA32F readExrBytes(const std::string& path, std::vector<uint8_t> bytes);
ExrLayerFile readExrLayersBytes(const std::string& path, std::vector<uint8_t> bytes);

}  // namespace dvsgi::image::detail
