#include "gpu/timers.h"

#include <stdexcept>

#include "gpu/check.h"
#include "gpu/context.h"

namespace dvsgi::gpu {

GpuTimers::GpuTimers(const Context& ctx, uint32_t maxScopes) : ctx_(ctx), maxScopes_(maxScopes) {
    VkQueryPoolCreateInfo ci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    ci.queryType = VK_QUERY_TYPE_TIMESTAMP;
    ci.queryCount = maxScopes * 2;
    VK_CHECK(vkCreateQueryPool(ctx.device, &ci, nullptr, &pool_));
    reset();
}

GpuTimers::~GpuTimers() { vkDestroyQueryPool(ctx_.device, pool_, nullptr); }

void GpuTimers::reset() {
    vkResetQueryPool(ctx_.device, pool_, 0, maxScopes_ * 2);
    names_.clear();
    open_.clear();
    used_ = 0;
}

void GpuTimers::begin(VkCommandBuffer cmd, const std::string& name) {
    if (used_ >= maxScopes_) throw std::runtime_error("GpuTimers: more than " + std::to_string(maxScopes_) + " scopes");
    names_.push_back(name);
    open_.push_back(used_);
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, pool_, used_ * 2);
    ++used_;
    ctx_.beginLabel(cmd, name.c_str());
}

void GpuTimers::end(VkCommandBuffer cmd) {
    if (open_.empty()) throw std::runtime_error("GpuTimers::end without begin");
    ctx_.endLabel(cmd);
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, pool_, open_.back() * 2 + 1);
    open_.pop_back();
}

std::vector<TimerResult> GpuTimers::results() const {
    std::vector<TimerResult> out;
    if (used_ == 0) return out;
    std::vector<uint64_t> ticks(used_ * 2);
    VK_CHECK(vkGetQueryPoolResults(ctx_.device, pool_, 0, used_ * 2, ticks.size() * sizeof(uint64_t), ticks.data(),
                                   sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    const double msPerTick = ctx_.properties.limits.timestampPeriod * 1e-6;
    for (uint32_t i = 0; i < used_; ++i) {
        const double ms = double(ticks[i * 2 + 1] - ticks[i * 2]) * msPerTick;
        bool merged = false;
        for (TimerResult& r : out)
            if (r.name == names_[i]) {
                r.ms += ms;
                merged = true;
            }
        if (!merged) out.push_back({names_[i], ms});
    }
    return out;
}

}  // namespace dvsgi::gpu
