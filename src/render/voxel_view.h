// Voxel debug view: the chosen voxel volume drawn as cubes from the camera
// (a DDA ray march per pixel), written to the output image instead of the
// shaded frame.
#pragma once

#include "gpu/pipeline.h"
#include "gpu/resources.h"

namespace dvsgi::gpu {
class GpuTimers;
class Tracker;
}
namespace dvsgi::vxgi {
class VoxelVolumes;
}

namespace dvsgi::render {

enum class ViewMode { Final, VoxelAlbedo, VoxelNormal, VoxelEmission, VoxelRadiance, VoxelDirectional, VoxelAge };

struct ViewSettings {
    ViewMode mode = ViewMode::Final;
    uint32_t mip = 0;        // directional volumes only
    uint32_t direction = 0;  // directional volumes: 0..5 = -X +X -Y +Y -Z +Z
};

class VoxelViewPass {
public:
    explicit VoxelViewPass(const gpu::Context& ctx);
    // `output` is written whole and left in use::ComputeWrite.
    void record(VkCommandBuffer cmd, gpu::Tracker& tracker, const vxgi::VoxelVolumes& volumes,
                const gpu::Buffer& frame, const gpu::Image& output, const ViewSettings& view,
                gpu::GpuTimers* timers) const;

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
};

}  // namespace dvsgi::render
