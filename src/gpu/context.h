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
    // With validation: the layer's synchronization validation as well, so a
    // missing or too weak barrier is a validation error (SYNC-HAZARD-*) rather
    // than a race that lavapipe's in-order execution hides.
    bool syncValidation = true;
    std::string deviceName;        // case-insensitive substring; empty = best
    std::vector<const char*> instanceExtensions;  // e.g. surface extensions
    bool swapchain = false;        // enable VK_KHR_swapchain on the device
    bool printDevice = false;      // one line naming the device on stdout
};

// Vulkan objects that an embedding application created and keeps owning. The
// Context uses them and destroys none of them. The device must have been
// created with API version 1.3 and what dvsgi needs (see requiredFeatures()).
struct ExternalDevice {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;  // graphics + compute, with timestamps
    VkQueue queue = VK_NULL_HANDLE;
    // What the application enabled beyond the required set: a device's enabled
    // features cannot be queried, so the caller states them.
    bool shaderImageFloat32AtomicAdd = false;  // VK_EXT_shader_atomic_float (voxels need it)
    bool conservativeRasterization = false;    // VK_EXT_conservative_rasterization
    bool samplerAnisotropy = false;            // textures are sampled anisotropically only then
    bool shaderFloat64 = false;                // the compute voxelizer may run
    // The instance has VK_EXT_debug_utils enabled: the Context then installs its
    // own messenger and counts validation messages as it does for its own instance.
    bool debugUtils = false;
};

struct DeviceFeatures {
    bool conservativeRaster = false;  // VK_EXT_conservative_rasterization
    bool atomicFloat = false;         // shaderImageFloat32AtomicAdd
    bool samplerAnisotropy = false;   // enabled on the device; samplers use anisotropy only then
    bool memoryBudget = false;        // VK_EXT_memory_budget enabled (deviceMemoryUsage() works)
    bool float64 = false;             // shaderFloat64: the compute voxelizer's exact test
};

class Context {
public:
    explicit Context(const ContextOptions& options);
    // Wraps an application's device: only the command pool (and the messenger,
    // with debugUtils) are created here and destroyed with the Context.
    // options.printDevice applies; validation and deviceName do not (the
    // application chose them). Throws GpuError naming what the device lacks.
    Context(const ExternalDevice& external, const ContextOptions& options);
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
    // The part of validationErrors() that synchronization validation raised.
    uint32_t syncHazards() const { return hazards_.load(); }
    bool syncValidationEnabled() const { return syncValidation_; }
    const std::vector<std::string>& validationMessages() const { return messages_; }
    bool validationEnabled() const { return messenger_ != VK_NULL_HANDLE; }

    // With validation on, validation messages show these names and labels
    // next to the handles, so a hazard names the resource and the pass;
    // without validation they do nothing.
    void nameObject(VkObjectType type, uint64_t handle, const char* name) const;
    void beginLabel(VkCommandBuffer cmd, const char* name) const;
    void endLabel(VkCommandBuffer cmd) const;

    uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags flags) const;
    // The driver's own count of bytes in use on device-local heaps (all
    // processes' view of this one, VK_EXT_memory_budget); -1 without the extension.
    int64_t deviceMemoryUsage() const;
    // maxMemoryAllocationSize (Vulkan 1.1): the largest single allocation.
    uint64_t maxAllocationSize = 0;

    // Records commands into a fresh primary command buffer, submits and waits.
    void submitAndWait(const std::function<void(VkCommandBuffer)>& record) const;

    PFN_vkCmdPushDescriptorSetKHR cmdPushDescriptorSet = nullptr;

    bool ownsDevice() const { return ownsDevice_; }

private:
    void checkQueueFamily();
    void finishSetup(const ContextOptions& options);
    void createMessenger();

    bool ownsDevice_ = true;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    PFN_vkSetDebugUtilsObjectNameEXT setObjectName_ = nullptr;
    PFN_vkCmdBeginDebugUtilsLabelEXT beginLabel_ = nullptr;
    PFN_vkCmdEndDebugUtilsLabelEXT endLabel_ = nullptr;
    std::atomic<uint32_t> errors_{0};
    std::atomic<uint32_t> warnings_{0};
    std::atomic<uint32_t> hazards_{0};
    bool syncValidation_ = false;
    std::vector<std::string> messages_;

    static VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                        VkDebugUtilsMessageTypeFlagsEXT,
                                                        const VkDebugUtilsMessengerCallbackDataEXT*, void*);
};

// Device-level features and extensions dvsgi enables on its own devices, and
// that an ExternalDevice must have enabled: names for documentation and messages.
std::vector<std::string> requiredFeatures();

// Every physical device the loader reports, as "name (type)", for messages.
std::vector<std::string> listDevices(VkInstance instance);

}  // namespace dvsgi::gpu
