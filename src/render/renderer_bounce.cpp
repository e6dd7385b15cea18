// The voxel bounce's recording: which way it traces (rays or cones, through
// clipmap levels), when a frame feeds back from the frame before, and the
// convergence statistics a converging render reads after each bounce.
#include "render/renderer.h"

#include "shared/bounce_pass.h"
#include "vxgi/bounce.h"
#include "vxgi/cone_settings.h"
#include "vxgi/volumes.h"

namespace dvsgi::render {

namespace sh = dvsgi::shader;

bool Renderer::bounceRays() const { return bounceTracesRays(settings_); }

bool Renderer::gatherRays() const { return voxelizer_ && gatherTracesRays(settings_); }

bool Renderer::areaLightRays() const {
    return settings_.emitterRays && voxelizer_ && clip_.empty() && patchCount_ > 0 &&
           settings_.voxelizer != vxgi::VoxelizerKind::Pv;
}

bool Renderer::raysRead() const { return voxelizer_ && (bounceRays() || gatherRays() || areaLightRays()); }

void Renderer::packRayData(VkCommandBuffer cmd) {
    if (raysRead() && !rayData_->packed) bounce_->recordRayData(cmd, tracker_, *volumes_, *rayData_, timers_.get());
}

// What a bounce's cones trace with --clipmap: the levels through the windows
// their directional volumes were last filtered in.
std::optional<vxgi::ClipTrace> Renderer::bounceTrace() const {
    if (clip_.empty()) return std::nullopt;
    return vxgi::ClipTrace{*directionalLevels_, *atlases_, levelVolumes().back()->grid};
}

void Renderer::recordBounce(VkCommandBuffer cmd, bool withStats) {
    const std::optional<vxgi::ClipTrace> trace = bounceTrace();
    recordLevels(cmd, "voxel filtering (bounce)", [&](size_t l, const vxgi::VoxelVolumes& v) {
        recordLevelBounce(cmd, l, v, trace ? &*trace : nullptr, withStats);
    });
}

// A level's bounce. With --clipmap its voxels trace from their level up,
// through the windows the directional volumes were filtered in.
void Renderer::recordLevelBounce(VkCommandBuffer cmd, size_t l, const vxgi::VoxelVolumes& v,
                                 const vxgi::ClipTrace* trace, bool withStats, bool blend) {
    const vxgi::ConeSettings cone = vxgi::bounceCones(settings_.cones, settings_.voxelLight.bounceStepFactor);
    vxgi::VoxelHistory history;
    if (blend) {
        // UINT32_MAX: a tag no frame writes, so nothing is blended with.
        const bool use = lastHistoryTag_ != 0 && historyHold_ == 0;
        history = {&voxelHistory_[l], historyTag_, use ? lastHistoryTag_ : UINT32_MAX,
                   settings_.voxelLight.temporalAlpha};
    }
    const vxgi::VoxelLightSettings& vl = settings_.voxelLight;
    const uint32_t rays = bounceRays() ? vl.bounceRays : 0u;
    bounce_->record(cmd, tracker_, v, samplers_->volume.handle(), cone, rays, rayData_.get(), vl.backsDark,
                    withStats ? bounceStats_.at(l).get() : nullptr, timers_.get(), trace, uint32_t(l),
                    blend ? &history : nullptr);
}

bool Renderer::feedbackFrame() const {
    const vxgi::BounceMode m = settings_.voxelLight.bounceMode;
    if (m == vxgi::BounceMode::Feedback) return true;
    // A feedback frame's rays read the light the static voxels kept from the
    // frame before; after a static re-voxelization they have none, and a
    // converging render converges again rather than start over from one bounce.
    const bool staticLightLost = bounceRays() && (staticDirty_ || !staticLightKept_);
    return m == vxgi::BounceMode::Converge && haveHistory_ && !staticLightLost;
}

double Renderer::bounceChange() const {
    double change = 0.0, reflected = 0.0;
    const std::vector<const vxgi::VoxelVolumes*> levels = levelVolumes();
    for (size_t l = 0; l < bounceStats_.size(); ++l) {
        const float* f = static_cast<const float*>(bounceStats_[l]->mapped());
        const uint32_t count = vxgi::BouncePass::statsFloats(levels[l]->slots);
        for (uint32_t i = 0; i + 1 < count; i += sh::BOUNCE_STATS_FLOATS) {
            change += f[i];
            reflected += f[i + 1];
        }
    }
    return reflected > 0.0 ? change / reflected : 0.0;
}

}  // namespace dvsgi::render
