// Structural checks of OBJ, MTL and PLY bytes before assimp sees them. Assimp
// asserts (aborting the process), loops forever or reads garbage on some
// malformed inputs (a PLY without end_header, faces with zero indices, counts
// larger than the data); these checks turn every such input into a LoadError
// naming the file. They accept everything the shared scenes contain.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace dvsgi::scene::detail {

// Polygons with more corners than this are refused: assimp's triangulation
// of one polygon is quadratic in its corner count.
constexpr uint64_t kMaxPolygonCorners = 1024;

// Each throws LoadError("<path>: ...") on the first problem found.
void precheckPly(const std::string& path, const uint8_t* data, size_t size);
// Returns the mtllib names the OBJ refers to (as written, '\\' turned '/').
std::vector<std::string> precheckObj(const std::string& path, const uint8_t* data, size_t size);
void precheckMtl(const std::string& path, const uint8_t* data, size_t size);

// Whether `size` bytes can hold an image of `width` x `height` texels. stb
// reads zeros past the end of the data, so a 64-byte TGA header claiming
// 11055 x 20034 texels would allocate and fill 900 MB for ten seconds.
// Uncompressed BMP and TGA must contain every row, and no format may claim
// more texels per byte than its best compression reaches.
bool precheckImageData(const uint8_t* data, size_t size, uint64_t width, uint64_t height, std::string& error);

// A PNG with its zero-length IDAT chunks removed, or an empty vector when it
// has none. stb_image 2.27 copies a zero-length first IDAT through a null
// pointer (undefined behaviour); such chunks carry no data, so dropping them
// changes no texel.
std::vector<uint8_t> withoutEmptyPngIdat(const uint8_t* data, size_t size);

}  // namespace dvsgi::scene::detail
