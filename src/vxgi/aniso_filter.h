// Anisotropic filtering (paper section VIII): the radiance volume into six
// directional volumes with their mip chains, each level from the one below.
#pragma once

#include "gpu/pipeline.h"

namespace dvsgi::gpu {
class GpuTimers;
class Tracker;
}

namespace dvsgi::vxgi {

class VoxelVolumes;

class AnisoFilterPass {
public:
    explicit AnisoFilterPass(const gpu::Context& ctx);
    // Reads `radiance` (and the occupied-voxel list: the base level is
    // composited only where voxels are), writes every level of the directional
    // volumes; the cells that hold two-sided voxels (lib/voxel_sides.glsl) are
    // written again from the voxels' side light before the next level.
    // `backsDark`: a one-sided voxel shows its light only to rays that meet its
    // front (false: every way, the paper's filter).
    void record(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes, bool backsDark,
                gpu::GpuTimers* timers, const char* timerName) const;

private:
    static gpu::Descriptors levelZeroBindings(const VoxelVolumes& volumes);
    static void readLevelZero(gpu::Tracker& tracker, const VoxelVolumes& volumes);
    void dispatchOverLevelZero(VkCommandBuffer cmd, const gpu::Pipeline& pipeline, const gpu::Descriptors& bindings,
                               const VoxelVolumes& volumes, bool backsDark) const;
    void recordBase(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes, bool backsDark) const;
    void recordTwoSided(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes, bool backsDark) const;

    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;  // levels above the base: read the level below
    gpu::Pipeline base_;      // the base level: reads the radiance volume, over the list
    gpu::Pipeline twoSided_;
};

}  // namespace dvsgi::vxgi
