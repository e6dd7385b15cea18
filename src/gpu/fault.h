// Test-only fault injection. The environment variable DVSGI_FAULT makes one
// Vulkan call report a failure the driver would report, so the tests can drive
// each device-fault path through the real error handling (docs/RELIABILITY.md,
// "Device faults"). Unset (always, outside tests) every query returns
// VK_SUCCESS after one getenv at the first call.
//
//   DVSGI_FAULT=oom:NAME         allocating an image or buffer whose name contains
//                                NAME returns VK_ERROR_OUT_OF_DEVICE_MEMORY
//   DVSGI_FAULT=device-lost@N    the N-th queue submission (1-based, counted over
//                                the process) returns VK_ERROR_DEVICE_LOST
//   DVSGI_FAULT=swapchain        creating a swapchain returns VK_ERROR_INITIALIZATION_FAILED
//
// Any other value throws GpuError at the first query, so a misspelt fault
// cannot make a test pass without injecting anything.
#pragma once

#include <vulkan/vulkan.h>

namespace dvsgi::gpu::fault {

VkResult allocation(const char* name);  // before vkAllocateMemory
VkResult submission();                  // before vkQueueSubmit2; counts submissions
VkResult swapchain();                   // before vkCreateSwapchainKHR

}  // namespace dvsgi::gpu::fault
