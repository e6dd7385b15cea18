// Temporal accumulation of the per-pixel indirect diffuse term (issue #11
// item 3): last frame's accumulated term is reprojected into this frame
// through the depth buffer and both cameras, rejected where the surface
// differs (disocclusion) or falls off screen, and blended with this frame's
// cone-traced term. Runs after the gather (and upsampling), before the
// composite; shaders/temporal_indirect.comp says how.
#pragma once

#include <algorithm>
#include <cstdint>

#include <glm/glm.hpp>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "render/frame_resources.h"

namespace dvsgi::gpu {
class GpuTimers;
class Tracker;
}

namespace dvsgi::render {

struct TemporalSettings {
    bool enabled = true;   // off: the gather's term goes to the composite as it is
    float minAlpha = 0.05f; // weight of this frame's term (from the start once the voxel light has settled: temporalBlendWeight)
};

// The weight of this frame's term when the history holds `historyFrames`
// frames, the same for every pixel. While the voxel light still climbs from
// frame to frame with nothing dropped (feedback bounces from the first frame),
// the running mean of the frames since the history (re)started, until
// 1/minAlpha of them, then an exponential average: the term follows the light
// within the frames it has. Once the light has settled (it converged, or the
// history was held back while it settled), minAlpha from the first frame on:
// the gathers then differ only in how a moving camera's pixels sample the
// surfaces, and averaging those fast moved every pixel by half, a third, ...
// of that difference in the frames after a restart (docs/benchmarks.md).
inline float temporalBlendWeight(float minAlpha, uint32_t historyFrames, bool lightClimbs) {
    return lightClimbs ? std::max(1.0f / float(historyFrames + 1u), minAlpha) : minAlpha;
}

struct TemporalIndirectInputs {
    const GBuffer& gbuffer;  // this frame's depth and normals
    const Samplers& samplers;
    const gpu::Buffer& frame;  // FrameConstants of this frame's camera
    const gpu::Image& history;  // last frame's accumulated term (RGBA32F, a = the pixel's frames in it, >= 1)
    const gpu::Image& surface;  // last frame's normal and view depth (RGBA16F)
    glm::mat4 previousViewProj;  // last frame's camera, as FrameConstants::viewProj
    bool historyValid;           // false: first frame or a reset, the history is not read
    uint32_t historyFrames;      // frames the history holds (when valid)
    bool lightClimbs;            // the voxel light may still grow frame by frame (temporalBlendWeight)
};

struct TemporalIndirectTargets {
    const gpu::Image& diffuse;  // internal size, read and overwritten with the accumulated term (a kept)
    const gpu::Image& history;  // this frame's accumulated term and count, for the next frame
    const gpu::Image& surface;  // this frame's normal and view depth
};

class TemporalIndirectPass {
public:
    explicit TemporalIndirectPass(const gpu::Context& ctx);
    // Writes the history targets whole; `diffuse` changes only where history
    // was accepted, so without valid history it stays exactly as it was.
    void record(VkCommandBuffer cmd, gpu::Tracker& tracker, const TemporalIndirectInputs& in,
                const TemporalIndirectTargets& out, const TemporalSettings& settings, gpu::GpuTimers* timers) const;

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
};

// Which of the two history pairs (FrameTargets::temporal) holds last frame's
// term, and under which camera; the Renderer keeps one. drop() discards it
// for a number of frames (first frame, static geometry or lights changed,
// settings changed: while the voxel light still settles after a change, an
// average would keep part of the old light).
struct TemporalState {
    uint32_t previous = 0;  // index of last frame's pair; this frame writes the other
    bool valid = false;
    uint32_t hold = 0;      // frames that still start without history
    uint32_t frames = 0;    // frames the history holds (meaningful while valid; stops counting at kFramesCounted)
    // Far past 1/minAlpha for any weight the settings allow (0.01 at least).
    static constexpr uint32_t kFramesCounted = 1u << 16;
    glm::mat4 previousViewProj{1.0f};
    void reset() { drop(1); }
    // The next `holdFrames` frames (at least 1) start without history.
    void drop(uint32_t holdFrames) {
        valid = false;
        hold = hold > holdFrames ? hold : holdFrames;
    }
    // At the start of each frame.
    void beginFrame() {
        if (hold == 0) return;
        valid = false;
        --hold;
    }
    // After recording a frame that wrote pair 1 - previous under `viewProj`.
    void advance(const glm::mat4& viewProj) {
        frames = valid ? std::min(frames + 1u, kFramesCounted) : 1u;
        previous = 1 - previous;
        valid = true;
        previousViewProj = viewProj;
    }
};

}  // namespace dvsgi::render
