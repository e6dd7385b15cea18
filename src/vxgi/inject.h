// Voxel direct light (paper sections VI, VII): every occupied voxel's direct
// light from each light (shadow maps, raycasts through the voxels, or none)
// plus its emission, into VoxelVolumes::direct (per slot) and ::radiance (the
// start of the bounce iteration).
#pragma once

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "vxgi/voxel_light_settings.h"

namespace dvsgi::gpu {
class GpuTimers;
class Tracker;
}

namespace dvsgi::vxgi {

class VoxelVolumes;

struct ShadowInputs {
    const gpu::Buffer& lights;
    uint32_t lightCount;
    const gpu::Buffer& views;
    const gpu::Image& shadowMap;    // depth array (FrameTargets::shadowMap)
    const gpu::Image& shadowGradient;  // its casters' depth gradients (FrameTargets::shadowGradient)
    VkSampler gatherSampler;        // nearest, clamped: the lookup gathers 2 x 2 texels of both
    bool shadowsRendered;
};

class InjectPass {
public:
    explicit InjectPass(const gpu::Context& ctx);
    // Reads the list, the attributes and the index (voxel shadow rays); writes
    // `direct` and `radiance` of the listed (occupied) voxels. `occupancy`
    // (optional): this frame's rays' occupancy bits (RayData::occupancy,
    // packed), with which voxel shadow rays cross empty cells in one step.
    void record(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes, const ShadowInputs& shadows,
                const VoxelLightSettings& settings, gpu::GpuTimers* timers,
                const gpu::Buffer* occupancy = nullptr) const;

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_, occupancyPipeline_;
};

}  // namespace dvsgi::vxgi
