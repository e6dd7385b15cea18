// "frame 12/100" lines on stderr for long frame sequences (render --frames,
// bench, soak), so a run that takes minutes shows it is alive. At most two
// lines a second: a line is printed when half a second has passed since the
// previous one, and the last frame only when something was printed before, so
// short runs stay silent.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace dvsgi::app {

class FrameProgress {
public:
    FrameProgress(std::string label, uint32_t total, bool enabled)
        : label_(std::move(label)), total_(total), enabled_(enabled && total > 1), last_(Clock::now()) {}

    // `frames` frames of `total` are finished.
    void done(uint32_t frames) {
        if (!enabled_) return;
        const auto now = Clock::now();
        const bool final = frames >= total_;
        if (final ? !printed_ : now - last_ < std::chrono::milliseconds(500)) return;
        std::fprintf(stderr, "%s%sframe %u/%u\n", label_.c_str(), label_.empty() ? "" : ": ", frames, total_);
        last_ = now;
        printed_ = true;
    }

private:
    using Clock = std::chrono::steady_clock;
    std::string label_;
    uint32_t total_;
    bool enabled_;
    bool printed_ = false;
    Clock::time_point last_;
};

}  // namespace dvsgi::app
