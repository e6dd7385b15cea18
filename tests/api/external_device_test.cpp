// The public API on an application's own Vulkan device: the test creates the
// instance (validation layer + its own messenger) and device as an embedding
// application would, lets dvsgi render into a VkImage it created, reads that
// image back itself and compares it with dvsgi's host read-back and with a
// render on dvsgi's own device. Only include/dvsgi/dvsgi.h and Vulkan are used.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <dvsgi/dvsgi.h>

namespace {

#define CHECK_VK(call) ASSERT_EQ((call), VK_SUCCESS) << #call

std::atomic<int> g_errors{0};

VKAPI_ATTR VkBool32 VKAPI_CALL countErrors(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                           VkDebugUtilsMessageTypeFlagsEXT,
                                           const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
    if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
        ++g_errors;
        ADD_FAILURE() << "validation: " << (data->pMessage ? data->pMessage : "");
    }
    return VK_FALSE;
}

dvsgi::Settings smallSettings() {
    dvsgi::Settings s;
    s.width = s.height = 32;
    s.voxels = 32;
    return s;
}

double relRmse(const std::vector<float>& a, const std::vector<float>& b) {
    double err = 0.0, ref = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        if (i % 4 == 3) continue;  // RGB only
        err += (double(a[i]) - b[i]) * (double(a[i]) - b[i]);
        ref += double(b[i]) * b[i];
    }
    return std::sqrt(err / ref);
}

// What an application owns: instance, device, queue, and a few helpers to
// create and read back its images.
class AppDevice : public ::testing::Test {
protected:
    void SetUp() override {
        g_errors = 0;
        const char* layer = "VK_LAYER_KHRONOS_validation";
        const char* ext = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
        VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
        app.apiVersion = VK_API_VERSION_1_3;
        VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
        ici.pApplicationInfo = &app;
        ici.enabledLayerCount = 1;
        ici.ppEnabledLayerNames = &layer;
        ici.enabledExtensionCount = 1;
        ici.ppEnabledExtensionNames = &ext;
        CHECK_VK(vkCreateInstance(&ici, nullptr, &instance));
        VkDebugUtilsMessengerCreateInfoEXT mi{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
        mi.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
        mi.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT;
        mi.pfnUserCallback = countErrors;
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
        CHECK_VK(create(instance, &mi, nullptr, &messenger));

        uint32_t n = 0;
        vkEnumeratePhysicalDevices(instance, &n, nullptr);
        std::vector<VkPhysicalDevice> devices(n);
        vkEnumeratePhysicalDevices(instance, &n, devices.data());
        // The device dvsgi would pick for itself (discrete > integrated > virtual > CPU),
        // so the comparison with its own device compares one driver with itself.
        const auto rank = [](VkPhysicalDeviceType t) {
            return t == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU     ? 4
                   : t == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU ? 3
                   : t == VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU    ? 2
                   : t == VK_PHYSICAL_DEVICE_TYPE_CPU            ? 1
                                                                 : 0;
        };
        int best = -1;
        for (VkPhysicalDevice pd : devices) {
            VkPhysicalDeviceProperties p;
            vkGetPhysicalDeviceProperties(pd, &p);
            if (p.apiVersion >= VK_API_VERSION_1_3 && rank(p.deviceType) > best) {
                best = rank(p.deviceType);
                physical = pd;
            }
        }
        ASSERT_NE(physical, VK_NULL_HANDLE) << "no Vulkan 1.3 device";
        vkGetPhysicalDeviceQueueFamilyProperties(physical, &n, nullptr);
        std::vector<VkQueueFamilyProperties> families(n);
        vkGetPhysicalDeviceQueueFamilyProperties(physical, &n, families.data());
        family = UINT32_MAX;
        for (uint32_t i = 0; i < n && family == UINT32_MAX; ++i)
            if ((families[i].queueFlags & (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) ==
                    (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT) &&
                families[i].timestampValidBits)
                family = i;
        ASSERT_NE(family, UINT32_MAX);

        // Exactly the features dvsgi.h lists for an ExternalDevice, and
        // shaderFloat64 where supported, as dvsgi's own device: the same voxelizer on both.
        VkPhysicalDeviceFeatures supported;
        vkGetPhysicalDeviceFeatures(physical, &supported);
        float64 = supported.shaderFloat64;
        VkPhysicalDeviceShaderAtomicFloatFeaturesEXT atomic{
            VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
        atomic.shaderImageFloat32Atomics = atomic.shaderImageFloat32AtomicAdd = VK_TRUE;
        VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES, &atomic};
        f13.dynamicRendering = f13.synchronization2 = f13.maintenance4 = VK_TRUE;
        VkPhysicalDeviceVulkan12Features f12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &f13};
        f12.hostQueryReset = VK_TRUE;
        VkPhysicalDeviceVulkan11Features f11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES, &f12};
        f11.shaderDrawParameters = VK_TRUE;
        VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &f11};
        f2.features.geometryShader = f2.features.fragmentStoresAndAtomics = VK_TRUE;
        f2.features.vertexPipelineStoresAndAtomics = VK_TRUE;
        f2.features.shaderFloat64 = float64;
        const char* exts[] = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME, VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME};
        const float priority = 1.0f;
        VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        qci.queueFamilyIndex = family;
        qci.queueCount = 1;
        qci.pQueuePriorities = &priority;
        VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &f2};
        dci.queueCreateInfoCount = 1;
        dci.pQueueCreateInfos = &qci;
        dci.enabledExtensionCount = 2;
        dci.ppEnabledExtensionNames = exts;
        CHECK_VK(vkCreateDevice(physical, &dci, nullptr, &device));
        vkGetDeviceQueue(device, family, 0, &queue);
        VkCommandPoolCreateInfo cpi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        cpi.queueFamilyIndex = family;
        CHECK_VK(vkCreateCommandPool(device, &cpi, nullptr, &pool));
    }

    void TearDown() override {
        // dvsgi must have left every handle alive: destroying them here after
        // its Renderer is gone is valid only if it did not destroy them itself.
        for (auto& [image, memory] : images) {
            vkDestroyImage(device, image, nullptr);
            vkFreeMemory(device, memory, nullptr);
        }
        if (pool) vkDestroyCommandPool(device, pool, nullptr);
        if (device) vkDestroyDevice(device, nullptr);
        if (messenger) {
            auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
                vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
            destroy(instance, messenger, nullptr);
        }
        if (instance) vkDestroyInstance(instance, nullptr);
        EXPECT_EQ(g_errors.load(), 0) << "Vulkan validation errors";
    }

    dvsgi::ExternalDevice external() const {
        dvsgi::ExternalDevice e;
        e.instance = instance;
        e.physicalDevice = physical;
        e.device = device;
        e.queueFamily = family;
        e.queue = queue;
        e.shaderImageFloat32AtomicAdd = true;
        e.shaderFloat64 = float64 == VK_TRUE;
        e.debugUtils = true;
        return e;
    }

    uint32_t memoryType(uint32_t bits, VkMemoryPropertyFlags flags) const {
        VkPhysicalDeviceMemoryProperties mp;
        vkGetPhysicalDeviceMemoryProperties(physical, &mp);
        for (uint32_t i = 0; i < mp.memoryTypeCount; ++i)
            if ((bits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & flags) == flags) return i;
        return UINT32_MAX;
    }

    VkImage makeImage(VkFormat format, uint32_t w, uint32_t h) {
        VkImageCreateInfo ci{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        ci.imageType = VK_IMAGE_TYPE_2D;
        ci.format = format;
        ci.extent = {w, h, 1};
        ci.mipLevels = ci.arrayLayers = 1;
        ci.samples = VK_SAMPLE_COUNT_1_BIT;
        ci.tiling = VK_IMAGE_TILING_OPTIMAL;
        ci.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        VkImage image = VK_NULL_HANDLE;
        EXPECT_EQ(vkCreateImage(device, &ci, nullptr, &image), VK_SUCCESS);
        VkMemoryRequirements req;
        vkGetImageMemoryRequirements(device, image, &req);
        VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        ai.allocationSize = req.size;
        ai.memoryTypeIndex = memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        VkDeviceMemory memory = VK_NULL_HANDLE;
        EXPECT_EQ(vkAllocateMemory(device, &ai, nullptr, &memory), VK_SUCCESS);
        EXPECT_EQ(vkBindImageMemory(device, image, memory, 0), VK_SUCCESS);
        images.emplace_back(image, memory);
        return image;
    }

    // The application's own read-back of an image dvsgi left in TRANSFER_SRC_OPTIMAL.
    std::vector<uint8_t> readBack(VkImage image, uint32_t w, uint32_t h, uint32_t texelBytes) {
        const VkDeviceSize bytes = VkDeviceSize(w) * h * texelBytes;
        VkBufferCreateInfo bi{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
        bi.size = bytes;
        bi.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        VkBuffer buffer;
        EXPECT_EQ(vkCreateBuffer(device, &bi, nullptr, &buffer), VK_SUCCESS);
        VkMemoryRequirements req;
        vkGetBufferMemoryRequirements(device, buffer, &req);
        VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        ai.allocationSize = req.size;
        ai.memoryTypeIndex = memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                                VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        VkDeviceMemory memory;
        EXPECT_EQ(vkAllocateMemory(device, &ai, nullptr, &memory), VK_SUCCESS);
        vkBindBufferMemory(device, buffer, memory, 0);

        VkCommandBufferAllocateInfo cai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        cai.commandPool = pool;
        cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        cai.commandBufferCount = 1;
        VkCommandBuffer cmd;
        vkAllocateCommandBuffers(device, &cai, &cmd);
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        vkBeginCommandBuffer(cmd, &begin);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {w, h, 1};
        vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &region);
        VkMemoryBarrier2 mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
        mb.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
        mb.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        mb.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
        mb.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
        VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dep.memoryBarrierCount = 1;
        dep.pMemoryBarriers = &mb;
        vkCmdPipelineBarrier2(cmd, &dep);
        vkEndCommandBuffer(cmd);
        VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        si.commandBufferCount = 1;
        si.pCommandBuffers = &cmd;
        EXPECT_EQ(vkQueueSubmit(queue, 1, &si, VK_NULL_HANDLE), VK_SUCCESS);
        vkQueueWaitIdle(queue);
        std::vector<uint8_t> out(bytes);
        void* mapped = nullptr;
        vkMapMemory(device, memory, 0, bytes, 0, &mapped);
        std::memcpy(out.data(), mapped, bytes);
        vkUnmapMemory(device, memory);
        vkFreeCommandBuffers(device, pool, 1, &cmd);
        vkDestroyBuffer(device, buffer, nullptr);
        vkFreeMemory(device, memory, nullptr);
        return out;
    }

    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    uint32_t family = 0;
    VkBool32 float64 = VK_FALSE;  // shaderFloat64 enabled (when supported)
    VkQueue queue = VK_NULL_HANDLE;
    VkCommandPool pool = VK_NULL_HANDLE;
    std::vector<std::pair<VkImage, VkDeviceMemory>> images;
};

TEST_F(AppDevice, RendersIntoTheApplicationsImage) {
    const dvsgi::Scene scene = dvsgi::Scene::cornellBox();
    const dvsgi::Settings settings = smallSettings();
    const VkImage exact = makeImage(VK_FORMAT_R32G32B32A32_SFLOAT, 32, 32);
    const VkImage half = makeImage(VK_FORMAT_R16G16B16A16_SFLOAT, 16, 16);
    dvsgi::Image host;
    {
        dvsgi::Renderer renderer(scene, settings, external());
        EXPECT_THROW(renderer.copyTo({exact, VK_FORMAT_R32G32B32A32_SFLOAT, 32, 32}), dvsgi::Error)
            << "copyTo before any frame";
        renderer.renderTo({exact, VK_FORMAT_R32G32B32A32_SFLOAT, 32, 32, VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL});
        // A blit into another format and size, from a layout the app chose.
        renderer.copyTo({half, VK_FORMAT_R16G16B16A16_SFLOAT, 16, 16, VK_IMAGE_LAYOUT_UNDEFINED,
                         VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL});
        host = renderer.readImage();
        EXPECT_EQ(renderer.validationErrors(), 0u);
    }
    // The renderer is gone; the app's device must still work (TearDown uses it).
    ASSERT_EQ(host.width, 32u);
    ASSERT_EQ(host.rgba.size(), 32u * 32u * 4u);

    const std::vector<uint8_t> bytes = readBack(exact, 32, 32, 16);
    std::vector<float> copied(32 * 32 * 4);
    std::memcpy(copied.data(), bytes.data(), bytes.size());
    for (size_t i = 0; i < copied.size(); ++i)
        if (i % 4 != 3) {
            ASSERT_EQ(copied[i], host.rgba[i]) << "float " << i << " of the exact copy";
        }

    double mean = 0.0;
    for (size_t i = 0; i < copied.size(); i += 4) mean += copied[i + 1];
    EXPECT_GT(mean / (32 * 32), 0.01) << "the copied frame is black";

    // 2:1 linear blit = the 2x2 average (each sample falls between four texels), in half precision.
    const std::vector<uint8_t> halfBytes = readBack(half, 16, 16, 8);
    double worstBlit = 0.0;
    for (uint32_t y = 0; y < 16; ++y)
        for (uint32_t x = 0; x < 16; ++x)
            for (uint32_t c = 0; c < 3; ++c) {
                float avg = 0.0f;
                for (uint32_t j = 0; j < 2; ++j)
                    for (uint32_t i = 0; i < 2; ++i) avg += 0.25f * host.rgba[((2 * y + j) * 32 + 2 * x + i) * 4 + c];
                uint16_t h;
                std::memcpy(&h, halfBytes.data() + ((y * 16 + x) * 4 + c) * 2, 2);
                // IEEE half -> float (normal numbers and zero suffice for radiance here).
                const int e = (h >> 10) & 31;
                const float v = e == 0 ? std::ldexp(float(h & 1023), -24)
                                       : std::ldexp(1.0f + float(h & 1023) / 1024.0f, e - 15);
                if (avg > 1e-3f) worstBlit = std::max(worstBlit, double(std::abs(v - avg) / avg));
                // Half rounding moves a value by up to 9.8e-4 of it (measured 9.57e-4).
                EXPECT_NEAR(v, avg, 1.5e-3f * std::max(avg, 1e-3f) + 1e-6f) << "blit pixel " << x << "," << y;
            }
    std::printf("  2:1 half blit: worst relative error %.2e against the 2x2 average\n", worstBlit);
}

TEST_F(AppDevice, MatchesARenderOnDvsgisOwnDevice) {
    const dvsgi::Scene scene = dvsgi::Scene::cornellBox();
    const dvsgi::Settings settings = smallSettings();
    dvsgi::Image app, own;
    {
        dvsgi::Renderer renderer(scene, settings, external());
        renderer.render();
        app = renderer.readImage();
    }
    {
        dvsgi::DeviceOptions options;
        options.validation = true;
        dvsgi::Renderer renderer(scene, settings, options);
        renderer.render();
        own = renderer.readImage();
        EXPECT_EQ(renderer.validationErrors(), 0u);
    }
    // Float atomics in voxelization may add in another order: not bit-exact on
    // a GPU (lavapipe gives 0; the bound is for that reordering, unmeasured).
    const double e = relRmse(app.rgba, own.rgba);
    std::printf("  application's device against dvsgi's: relative RMSE %.2e\n", e);
    EXPECT_LT(e, 1e-4);
}

// The tracing choices reach the renderer: each one changes the image, and
// their defaults are the ones `dvsgi render` has (embed_install.py renders
// the defaults both ways).
TEST_F(AppDevice, TraceSettingsChangeTheImage) {
    const dvsgi::Scene scene = dvsgi::Scene::cornellBox();
    dvsgi::Settings s = smallSettings();
    s.bounces = 1;
    auto image = [&](const dvsgi::Settings& settings) {
        dvsgi::Renderer renderer(scene, settings, external());
        renderer.render();
        return renderer.readImage().rgba;
    };
    const std::vector<float> base = image(s);
    std::vector<std::pair<const char*, dvsgi::Settings>> variants;
    dvsgi::Settings v = s;
    v.gatherTrace = dvsgi::Trace::Cones;
    variants.push_back({"gatherTrace cones", v});
    v = s;
    v.bounceTrace = dvsgi::Trace::Cones;
    variants.push_back({"bounceTrace cones", v});
    v = s;
    v.gatherRays = 4;
    variants.push_back({"gatherRays 4", v});
    v = s;
    v.gatherRayFilter = 1;
    variants.push_back({"gatherRayFilter 1", v});
    for (const auto& [name, settings] : variants) {
        const double e = relRmse(image(settings), base);
        std::printf("  %s against the defaults: relative RMSE %.2e\n", name, e);
        EXPECT_GT(e, 1e-3) << name;
    }
}

TEST_F(AppDevice, ErrorsNameTheSetting) {
    const dvsgi::Scene scene = dvsgi::Scene::cornellBox();
    auto message = [&](dvsgi::Settings s) -> std::string {
        try {
            dvsgi::Renderer renderer(scene, s, external());
        } catch (const dvsgi::Error& e) {
            return e.what();
        }
        return "<no error>";
    };
    dvsgi::Settings s = smallSettings();
    s.voxels = 100;
    EXPECT_NE(message(s).find("Settings::voxels"), std::string::npos) << message(s);
    s = smallSettings();
    s.camera = 5;
    EXPECT_NE(message(s).find("Settings::camera"), std::string::npos) << message(s);
    s = smallSettings();
    s.cones = 7;
    EXPECT_NE(message(s).find("Settings::cones"), std::string::npos) << message(s);
    s = smallSettings();
    s.clipmapLevels = 9;
    EXPECT_NE(message(s).find("Settings::clipmapLevels"), std::string::npos) << message(s);
    s = smallSettings();
    s.clipmapVoxel = -1.0f;
    EXPECT_NE(message(s).find("Settings::clipmapVoxel"), std::string::npos) << message(s);
    s = smallSettings();
    s.gatherRays = 0;
    EXPECT_NE(message(s).find("Settings::gatherRays"), std::string::npos) << message(s);
    s = smallSettings();
    s.gatherRayFilter = 6;
    EXPECT_NE(message(s).find("Settings::gatherRayFilter"), std::string::npos) << message(s);
    s = smallSettings();
    s.bounceTrace = dvsgi::Trace(7);
    EXPECT_NE(message(s).find("Settings::bounceTrace"), std::string::npos) << message(s);
    s = smallSettings();
    s.clipmapLevels = 2;
    EXPECT_EQ(message(s), "<no error>");

    dvsgi::Renderer renderer(scene, smallSettings(), external());
    renderer.render();
    try {
        renderer.copyTo({VK_NULL_HANDLE, VK_FORMAT_R32G32B32A32_SFLOAT, 32, 32});
        ADD_FAILURE() << "no error for a null image";
    } catch (const dvsgi::Error& e) {
        EXPECT_NE(std::string(e.what()).find("TargetImage::image"), std::string::npos) << e.what();
    }
    // A bad setSettings keeps the working renderer.
    s = smallSettings();
    s.traceScale = 2.0f;
    EXPECT_THROW(renderer.setSettings(s), dvsgi::Error);
    EXPECT_EQ(renderer.settings().traceScale, smallSettings().traceScale);
    EXPECT_NO_THROW(renderer.render());
    try {
        dvsgi::DeviceOptions options;
        options.deviceName = "no-such-gpu";
        dvsgi::Renderer own(scene, smallSettings(), options);
        ADD_FAILURE() << "no error for an unknown device name";
    } catch (const dvsgi::Error& e) {
        EXPECT_NE(std::string(e.what()).find("DeviceOptions::deviceName"), std::string::npos) << e.what();
    }
    try {
        dvsgi::Scene::load("/nonexistent/scene.gltf");
        ADD_FAILURE() << "no error for a missing file";
    } catch (const dvsgi::Error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/scene.gltf"), std::string::npos) << e.what();
    }
}

}  // namespace
