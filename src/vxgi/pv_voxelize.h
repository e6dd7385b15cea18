// Progressive screen-space voxelization (Gaitatzes & Papaioannou, seed 004;
// `--voxelizer pv`): the volumes persist from frame to frame; each frame a
// cleanup frees the voxels that the frame's depth buffers (the camera's and
// the shadow maps) show to be empty and carries the rest over, then the
// camera's G-buffer is injected into the voxels its pixels lie in. Cost
// depends on the image and the occupied voxels, not on the triangle count;
// geometry never seen by a buffer is not voxelized (shared/pv_pass.h).
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "gpu/pipeline.h"
#include "gpu/resources.h"

namespace dvsgi::gpu {
class GpuTimers;
class Tracker;
}

namespace dvsgi::vxgi {

class VoxelVolumes;

struct PvSettings {
    // Injection grid: samples along the G-buffer's longer side (the other side
    // in proportion); 0 = every pixel.
    uint32_t grid = 0;
    // Reflective shadow maps: each shadow view also renders a G-buffer of
    // rsm x rsm texels from the light, injected like the camera's, so that
    // lit surfaces the camera has not seen are voxelized too; 0 = off. Off
    // by default: along a Sponza walk they made the indirect light 1.4-3.1x
    // too bright (lit surfaces found, the occluders between them and what
    // the camera sees not), the camera alone 0.92-1.11x (docs/pv.md).
    uint32_t rsm = 0;
    // Extra viewpoints: six 90-degree G-buffers of views x views texels
    // around the camera, injected like the camera's, so that what it does
    // not face is found too; 0 = off.
    uint32_t views = 0;
    // The chapter's single-pass variant: every grid voxel in a G-buffer's
    // depth band takes the sample of the pixel it projects to, instead of
    // each sample (and its footprint corners) adding to its voxel.
    bool singlePass = false;
};

// The depth buffers that can prove voxels empty. `views` holds
// shader::PvDepthView records, the camera's first.
struct PvDepthInputs {
    const gpu::Image& cameraDepth;  // D32
    const gpu::Image& shadowMap;    // D32 array
    const gpu::Buffer& views;
    uint32_t viewCount;
    VkSampler pointSampler;
};

// The camera's G-buffer, as the frame rendered it.
struct PvGBufferInputs {
    const gpu::Image& depth;
    const gpu::Image& base;
    const gpu::Image& normal;
    const gpu::Image& emission;
    const gpu::Buffer& frame;  // shader::FrameConstants
    VkSampler pointSampler;
};

// The injection grid (width, height) for a G-buffer of width x height.
glm::uvec2 pvInjectionGrid(uint32_t width, uint32_t height, const PvSettings& settings);

class PvVoxelizer {
public:
    explicit PvVoxelizer(const gpu::Context& ctx);

    // Last frame's voxels into this frame's list: the volumes' sums and list
    // trade places with this pass's own pair (the chapter's ping-pong
    // volumes), the new list starts empty, and each old voxel is freed or
    // moved (see pv_cleanup.comp). The index and the radiance of freed
    // voxels are zeroed.
    void cleanup(VkCommandBuffer cmd, gpu::Tracker& tracker, VoxelVolumes& volumes, const PvDepthInputs& depth,
                 gpu::GpuTimers* timers);
    // Adds the G-buffer's samples to their voxels, claiming new ones (static
    // bit set: progressive voxels have no static/dynamic split).
    // VoxelListPass::finish(static) counts them afterwards.
    void inject(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes, const PvGBufferInputs& g,
                const PvSettings& settings, gpu::GpuTimers* timers) const;
    // The pass's own sums and list (the other half of the ping-pong pair).
    uint64_t memoryBytes() const;

private:
    const gpu::Context& ctx_;
    gpu::Pipeline cleanup_;
    gpu::Pipeline inject_;
    gpu::Pipeline band_;
    gpu::Image otherAccum_;
    gpu::Buffer otherList_;
};

}  // namespace dvsgi::vxgi
