// Error handling for Vulkan calls: every failing call becomes a GpuError whose
// message names the call and the VkResult, so the CLI can print one clear line.
#pragma once

#include <stdexcept>
#include <string>

#include <vulkan/vulkan.h>

namespace dvsgi::gpu {

struct GpuError : std::runtime_error {
    VkResult result;
    GpuError(const std::string& what, VkResult r) : std::runtime_error(what), result(r) {}
};

const char* resultName(VkResult r);
[[noreturn]] void throwVkError(const char* call, VkResult r);

}  // namespace dvsgi::gpu

#define VK_CHECK(call)                                                    \
    do {                                                                  \
        VkResult vk_check_result_ = (call);                               \
        if (vk_check_result_ != VK_SUCCESS)                               \
            ::dvsgi::gpu::throwVkError(#call, vk_check_result_);          \
    } while (0)
