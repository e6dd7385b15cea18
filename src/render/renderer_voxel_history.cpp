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
// converging took bounces (all of --max-bounces before any frame converged),
// but converging stopped once a bounce added a fraction of a per cent of the
// light, while stale light starts from all of the old indirect light: after
// that many frames a few per cent of it is left. So averages over frames (the
// voxels' reflected light, the pixels' indirect term) wait twice as long, and
// the stale light goes as fast as without them (tests Converge/SwitchedOff.*,
// Clipmap.SwitchedOffLightLeavesNoGhost). Fixed frames add no feedback.
uint32_t Renderer::settleFrames() const {
    const vxgi::VoxelLightSettings& vl = settings_.voxelLight;
    if (vl.bounceMode == vxgi::BounceMode::Fixed) return 1u;
    return convergedBounces_ ? 2 * convergedBounces_ : vl.maxBounces;
}

void Renderer::dropVoxelHistory() {
    lastHistoryTag_ = 0;
    historyHold_ = std::max(historyHold_, settleFrames());
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
