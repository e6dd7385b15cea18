// Conservative voxelization of the scene into the voxel attribute volume
// (paper section V), and the per-frame clear of dynamic voxels.
#pragma once

#include "gpu/pipeline.h"

namespace dvsgi::gpu {
class GpuTimers;
class Tracker;
}
namespace dvsgi::gpuscene {
class SceneGpu;
}

namespace dvsgi::vxgi {

class VoxelVolumes;

enum class VoxelizeMode { Static, Dynamic };

class Voxelizer {
public:
    // hardwareConservative: use VK_EXT_conservative_rasterization instead of
    // the geometry-shader dilation (only when the device has it).
    Voxelizer(const gpu::Context& ctx, const gpuscene::SceneGpu& scene, bool hardwareConservative);

    // Zeroes attributes, flags, direct light and radiance: the start of a
    // static re-voxelization (the occupied-voxel list is reset beside it).
    void clearAll(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes,
                  gpu::GpuTimers* timers) const;
    // Zeroes the voxels of the list's dynamic entries (what dynamic geometry
    // wrote last frame); VoxelListPass::dropDynamic then forgets them.
    void clearDynamic(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes,
                      gpu::GpuTimers* timers) const;
    // Voxelizes the static or the dynamic draws of the scene, appending newly
    // occupied voxels to the list (VoxelListPass::finish then counts them).
    void voxelize(VkCommandBuffer cmd, gpu::Tracker& tracker, const gpuscene::SceneGpu& scene,
                  const VoxelVolumes& volumes, VoxelizeMode mode, gpu::GpuTimers* timers) const;
    bool hardwareConservative() const { return hardware_; }

private:
    const gpu::Context& ctx_;
    bool hardware_;
    gpu::Pipeline voxelize_;
    gpu::Pipeline clear_;
};

}  // namespace dvsgi::vxgi
