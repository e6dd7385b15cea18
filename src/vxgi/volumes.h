// The voxel grid and the volumes that live on it (docs/ARCHITECTURE.md lists
// their formats). All volumes stay in the GENERAL layout for their lifetime.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/resources.h"
#include "scene/scene.h"

namespace dvsgi::vxgi {

struct GridSpec {
    glm::vec3 origin{0.0f};  // world position of the grid's minimum corner
    float voxelSize = 1.0f;  // edge of one voxel, metres
    uint32_t n = 128;        // voxels per edge
};

// A cube on the longest side of `bounds`, centred on it, with four voxels of
// margin on every side so surfaces on the bounds never sit on the grid's edge
// and cones cross their whole footprint before leaving the grid.
GridSpec fitGrid(const scene::Bounds& bounds, uint32_t n);
// A cube on the longest side of a user-given box (no margin added).
GridSpec gridForBox(const glm::vec3& boxMin, const glm::vec3& boxMax, uint32_t n);

uint32_t directionalMipCount(uint32_t n);  // (N/2)^3 down to 1^3

struct VolumeMemory {
    std::string name;
    std::string format;
    uint64_t bytes;
};
// What the volumes of an N^3 grid take, before allocating anything.
std::vector<VolumeMemory> volumeMemory(uint32_t n);
// Their sum over N^3: the figure issue #14's compact-storage goal is stated in.
double voxelBytesPerGridVoxel(uint32_t n);

class VoxelVolumes {
public:
    VoxelVolumes(const gpu::Context& ctx, const GridSpec& grid);

    GridSpec grid;
    uint32_t directionalMips;
    gpu::Image accum;     // R32_SFLOAT, N x N x (VOXEL_CHANNELS * N): summed attributes
    gpu::Image flags;     // R8_UINT, N^3: VOXEL_FLAG_STATIC where static geometry wrote
    gpu::Image direct;    // RGBA16F, N^3: direct light + emission, kept for the bounces
    gpu::Image radiance;  // RGBA16F, N^3: direct light + emission (+ bounces), a = opacity
    std::array<gpu::Image, 6> directional;  // RGBA16F, (N/2)^3 + mips; order -X +X -Y +Y -Z +Z
    gpu::Buffer gridBuffer;                  // shader::VoxelGrid
    // The occupied-voxel list (shared/voxel_list_pass.h): header, then up to
    // N^3 packed coordinates. Storage, indirect-dispatch arguments, fills.
    gpu::Buffer list;
    // Every volume, for code that handles them all alike. They start zeroed,
    // in gpu::use::ComputeReadWrite.
    std::vector<const gpu::Image*> all() const;
};

}  // namespace dvsgi::vxgi
