#include "gpu/context.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <mutex>

#include "gpu/check.h"
#include "gpu/fault.h"

namespace dvsgi::gpu {

const char* resultName(VkResult r) {
    switch (r) {
#define DVSGI_RESULT(x) case x: return #x;
        DVSGI_RESULT(VK_NOT_READY) DVSGI_RESULT(VK_TIMEOUT) DVSGI_RESULT(VK_INCOMPLETE)
        DVSGI_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY) DVSGI_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        DVSGI_RESULT(VK_ERROR_INITIALIZATION_FAILED) DVSGI_RESULT(VK_ERROR_DEVICE_LOST)
        DVSGI_RESULT(VK_ERROR_MEMORY_MAP_FAILED) DVSGI_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
        DVSGI_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT) DVSGI_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
        DVSGI_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER) DVSGI_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
        DVSGI_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED) DVSGI_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
        DVSGI_RESULT(VK_ERROR_SURFACE_LOST_KHR) DVSGI_RESULT(VK_ERROR_OUT_OF_DATE_KHR)
        DVSGI_RESULT(VK_SUBOPTIMAL_KHR) DVSGI_RESULT(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
#undef DVSGI_RESULT
        default: return "VkResult(other)";
    }
}

void throwVkError(const char* call, VkResult r) {
    std::string what = std::string("Vulkan call failed: ") + call + " returned " + resultName(r);
    if (r == VK_ERROR_OUT_OF_DEVICE_MEMORY || r == VK_ERROR_OUT_OF_HOST_MEMORY)
        what += " (out of memory: try fewer voxels or a smaller image)";
    throw GpuError(what, r);
}

namespace {

std::mutex g_messageMutex;

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

const char* typeName(VkPhysicalDeviceType t) {
    switch (t) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete";
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual";
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
        default: return "other";
    }
}

int typeRank(VkPhysicalDeviceType t) {
    switch (t) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
        default: return 0;
    }
}

bool hasLayer(const char* name) {
    uint32_t n = 0;
    vkEnumerateInstanceLayerProperties(&n, nullptr);
    std::vector<VkLayerProperties> layers(n);
    vkEnumerateInstanceLayerProperties(&n, layers.data());
    return std::any_of(layers.begin(), layers.end(),
                       [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool layerHasExtension(const char* layer, const char* name) {
    uint32_t n = 0;
    vkEnumerateInstanceExtensionProperties(layer, &n, nullptr);
    std::vector<VkExtensionProperties> exts(n);
    vkEnumerateInstanceExtensionProperties(layer, &n, exts.data());
    return std::any_of(exts.begin(), exts.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

bool hasDeviceExtension(VkPhysicalDevice pd, const char* name) {
    uint32_t n = 0;
    vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> exts(n);
    vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, exts.data());
    return std::any_of(exts.begin(), exts.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
    uint32_t n = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &n, nullptr));
    std::vector<VkPhysicalDevice> devices(n);
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &n, devices.data()));
    return devices;
}

std::vector<VkQueueFamilyProperties> queueFamilies(VkPhysicalDevice pd) {
    uint32_t n = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, nullptr);
    std::vector<VkQueueFamilyProperties> families(n);
    vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, families.data());
    return families;
}

// Every pass runs on one queue, and the timers need timestamps on it.
bool usableFamily(const VkQueueFamilyProperties& f) {
    const VkQueueFlags want = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    return (f.queueFlags & want) == want && f.timestampValidBits > 0;
}

VkDebugUtilsMessengerCreateInfoEXT messengerCreateInfo(PFN_vkDebugUtilsMessengerCallbackEXT callback, void* user) {
    VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT;
    info.pfnUserCallback = callback;
    info.pUserData = user;
    return info;
}

}  // namespace

std::vector<std::string> requiredFeatures() {
    return {"Vulkan 1.3",
            "geometryShader",
            "fragmentStoresAndAtomics",
            "vertexPipelineStoresAndAtomics",
            "shaderDrawParameters (1.1)",
            "hostQueryReset (1.2)",
            "dynamicRendering (1.3)",
            "synchronization2 (1.3)",
            "maintenance4 (1.3)",
            "VK_KHR_push_descriptor",
            "VK_EXT_shader_atomic_float shaderImageFloat32Atomics + shaderImageFloat32AtomicAdd (for voxels)"};
}

std::vector<std::string> listDevices(VkInstance instance) {
    std::vector<std::string> out;
    for (VkPhysicalDevice pd : physicalDevices(instance)) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(pd, &p);
        out.push_back(std::string(p.deviceName) + " (" + typeName(p.deviceType) + ")");
    }
    return out;
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                      VkDebugUtilsMessageTypeFlagsEXT,
                                                      const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                      void* user) {
    auto* self = static_cast<Context*>(user);
    const bool error = severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    if (error)
        self->errors_++;
    else
        self->warnings_++;
    if (error && data->pMessageIdName && std::strncmp(data->pMessageIdName, "SYNC-", 5) == 0) self->hazards_++;
    std::lock_guard<std::mutex> lock(g_messageMutex);
    if (self->messages_.size() < 64) self->messages_.push_back(data->pMessage ? data->pMessage : "");
    std::fprintf(stderr, "[validation %s] %s\n", error ? "error" : "warning", data->pMessage ? data->pMessage : "");
    return VK_FALSE;
}

Context::Context(const ContextOptions& options) {
    const char* kValidation = "VK_LAYER_KHRONOS_validation";
    std::vector<const char*> layers;
    std::vector<const char*> extensions = options.instanceExtensions;
    if (options.validation) {
        if (!hasLayer(kValidation))
            throw GpuError("validate: the Khronos validation layer is not installed "
                           "(Debian package vulkan-validationlayers)", VK_ERROR_LAYER_NOT_PRESENT);
        layers.push_back(kValidation);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        // The layer implements VK_EXT_validation_features itself; a layer too
        // old for it validates without the synchronization checks.
        syncValidation_ = options.syncValidation &&
                          layerHasExtension(kValidation, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
        if (syncValidation_) extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    }

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "dvsgi";
    app.pEngineName = "dvsgi";
    app.apiVersion = VK_API_VERSION_1_3;

    VkDebugUtilsMessengerCreateInfoEXT messengerInfo = messengerCreateInfo(&Context::debugCallback, this);

    VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ici.pApplicationInfo = &app;
    ici.enabledLayerCount = uint32_t(layers.size());
    ici.ppEnabledLayerNames = layers.data();
    ici.enabledExtensionCount = uint32_t(extensions.size());
    ici.ppEnabledExtensionNames = extensions.data();
    if (options.validation) ici.pNext = &messengerInfo;  // also catches instance creation issues
    const VkValidationFeatureEnableEXT syncFeature = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT validationFeatures{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    validationFeatures.enabledValidationFeatureCount = 1;
    validationFeatures.pEnabledValidationFeatures = &syncFeature;
    if (syncValidation_) {
        validationFeatures.pNext = ici.pNext;
        ici.pNext = &validationFeatures;
    }
    VkResult r = vkCreateInstance(&ici, nullptr, &instance);
    if (r == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw GpuError("no Vulkan 1.3 driver found (install mesa-vulkan-drivers for the software driver)", r);
    VK_CHECK(r);

    if (options.validation) createMessenger();

    // Pick the device: a named one if asked, else the best type that speaks 1.3.
    std::vector<VkPhysicalDevice> candidates = physicalDevices(instance);
    if (candidates.empty()) throw GpuError("no Vulkan device found (install mesa-vulkan-drivers)", VK_ERROR_INITIALIZATION_FAILED);
    int bestRank = -1;
    for (VkPhysicalDevice pd : candidates) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(pd, &p);
        if (p.apiVersion < VK_API_VERSION_1_3) continue;
        if (!options.deviceName.empty() && lower(p.deviceName).find(lower(options.deviceName)) == std::string::npos)
            continue;
        if (typeRank(p.deviceType) > bestRank) {
            bestRank = typeRank(p.deviceType);
            physical = pd;
        }
    }
    if (physical == VK_NULL_HANDLE) {
        std::string names;
        for (const std::string& n : listDevices(instance)) names += (names.empty() ? "" : ", ") + n;
        throw GpuError(options.deviceName.empty()
                           ? "no Vulkan 1.3 device found; devices: " + names
                           : "device: no Vulkan 1.3 device matches '" + options.deviceName + "'; devices: " + names,
                       VK_ERROR_INITIALIZATION_FAILED);
    }
    vkGetPhysicalDeviceProperties(physical, &properties);
    deviceName = properties.deviceName;

    const std::vector<VkQueueFamilyProperties> families = queueFamilies(physical);
    queueFamily = UINT32_MAX;
    for (uint32_t i = 0; i < families.size(); ++i)
        if (usableFamily(families[i])) {
            queueFamily = i;
            break;
        }
    if (queueFamily == UINT32_MAX)
        throw GpuError(deviceName + ": no graphics+compute queue with timestamps", VK_ERROR_FEATURE_NOT_PRESENT);

    // Features: check what we need, enable optional ones the device has.
    VkPhysicalDeviceShaderAtomicFloatFeaturesEXT atomicFloat{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
    VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceVulkan12Features f12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceVulkan11Features f11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
    VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    const bool hasAtomicFloat = hasDeviceExtension(physical, VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME);
    f2.pNext = &f11;
    f11.pNext = &f12;
    f12.pNext = &f13;
    if (hasAtomicFloat) f13.pNext = &atomicFloat;
    vkGetPhysicalDeviceFeatures2(physical, &f2);

    struct Need { const char* name; VkBool32 have; };
    const Need needs[] = {
        {"geometryShader", f2.features.geometryShader},
        {"fragmentStoresAndAtomics", f2.features.fragmentStoresAndAtomics},
        {"vertexPipelineStoresAndAtomics", f2.features.vertexPipelineStoresAndAtomics},
        {"shaderDrawParameters", f11.shaderDrawParameters},
        {"hostQueryReset", f12.hostQueryReset},
        {"dynamicRendering", f13.dynamicRendering},
        {"synchronization2", f13.synchronization2},
        {"maintenance4", f13.maintenance4},
    };
    for (const Need& n : needs)
        if (!n.have)
            throw GpuError(deviceName + " lacks the Vulkan feature " + n.name + " that dvsgi needs",
                           VK_ERROR_FEATURE_NOT_PRESENT);
    std::vector<const char*> deviceExtensions = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
    if (!hasDeviceExtension(physical, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME))
        throw GpuError(deviceName + " lacks VK_KHR_push_descriptor that dvsgi needs", VK_ERROR_EXTENSION_NOT_PRESENT);
    if (options.swapchain) deviceExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    features.atomicFloat = hasAtomicFloat && atomicFloat.shaderImageFloat32AtomicAdd;
    if (features.atomicFloat) deviceExtensions.push_back(VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME);
    features.conservativeRaster = hasDeviceExtension(physical, VK_EXT_CONSERVATIVE_RASTERIZATION_EXTENSION_NAME);
    if (features.conservativeRaster) deviceExtensions.push_back(VK_EXT_CONSERVATIVE_RASTERIZATION_EXTENSION_NAME);
    // Only for reporting (the soak's device-memory series); costs nothing when absent.
    features.memoryBudget = hasDeviceExtension(physical, VK_EXT_MEMORY_BUDGET_EXTENSION_NAME);
    if (features.memoryBudget) deviceExtensions.push_back(VK_EXT_MEMORY_BUDGET_EXTENSION_NAME);

    // Enable exactly what the shaders use, not everything the device offers.
    VkPhysicalDeviceShaderAtomicFloatFeaturesEXT atomicOn{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
    atomicOn.shaderImageFloat32Atomics = features.atomicFloat;
    atomicOn.shaderImageFloat32AtomicAdd = features.atomicFloat;
    VkPhysicalDeviceVulkan13Features on13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    on13.dynamicRendering = VK_TRUE;
    on13.synchronization2 = VK_TRUE;
    on13.maintenance4 = VK_TRUE;
    if (features.atomicFloat) on13.pNext = &atomicOn;
    VkPhysicalDeviceVulkan12Features on12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    on12.hostQueryReset = VK_TRUE;
    on12.pNext = &on13;
    VkPhysicalDeviceVulkan11Features on11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
    on11.shaderDrawParameters = VK_TRUE;
    on11.pNext = &on12;
    VkPhysicalDeviceFeatures2 on{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    on.pNext = &on11;
    on.features.geometryShader = VK_TRUE;
    on.features.fragmentStoresAndAtomics = VK_TRUE;
    on.features.vertexPipelineStoresAndAtomics = VK_TRUE;
    on.features.samplerAnisotropy = f2.features.samplerAnisotropy;
    features.samplerAnisotropy = f2.features.samplerAnisotropy;
    on.features.multiDrawIndirect = f2.features.multiDrawIndirect;
    on.features.shaderFloat64 = f2.features.shaderFloat64;
    features.float64 = f2.features.shaderFloat64;

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qci.queueFamilyIndex = queueFamily;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    dci.pNext = &on;
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    dci.enabledExtensionCount = uint32_t(deviceExtensions.size());
    dci.ppEnabledExtensionNames = deviceExtensions.data();
    VK_CHECK(vkCreateDevice(physical, &dci, nullptr, &device));
    vkGetDeviceQueue(device, queueFamily, 0, &queue);
    finishSetup(options);
}

Context::Context(const ExternalDevice& external, const ContextOptions& options) : ownsDevice_(false) {
    if (!external.instance || !external.physical || !external.device || !external.queue)
        throw GpuError("external device: instance, physical device, device and queue must all be set",
                       VK_ERROR_INITIALIZATION_FAILED);
    instance = external.instance;
    physical = external.physical;
    device = external.device;
    queue = external.queue;
    queueFamily = external.queueFamily;
    vkGetPhysicalDeviceProperties(physical, &properties);
    deviceName = properties.deviceName;
    if (properties.apiVersion < VK_API_VERSION_1_3)
        throw GpuError("external device: " + deviceName + " does not support Vulkan 1.3",
                       VK_ERROR_INCOMPATIBLE_DRIVER);
    const std::vector<VkQueueFamilyProperties> families = queueFamilies(physical);
    if (queueFamily >= families.size() || !usableFamily(families[queueFamily]))
        throw GpuError("external device: queue family " + std::to_string(queueFamily) +
                           " is not a graphics+compute family with timestamps",
                       VK_ERROR_FEATURE_NOT_PRESENT);
    features.atomicFloat = external.shaderImageFloat32AtomicAdd;
    features.conservativeRaster = external.conservativeRasterization;
    features.samplerAnisotropy = external.samplerAnisotropy;
    features.float64 = external.shaderFloat64;
    if (external.debugUtils) createMessenger();
    finishSetup(options);
}

// Shared by both constructors once instance, device and queue are known.
void Context::finishSetup(const ContextOptions& options) {
    vkGetPhysicalDeviceMemoryProperties(physical, &memory);
    VkPhysicalDeviceVulkan11Properties p11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_PROPERTIES};
    VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    p2.pNext = &p11;
    vkGetPhysicalDeviceProperties2(physical, &p2);
    maxAllocationSize = p11.maxMemoryAllocationSize;
    cmdPushDescriptorSet = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
        vkGetDeviceProcAddr(device, "vkCmdPushDescriptorSetKHR"));
    // Null when the extension was not enabled: every pass binds through it.
    if (!cmdPushDescriptorSet)
        throw GpuError(deviceName + ": VK_KHR_push_descriptor is not enabled on the device",
                       VK_ERROR_EXTENSION_NOT_PRESENT);

    if (messenger_) {
        setObjectName_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
            vkGetInstanceProcAddr(instance, "vkSetDebugUtilsObjectNameEXT"));
        beginLabel_ = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
            vkGetInstanceProcAddr(instance, "vkCmdBeginDebugUtilsLabelEXT"));
        endLabel_ = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
            vkGetInstanceProcAddr(instance, "vkCmdEndDebugUtilsLabelEXT"));
    }

    VkCommandPoolCreateInfo cpi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    cpi.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    cpi.queueFamilyIndex = queueFamily;
    VK_CHECK(vkCreateCommandPool(device, &cpi, nullptr, &commandPool));

    if (options.printDevice)
        std::printf("device: %s (%s)%s\n", deviceName.c_str(), typeName(properties.deviceType),
                    !messenger_ ? "" : syncValidation_ ? ", validation on (with synchronization)" : ", validation on");
}

void Context::createMessenger() {
    const VkDebugUtilsMessengerCreateInfoEXT info = messengerCreateInfo(&Context::debugCallback, this);
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    if (!create)
        throw GpuError("VK_EXT_debug_utils is not enabled on the instance", VK_ERROR_EXTENSION_NOT_PRESENT);
    VK_CHECK(create(instance, &info, nullptr, &messenger_));
}

Context::~Context() {
    if (device) {
        // An application's device may be busy with its own work; wait for ours only.
        if (ownsDevice_)
            vkDeviceWaitIdle(device);
        else
            vkQueueWaitIdle(queue);
        if (commandPool) vkDestroyCommandPool(device, commandPool, nullptr);
        if (ownsDevice_) vkDestroyDevice(device, nullptr);
    }
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(instance, messenger_, nullptr);
    }
    if (instance && ownsDevice_) vkDestroyInstance(instance, nullptr);
}

void Context::nameObject(VkObjectType type, uint64_t handle, const char* name) const {
    if (!setObjectName_ || !handle) return;
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = name;
    setObjectName_(device, &info);
}

void Context::beginLabel(VkCommandBuffer cmd, const char* name) const {
    if (!beginLabel_ || !endLabel_) return;
    VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
    label.pLabelName = name;
    beginLabel_(cmd, &label);
}

void Context::endLabel(VkCommandBuffer cmd) const {
    if (beginLabel_ && endLabel_) endLabel_(cmd);
}

uint32_t Context::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags flags) const {
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags) return i;
    throw GpuError("no Vulkan memory type with the required properties", VK_ERROR_FEATURE_NOT_PRESENT);
}

int64_t Context::deviceMemoryUsage() const {
    if (!features.memoryBudget) return -1;
    VkPhysicalDeviceMemoryBudgetPropertiesEXT budget{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_BUDGET_PROPERTIES_EXT};
    VkPhysicalDeviceMemoryProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_PROPERTIES_2};
    props.pNext = &budget;
    vkGetPhysicalDeviceMemoryProperties2(physical, &props);
    int64_t used = 0;
    for (uint32_t i = 0; i < props.memoryProperties.memoryHeapCount; ++i)
        if (props.memoryProperties.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            used += int64_t(budget.heapUsage[i]);
    return used;
}

void Context::submitAndWait(const std::function<void(VkCommandBuffer)>& record) const {
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = commandPool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    VkCommandBuffer cmd;
    VK_CHECK(vkAllocateCommandBuffers(device, &ai, &cmd));
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cmd, &bi));
    record(cmd);
    VK_CHECK(vkEndCommandBuffer(cmd));

    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    VK_CHECK(vkCreateFence(device, &fi, nullptr, &fence));
    VkCommandBufferSubmitInfo cbi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    cbi.commandBuffer = cmd;
    VkSubmitInfo2 si{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    si.commandBufferInfoCount = 1;
    si.pCommandBufferInfos = &cbi;
    VkResult r = fault::submission();
    const char* call = "vkQueueSubmit2";
    if (r == VK_SUCCESS) r = vkQueueSubmit2(queue, 1, &si, fence);
    if (r == VK_SUCCESS) {
        call = "vkWaitForFences";
        r = vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX);
    }
    vkDestroyFence(device, fence, nullptr);
    vkFreeCommandBuffers(device, commandPool, 1, &cmd);
    // A lost device is no setting's fault: say so plainly, since nothing the
    // user changes on the command line brings it back.
    if (r == VK_ERROR_DEVICE_LOST)
        throw GpuError("the Vulkan device (" + deviceName + ") was lost: " + call +
                           " returned VK_ERROR_DEVICE_LOST (the driver or GPU reset or crashed)",
                       r);
    if (r != VK_SUCCESS) throwVkError(call, r);
}

}  // namespace dvsgi::gpu
