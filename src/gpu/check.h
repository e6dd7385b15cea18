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

// A device allocation that failed. Carries what was being created and the
// device's limits, so the application can name the setting that sized it
// (app/device_faults.cpp) instead of a bare VkResult.
struct DeviceMemoryError : GpuError {
    std::string resource;         // the image or buffer, e.g. "voxel attributes"
    uint64_t bytes = 0;           // what the allocation asked for
    uint64_t heapBytes = 0;       // size of the heap it was asked from
    uint64_t maxAllocation = 0;   // VkPhysicalDeviceMaintenance3Properties::maxMemoryAllocationSize
    std::string device;
    DeviceMemoryError(const std::string& what, VkResult r) : GpuError(what, r) {}
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
