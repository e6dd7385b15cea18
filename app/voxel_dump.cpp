#include "voxel_dump.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image/file_util.h"
#include "image/image_io.h"
#include "shared/voxel_data.h"
#include "vxgi/volumes.h"
#include "vxgi/voxel_storage_io.h"

namespace dvsgi::app {

namespace {

namespace sh = dvsgi::shader;
// The rows are written as the host holds them and the header says '<f4'.
static_assert(std::endian::native == std::endian::little, "--voxel-dump writes little-endian float32");

// The .npy header (format 1.0) of a C-order float32 table: magic, version,
// header length, then the dict padded with spaces so that the data starts on
// a 64-byte boundary.
std::string npyHeader(size_t rows, size_t columns) {
    std::string dict = "{'descr': '<f4', 'fortran_order': False, 'shape': (" + std::to_string(rows) + ", " +
                       std::to_string(columns) + "), }";
    const size_t fixed = 10;  // magic (6), version (2), length (2)
    dict.append((64 - (fixed + dict.size() + 1) % 64) % 64, ' ');
    dict.push_back('\n');
    std::string out("\x93NUMPY\x01\x00", 8);
    out.push_back(char(dict.size() & 0xff));
    out.push_back(char(dict.size() >> 8));
    return out + dict;
}

}  // namespace

void writeVoxelDump(const std::string& path, const gpu::Context& ctx, const vxgi::VoxelVolumes& volumes) {
    const vxgi::DenseAttributes attributes = vxgi::readAttributes(ctx, volumes);
    const std::vector<glm::vec4> direct = vxgi::readDirectLight(ctx, volumes);
    const std::vector<glm::vec4> radiance = vxgi::readRadiance(ctx, volumes);
    const std::vector<glm::uvec4> sides = vxgi::readSideLight(ctx, volumes);
    const uint32_t n = volumes.grid.n;
    const float size = volumes.grid.voxelSize;
    std::vector<float> rows;
    for (int z = 0; z < int(n); ++z)
        for (int y = 0; y < int(n); ++y)
            for (int x = 0; x < int(n); ++x) {
                const float count = attributes.at(x, y, z, sh::CH_COUNT);
                if (count <= 0.0f) continue;
                const size_t i = (size_t(z) * n + size_t(y)) * n + size_t(x);
                glm::vec3 normal(0.0f);
                for (int a = 0; a < 3; ++a)
                    normal[a] = std::sqrt(attributes.at(x, y, z, sh::CH_NORMAL_POS_X + 2 * uint32_t(a)) / count) -
                                std::sqrt(attributes.at(x, y, z, sh::CH_NORMAL_NEG_X + 2 * uint32_t(a)) / count);
                const float len = glm::length(normal);
                normal = len > 1e-6f ? normal / len : glm::vec3(0.0f);
                const glm::vec3 centre = volumes.grid.origin + (glm::vec3(x, y, z) + 0.5f) * size;
                // Side light only where it is kept: one-sided slots hold whatever was there.
                const float code = std::round(direct[i].a - 1.0f);
                const bool twoSided = code >= 1.0f && code <= 3.0f;
                const glm::vec3 plus = twoSided ? vxgi::unpackRgb9e5(sides[i].x) + vxgi::unpackRgb9e5(sides[i].z)
                                                : glm::vec3(0.0f);
                const glm::vec3 minus = twoSided ? vxgi::unpackRgb9e5(sides[i].y) + vxgi::unpackRgb9e5(sides[i].w)
                                                 : glm::vec3(0.0f);
                const float row[kVoxelDumpColumnCount] = {
                    float(x), float(y), float(z), centre.x, centre.y, centre.z, normal.x, normal.y, normal.z,
                    attributes.at(x, y, z, sh::CH_ALBEDO_R) / count, attributes.at(x, y, z, sh::CH_ALBEDO_G) / count,
                    attributes.at(x, y, z, sh::CH_ALBEDO_B) / count, direct[i].r, direct[i].g, direct[i].b,
                    radiance[i].r, radiance[i].g, radiance[i].b, code, count, plus.r, plus.g, plus.b, minus.r,
                    minus.g, minus.b};
                rows.insert(rows.end(), row, row + kVoxelDumpColumnCount);
            }
    const std::string header = npyHeader(rows.size() / kVoxelDumpColumnCount, kVoxelDumpColumnCount);
    std::vector<uint8_t> bytes(header.begin(), header.end());
    const auto* data = reinterpret_cast<const uint8_t*>(rows.data());
    bytes.insert(bytes.end(), data, data + rows.size() * sizeof(float));
    try {
        image::detail::writeFileBytes(path, bytes);  // atomic, folders created, errors name the path
    } catch (const image::IoError& e) {
        throw image::IoError(std::string("--voxel-dump: ") + e.what());
    }
}

}  // namespace dvsgi::app
