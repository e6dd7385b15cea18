#include "bench_flicker.h"

#include <algorithm>

#include "vxgi/clipmap.h"

namespace dvsgi::app {

void recordFrameFlicker(const render::Renderer& renderer, uint32_t frame, float time, const render::FrameStats& stats,
                        std::optional<render::TemporalFrame>& previous, Measurement& m) {
    render::TemporalFrame current = render::captureIndirect(renderer);
    nlohmann::json f = {{"frame", frame}, {"time", time}, {"gpu_ms", stats.gpuMs}};
    nlohmann::json passes = nlohmann::json::object();
    for (const gpu::TimerResult& r : stats.passes) passes[r.name] = r.ms;
    f["passes"] = passes;
    if (previous) {
        const render::TemporalChange c = render::temporalChange(*previous, current);
        f["flicker"] = {{"mean_relative_change", c.meanRelative},
                        {"p99_relative_change", c.p99Relative},
                        {"compared_pixels", c.compared},
                        {"disoccluded_pixels", c.rejected},
                        {"mean_indirect_luminance_before", c.meanLuminanceBefore},
                        {"mean_indirect_luminance_after", c.meanLuminanceAfter}};
        // The same for the light before the albedo: a moving camera resamples
        // texture detail too, which the figure above counts as change.
        const render::TemporalChange e =
            render::temporalChange(*previous, current, 0.02f, render::TemporalTerm::Irradiance);
        f["flicker"]["irradiance"] = {{"mean_relative_change", e.meanRelative},
                                      {"p99_relative_change", e.p99Relative}};
        // The jump of mean indirect luminance over the pixels both frames
        // saw, and whether a clipmap level scrolled this frame (its scroll
        // pass ran): issue #11 bounds the jump at a scroll by 2 %.
        const bool scrolled = std::any_of(stats.passes.begin(), stats.passes.end(),
                                          [](const gpu::TimerResult& r) { return r.name == vxgi::kClipmapScrollTimer; });
        f["flicker"]["scrolled"] = scrolled;
        if (c.compared > 0) {
            if (c.meanLuminanceBefore > 0.0) {
                const double jump = c.meanLuminanceAfter / c.meanLuminanceBefore - 1.0;
                f["flicker"]["luminance_jump"] = jump;
                if (scrolled) m.scrollJumps.push_back(jump);
            }
            m.flickerMean.push_back(c.meanRelative);
            m.flickerP99.push_back(c.p99Relative);
            m.flickerIrradianceMean.push_back(e.meanRelative);
            m.flickerIrradianceP99.push_back(e.p99Relative);
        }
    }
    m.detail["per_frame"].push_back(f);
    previous = std::move(current);
}

}  // namespace dvsgi::app
