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
    // Reads `radiance`, writes every level of the directional volumes.
    void record(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes, gpu::GpuTimers* timers,
                const char* timerName) const;

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
};

}  // namespace dvsgi::vxgi
