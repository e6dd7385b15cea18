// --voxel-temporal-alpha: the per-level history the voxel bounce blends the
// voxels' reflected light with (vxgi::VoxelHistory), and when it may be used.
#include "render/renderer.h"

#include <algorithm>

#include "gpu/context.h"
#include "gpu/tracker.h"
#include "gpu/transfer.h"
#include "vxgi/bounce.h"
#include "vxgi/volumes.h"

namespace dvsgi::render {

// After a change the light settles over about as many feedback frames as
// converging took bounces (all of --max-bounces before any frame converged);
// what is left after that is still a few per cent of the indirect light, so
// the blend waits twice as long, and the stale light goes as fast as without
// it (test Converge/SwitchedOff.*/Blended). Fixed frames add no feedback.
void Renderer::dropVoxelHistory() {
    const vxgi::VoxelLightSettings& vl = settings_.voxelLight;
    const uint32_t settle = vl.bounceMode == vxgi::BounceMode::Fixed ? 1u
                            : convergedBounces_                   ? 2 * convergedBounces_
                                                                  : vl.maxBounces;
    lastHistoryTag_ = 0;
    historyHold_ = std::max(historyHold_, settle);
}

bool Renderer::blendsVoxelRadiance() const {
    return voxelizer_ && !pv_ && feedbackFrame() && settings_.voxelLight.temporalAlpha < 1.0f;
}

void Renderer::prepareVoxelHistory() {
    const size_t levels = levelVolumes().size();
    voxelHistory_.resize(levels);
    for (size_t l = 0; l < levels; ++l) {
        const gpu::ImageDesc d = vxgi::historyImageDesc(level(l).slots);
        gpu::Image& img = voxelHistory_[l];
        if (img.handle() && img.desc().extent.height == d.extent.height) continue;
        img = gpu::Image(ctx_, d);
        ctx_.submitAndWait([&](VkCommandBuffer cmd) { gpu::recordZeroNewImage(cmd, img); });
        tracker_.assume(img, gpu::use::ComputeReadWrite);
        lastHistoryTag_ = 0;  // nothing written yet
    }
}

}  // namespace dvsgi::render
