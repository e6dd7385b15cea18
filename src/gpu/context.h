// The Vulkan instance, the chosen physical device and one logical device with a
// single universal queue. Headless: no surface extension unless asked for.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace dvsgi::gpu {

struct ContextOptions {
    bool validation = false;       // Khronos validation layer + message counting
    std::string deviceName;        // case-insensitive substring; empty = best
    std::vector<const char*> instanceExtensions;  // e.g. surface extensions
    bool swapchain = false;        // enable VK_KHR_swapchain on the device
    bool printDevice = false;      // one line naming the device on stdout
};

struct DeviceFeatures {
    bool conservativeRaster = false;  // VK_EXT_conservative_rasterization
    bool atomicFloat = false;         // shaderImageFloat32AtomicAdd
};

class Context {
public:
    explicit Context(const ContextOptions& options);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;
    VkCommandPool commandPool = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memory{};
    DeviceFeatures features;
    std::string deviceName;

    // Validation messages of severity error seen so far (and warnings, counted
    // apart). Tests assert validationErrors() == 0.
    uint32_t validationErrors() const { return errors_.load(); }
    uint32_t validationWarnings() const { return warnings_.load(); }
    const std::vector<std::string>& validationMessages() const { return messages_; }
    bool validationEnabled() const { return messenger_ != VK_NULL_HANDLE; }

    uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags flags) const;

    // Records commands into a fresh primary command buffer, submits and waits.
    void submitAndWait(const std::function<void(VkCommandBuffer)>& record) const;

    PFN_vkCmdPushDescriptorSetKHR cmdPushDescriptorSet = nullptr;

private:
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    std::atomic<uint32_t> errors_{0};
    std::atomic<uint32_t> warnings_{0};
    std::vector<std::string> messages_;

    static VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                        VkDebugUtilsMessageTypeFlagsEXT,
                                                        const VkDebugUtilsMessengerCallbackDataEXT*, void*);
};

// Every physical device the loader reports, as "name (type)", for messages.
std::vector<std::string> listDevices(VkInstance instance);

}  // namespace dvsgi::gpu
