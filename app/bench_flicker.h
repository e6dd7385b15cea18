// With --camera-path, `dvsgi bench` reports every measured frame: its GPU time
// per pass and the flicker figure of its indirect term (render/temporal_change.h:
// frame t reprojected into frame t+1 on static geometry).
#pragma once

#include <optional>

#include "bench_measurement.h"
#include "render/renderer.h"
#include "render/temporal_change.h"

namespace dvsgi::app {

// Reads back the frame's indirect term and depth, compares them with
// `previous` (when there is one), appends the frame to m.detail["per_frame"]
// and the figures to m.flickerMean / m.flickerP99, and keeps this frame as
// `previous`. Outside every timed region.
void recordFrameFlicker(const render::Renderer& renderer, uint32_t frame, float time, const render::FrameStats& stats,
                        std::optional<render::TemporalFrame>& previous, Measurement& m);

}  // namespace dvsgi::app
