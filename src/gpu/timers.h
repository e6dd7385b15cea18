// Named GPU timers from timestamp queries. A pass opens a scope by name; the
// results come back in recording order, so tables and JSON need no indices.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace dvsgi::gpu {

class Context;

struct TimerResult {
    std::string name;
    double ms = 0.0;
};

class GpuTimers {
public:
    GpuTimers(const Context& ctx, uint32_t maxScopes = 64);
    ~GpuTimers();
    GpuTimers(const GpuTimers&) = delete;
    GpuTimers& operator=(const GpuTimers&) = delete;

    void reset();  // host-side; call before recording a new frame
    void begin(VkCommandBuffer cmd, const std::string& name);
    void end(VkCommandBuffer cmd);  // closes the innermost open scope
    // Waits for the results of the last submitted frame. Same name twice: summed.
    std::vector<TimerResult> results() const;
    uint32_t capacity() const { return maxScopes_; }

private:
    const Context& ctx_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    uint32_t maxScopes_;
    std::vector<std::string> names_;
    std::vector<uint32_t> open_;
    uint32_t used_ = 0;
};

// RAII scope: GpuTimerScope t(timers, cmd, "lighting");
class GpuTimerScope {
public:
    GpuTimerScope(GpuTimers* timers, VkCommandBuffer cmd, const std::string& name) : timers_(timers), cmd_(cmd) {
        if (timers_) timers_->begin(cmd_, name);
    }
    ~GpuTimerScope() {
        if (timers_) timers_->end(cmd_);
    }
    GpuTimerScope(const GpuTimerScope&) = delete;
    GpuTimerScope& operator=(const GpuTimerScope&) = delete;

private:
    GpuTimers* timers_;
    VkCommandBuffer cmd_;
};

}  // namespace dvsgi::gpu
