// The compute voxelizer (voxelize.comp): triangles binned to voxels by an
// exact triangle/box test, without geometry shaders or rasterization. The
// Voxelizer (voxelize.h) holds one when --voxelizer compute is chosen.
#pragma once

#include <cstdint>

#include "gpu/pipeline.h"
#include "gpu/resources.h"

namespace dvsgi::gpu {
class Tracker;
}
namespace dvsgi::gpuscene {
class SceneGpu;
}

namespace dvsgi::vxgi {

class VoxelVolumes;
enum class VoxelizeMode;

class ComputeVoxelizer {
public:
    // Throws when the device lacks shaderFloat64 (the exact test needs it).
    ComputeVoxelizer(const gpu::Context& ctx, const gpuscene::SceneGpu& scene);

    // Adds one sample per (triangle, touched voxel) of the mode's draws.
    void voxelize(VkCommandBuffer cmd, gpu::Tracker& tracker, const gpuscene::SceneGpu& scene,
                  const VoxelVolumes& volumes, VoxelizeMode mode) const;
    // The most voxel columns a triangle walks alone before it is split into
    // tiles (shared/voxelize_compute_pass.h); the device type picks it. Tests
    // set 0 (every triangle tiled) and UINT32_MAX (none) to check both paths.
    void setTileThreshold(uint32_t columns) { smallColumns_ = columns; }

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
    gpu::Buffer groups_;    // shader::VoxcGroup: the static draws' groups, then the dynamic ones'
    gpu::Buffer tiles_;     // shader::VoxcTile[VOXC_MAX_TILES]
    gpu::Buffer indirect_;  // the tile phase's dispatch
    uint32_t staticGroups_ = 0, dynamicGroups_ = 0;
    size_t drawCount_ = 0;
    uint32_t smallColumns_ = 0;
};

}  // namespace dvsgi::vxgi
