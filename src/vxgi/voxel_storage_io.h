// Host copies of the per-slot voxel storage in the dense N^3 layout that
// tests and tools compare against: read-back (index + slots -> grid) and
// upload of attributes (grid -> index, slots and a finished list). Each call
// waits for the device; the volumes stay in gpu::use::ComputeReadWrite.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace dvsgi::gpu {
class Context;
}

namespace dvsgi::vxgi {

class VoxelVolumes;

// Attribute sums per grid voxel: VOXEL_CHANNELS slabs of N^3 floats, x fastest,
// slab c at z + c N; empty voxels read zero.
struct DenseAttributes {
    explicit DenseAttributes(uint32_t n = 0);
    uint32_t n;
    std::vector<float> data;
    float& at(int x, int y, int z, uint32_t channel) { return data[offset(x, y, z, channel)]; }
    float at(int x, int y, int z, uint32_t channel) const { return data[offset(x, y, z, channel)]; }

private:
    size_t offset(int x, int y, int z, uint32_t channel) const {
        return ((size_t(z) + size_t(channel) * n) * n + size_t(y)) * n + size_t(x);
    }
};

// The raw index values (shared/voxel_data.h) of the N^3 grid, x fastest.
std::vector<uint32_t> readVoxelIndex(const gpu::Context& ctx, const VoxelVolumes& volumes);
DenseAttributes readAttributes(const gpu::Context& ctx, const VoxelVolumes& volumes);
// The per-slot direct light (RGBA, from RGBA16F) per grid voxel; empty voxels read zero.
std::vector<glm::vec4> readDirectLight(const gpu::Context& ctx, const VoxelVolumes& volumes);
// The radiance volume (RGBA16F, N^3, level 0) per grid voxel, x fastest.
std::vector<glm::vec4> readRadiance(const gpu::Context& ctx, const VoxelVolumes& volumes);
// The per-slot side light (four packed RGB9E5 words, shaders/lib/voxel_sides.glsl)
// per grid voxel; empty voxels read zero, one-sided ones whatever the slot held.
std::vector<glm::uvec4> readSideLight(const gpu::Context& ctx, const VoxelVolumes& volumes);
// One RGB9E5 word as VK_FORMAT_E5B9G9R9_UFLOAT_PACK32 defines it.
glm::vec3 unpackRgb9e5(uint32_t word);
// Gives every voxel with a fragment count > 0 a static slot (in x-fastest
// order), uploads its sums, the index and the list with its counts and
// dispatch arguments, as after a static voxelization. Direct light and
// radiance are left as they are. Throws when the slots do not suffice.
void uploadAttributes(const gpu::Context& ctx, const VoxelVolumes& volumes, const DenseAttributes& attributes);

}  // namespace dvsgi::vxgi
