// The compute voxelizer (voxelize.comp): triangles binned to voxels by an
// exact triangle/box test, without geometry shaders or rasterization. The
// Voxelizer (voxelize.h) holds one when --voxelizer compute is chosen.
#pragma once

#include <cstdint>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "scene/scene.h"
#include "shared/voxelize_compute_pass.h"

namespace dvsgi::gpu {
class Tracker;
}
namespace dvsgi::gpuscene {
class SceneGpu;
}

namespace dvsgi::vxgi {

class VoxelVolumes;
struct GridSpec;
enum class VoxelizeMode;

// How the compute voxelizer splits large triangles (shared/voxelize_compute_pass.h).
struct ComputeTiling {
    uint32_t walkColumns;  // the most voxel columns a triangle walks alone before it is split into tiles
    uint32_t laneColumns;  // columns each invocation of a tile walks (1..VOXC_MAX_LANE_COLUMNS)
    uint32_t pending;      // hits a walk collects before sampling them (1..VOXC_PENDING)
};
// The tiling measured best for the device type (CPU devices walk longer and
// sample their hits in batches).
ComputeTiling computeTilingFor(VkPhysicalDeviceType type);

// Whether a triangle group whose world bounds are [lo, hi] can touch a voxel
// that static voxelization writes on `grid` with `keep` (shader::VoxelGrid.keep:
// after a clipmap scroll only the voxels outside the kept box). Conservative:
// two voxels of margin beyond the shader's own test of each triangle.
bool groupReachesWrittenVoxels(const glm::vec3& lo, const glm::vec3& hi, const GridSpec& grid, const glm::ivec4& keep);
// World bounds [lo, hi] of a local box under `world` (its eight corners).
void chunkWorldBounds(const scene::Bounds& local, const glm::mat4& world, glm::vec3& lo, glm::vec3& hi);

class ComputeVoxelizer {
public:
    // Throws when the device lacks shaderFloat64 (the exact test needs it).
    ComputeVoxelizer(const gpu::Context& ctx, const gpuscene::SceneGpu& scene);

    // Adds one sample per (triangle, touched voxel) of the mode's draws.
    void voxelize(VkCommandBuffer cmd, gpu::Tracker& tracker, const gpuscene::SceneGpu& scene,
                  const VoxelVolumes& volumes, VoxelizeMode mode) const;
    // The device type picks the tiling; tests set others (every triangle
    // tiled, none, one or several columns per lane) to check every path.
    void setTiling(ComputeTiling tiling);

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
    gpu::Buffer groups_;    // shader::VoxcGroup: the static draws' groups, then the dynamic ones'
    gpu::Buffer scrollGroups_;  // the static groups a scroll's slabs need (filled per scroll)
    std::vector<shader::VoxcGroup> staticGroupsHost_;  // the static groups, for the scroll's host-side culling

    gpu::Buffer tiles_;     // shader::VoxcTile[VOXC_MAX_TILES]
    gpu::Buffer indirect_;  // the tile phase's dispatch
    uint32_t staticGroups_ = 0, dynamicGroups_ = 0;
    size_t drawCount_ = 0;
    ComputeTiling tiling_;
};

}  // namespace dvsgi::vxgi
