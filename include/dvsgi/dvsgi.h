// dvsgi: real-time global illumination with deferred voxel shading, as a
// library. This header is the whole public API; it includes nothing of dvsgi's
// internals, only the C++ standard library and <vulkan/vulkan.h>.
//
//   dvsgi::Scene scene = dvsgi::Scene::cornellBox();   // or Scene::load("x.gltf")
//   dvsgi::Settings s;  s.width = s.height = 256;  s.voxels = 64;
//   dvsgi::Renderer r(scene, s);                        // own Vulkan device
//   dvsgi::FrameInfo info = r.render();
//   dvsgi::writeExr("out.exr", r.readImage());
//
// Images are linear radiance in W·m⁻²·sr⁻¹ (no tone mapping), RGBA32F, row 0
// at the top. Every failure throws dvsgi::Error whose message names the file,
// the setting (as "Settings::voxels") or the Vulkan call. Objects are not
// thread-safe; use one Renderer from one thread at a time. docs/API.md has more.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace dvsgi {

struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// "0.1.0": the version of the library that was linked.
std::string version();

// An imported scene: geometry, materials, textures, cameras and lights.
// Cheap to copy (shared, immutable).
class Scene {
public:
    // glTF 2.0 (.gltf/.glb), OBJ (+MTL) or PLY. Scenes without a camera or a
    // light get defaults (docs/UNITS.md). Throws Error naming the file.
    static Scene load(const std::string& path);
    // The built-in Cornell box (the scene of cornell-lights.gltf, compiled in).
    static Scene cornellBox();

    const std::string& source() const;                // path, or "builtin:cornell"
    const std::vector<std::string>& warnings() const; // e.g. a missing texture replaced by its factor
    uint32_t cameraCount() const;                     // placed camera nodes (Settings::camera)
    uint32_t lightCount() const;

private:
    struct Data;
    friend class Renderer;
    explicit Scene(std::shared_ptr<const Data> data) : data_(std::move(data)) {}
    std::shared_ptr<const Data> data_;
};

// Which term of the composition the output image holds.
enum class Output { Full, Direct, Indirect, Specular, AO, Shadow };

// How light is gathered over the voxels: rays walked voxel by voxel through
// the radiance volume, or the cone set through the filtered volumes (the
// paper). A clipmap (clipmapLevels > 0) always traces cones.
enum class Trace { Rays, Cones };

// The common settings. Defaults are those of `dvsgi render`; every other
// renderer parameter keeps the default documented in `dvsgi --help`.
struct Settings {
    uint32_t width = 512, height = 512;  // output size, 1..16384
    uint32_t supersample = 1;            // render k*width x k*height, box-average; 1..8
    uint32_t camera = 0;                 // index among the scene's cameras
    uint32_t voxels = 128;               // N of the N^3 grid: 0 or a power of two in 32..512
    uint32_t clipmapLevels = 0;          // 0 = one grid fitted to the scene; 1..8 levels of N^3 following
                                         // the camera, each twice the voxel of the one before (docs/clipmap.md)
    float clipmapVoxel = 0.0f;           // level 0's voxel edge in metres, 0..1000; 0 = the coarsest level
                                         // holds the whole scene from the starting camera
    int bounces = -1;                    // -1 = converge (auto); K in 0..64 = exactly K per frame
    float bounceConvergence = 0.005f;    // auto: stop when the light still missing is below this
    uint32_t maxBounces = 64;            // auto: give up after this many bounces; 1..1000
    Trace bounceTrace = Trace::Rays;     // the voxel bounce: 8 rays per voxel, or six cones
    Trace gatherTrace = Trace::Rays;     // each pixel's indirect diffuse light: gatherRays rays, or `cones`
    uint32_t gatherRays = 16;            // rays per traced pixel, 1..1024
    uint32_t gatherRayFilter = 3;        // passes of the rays' surface-aware 3x3 filter, taps 1, 2, 4, ... apart; 1..5
    uint32_t cones = 6;                  // diffuse cone set: 6 (60 degrees) or 16
    bool specular = true;                // reflection cone for glossy materials
    bool ao = false;                     // multiply the indirect terms by the cone AO
    float aoLambda = 0.5f;               // AO falloff 1/(1 + lambda r), r in voxels; 0..1000
    float traceScale = 0.5f;             // cone-trace resolution factor, 0.125..1
    uint32_t shadowMapSize = 2048;       // power of two in 256..8192
    Output output = Output::Full;
};

// Choosing a device when the Renderer creates its own.
struct DeviceOptions {
    bool validation = false;   // Khronos validation layer; messages counted (validationErrors())
    std::string deviceName;    // case-insensitive substring of the device name; empty = best
    bool printDevice = false;  // one line naming the device on stdout
};

// A device the application created and keeps owning; dvsgi destroys none of
// these handles (it creates and destroys only its own command pool, resources
// and, with debugUtils, a debug messenger). The device must be Vulkan 1.3 and
// have been created with: geometryShader, fragmentStoresAndAtomics,
// vertexPipelineStoresAndAtomics, shaderDrawParameters, hostQueryReset,
// dynamicRendering, synchronization2, maintenance4, VK_KHR_push_descriptor,
// and (for voxels > 0) VK_EXT_shader_atomic_float with
// shaderImageFloat32Atomics and shaderImageFloat32AtomicAdd. dvsgi submits to
// `queue` and waits for its own fences, so the application must not use the
// queue from another thread during a dvsgi call; destroying the Renderer
// waits for that queue to go idle.
struct ExternalDevice {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;                  // graphics + compute with timestamps
    VkQueue queue = VK_NULL_HANDLE;
    bool shaderImageFloat32AtomicAdd = false;  // enabled as above (required for voxels > 0)
    bool conservativeRasterization = false;    // VK_EXT_conservative_rasterization enabled
    bool samplerAnisotropy = false;            // feature enabled: textures sampled anisotropically
    bool shaderFloat64 = false;                // feature enabled: the compute voxelizer may run (its exact
                                               // test is double precision); without it voxelization rasterizes
    // The instance has VK_EXT_debug_utils enabled (and, typically, the
    // validation layer): dvsgi adds its own messenger and counts messages.
    bool debugUtils = false;
};

// An image of the application's to copy the output into (copyTo).
//   - 2D, one mip level and layer used (level 0, layer 0), created on the
//     Renderer's device, owned by its queue family (or VK_SHARING_MODE_CONCURRENT);
//   - usage includes VK_IMAGE_USAGE_TRANSFER_DST_BIT;
//   - format VK_FORMAT_R32G32B32A32_SFLOAT at the output size: exact copy
//     (vkCmdCopyImage); any other size or format: vkCmdBlitImage (linear
//     filter when the source format allows it), which needs a format with
//     VK_FORMAT_FEATURE_BLIT_DST_BIT (e.g. R16G16B16A16_SFLOAT, R8G8B8A8_UNORM;
//     values stay linear radiance, which UNORM formats clamp to [0, 1]).
// Layouts: the image is in `currentLayout` when copyTo is called (UNDEFINED is
// allowed and discards the contents) and is left in `finalLayout` (not
// UNDEFINED/PREINITIALIZED). Work the application submitted earlier to the
// same queue is complete before the copy writes (the barrier waits on all
// commands); work on other queues must be finished by the application.
// copyTo returns after the copy completed on the GPU.
struct TargetImage {
    VkImage image = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
    uint32_t width = 0, height = 0;
    VkImageLayout currentLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImageLayout finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
};

// Host image: width * height * 4 floats, RGBA, row 0 at the top.
struct Image {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;
};

struct PassTime {
    std::string name;  // e.g. "gbuffer", "voxel bounce" (docs/ARCHITECTURE.md lists them)
    double ms = 0.0;   // GPU time from timestamps
};

struct FrameInfo {
    std::vector<PassTime> passes;  // in recording order; a repeated pass is summed
    double gpuMs = 0.0;            // the whole frame
    uint32_t bounces = 0;          // voxel bounces computed this frame
    bool converged = false;        // auto bounces reached the convergence threshold
};

struct MemoryUse {
    std::string name;  // e.g. "voxel radiance", "g-buffer"
    uint64_t bytes = 0;
};

class Renderer {
public:
    // Creates its own Vulkan instance and device.
    Renderer(const Scene& scene, const Settings& settings = {}, const DeviceOptions& device = {});
    // Renders on the application's device (see ExternalDevice).
    Renderer(const Scene& scene, const Settings& settings, const ExternalDevice& device);
    ~Renderer();
    Renderer(Renderer&&) noexcept;
    Renderer& operator=(Renderer&&) noexcept;

    // Rebuilds the GPU resources for new settings (nothing is kept but the
    // device); the next render() starts from scratch (e.g. converges again).
    void setSettings(const Settings& settings);
    const Settings& settings() const;

    // Renders one frame and waits for it. A later frame with bounces = -1
    // adds one bounce from the previous frame instead of converging again.
    FrameInfo render();
    // The last frame's output (Settings::output) at the output size.
    Image readImage() const;
    // Copies the last frame's output into an application image (TargetImage
    // states the contract). Needs a frame: render() first.
    void copyTo(const TargetImage& target) const;
    // render() then copyTo(target).
    FrameInfo renderTo(const TargetImage& target);

    std::vector<MemoryUse> memory() const;  // GPU memory of every resource group
    std::string deviceName() const;
    // Validation messages of severity error seen on this Renderer's messenger
    // (DeviceOptions::validation, or ExternalDevice::debugUtils); 0 otherwise.
    uint32_t validationErrors() const;
    // Non-fatal problems (scene warnings, a camera aspect that the image overrides).
    std::vector<std::string> warnings() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Writes R, G, B of `image` as an OpenEXR file (ZIP, float or half samples),
// atomically (a temporary file renamed over `path`). Throws Error naming the file.
void writeExr(const std::string& path, const Image& image, bool half = false);

}  // namespace dvsgi
