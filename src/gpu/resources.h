// Move-only owners of Vulkan memory objects. Each owns its memory allocation
// (one allocation per resource keeps ownership obvious; the renderer creates few,
// large resources, far below maxMemoryAllocationCount).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

namespace dvsgi::gpu {

class Context;

enum class MemoryUse { Device, Upload, Readback };

// Every allocation Buffer and Image hold right now, process-wide. The soak
// (`dvsgi soak`) watches these: a leaked resource shows up even on drivers
// without VK_EXT_memory_budget.
struct LiveMemory {
    uint64_t bytes = 0;
    uint64_t allocations = 0;
};
LiveMemory liveDeviceMemory();

// A number no other Buffer or Image of this process ever had: drivers reuse
// Vulkan handle values once an object is destroyed (NVIDIA's often do at
// once), so state kept per resource, such as the tracker's layouts, must not
// be keyed by the handle.
uint64_t nextResourceSerial();

class Buffer {
public:
    Buffer() = default;
    Buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use, const char* name);
    ~Buffer() { reset(); }
    Buffer(Buffer&& o) noexcept { *this = std::move(o); }
    Buffer& operator=(Buffer&& o) noexcept;
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    VkBuffer handle() const { return buffer_; }
    uint64_t serial() const { return serial_; }
    VkDeviceSize size() const { return size_; }
    void* mapped() const { return mapped_; }  // non-null for Upload/Readback
    explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }
    void reset();

private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize size_ = 0;
    VkDeviceSize allocated_ = 0;  // the allocation's size (>= size_), for liveDeviceMemory()
    void* mapped_ = nullptr;
    uint64_t serial_ = 0;
};

struct ImageDesc {
    VkImageType type = VK_IMAGE_TYPE_2D;
    VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
    VkExtent3D extent{1, 1, 1};
    uint32_t mipLevels = 1;
    uint32_t layers = 1;
    VkImageUsageFlags usage = 0;
    const char* name = "image";
};

class Image {
public:
    Image() = default;
    Image(const Context& ctx, const ImageDesc& desc);
    ~Image() { reset(); }
    Image(Image&& o) noexcept { *this = std::move(o); }
    Image& operator=(Image&& o) noexcept;
    Image(const Image&) = delete;
    Image& operator=(const Image&) = delete;

    VkImage handle() const { return image_; }
    uint64_t serial() const { return serial_; }
    VkImageView view() const { return view_; }  // all mips and layers
    VkImageView mipView(uint32_t mip) const { return mipViews_.at(mip); }       // one mip, all layers
    VkImageView layerView(uint32_t layer) const { return layerViews_.at(layer); } // one layer, mip 0 (2D)
    const ImageDesc& desc() const { return desc_; }
    VkImageAspectFlags aspect() const;
    VkDeviceSize memorySize() const { return memorySize_; }
    explicit operator bool() const { return image_ != VK_NULL_HANDLE; }
    void reset();

private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize memorySize_ = 0;
    VkImageView view_ = VK_NULL_HANDLE;
    std::vector<VkImageView> mipViews_;
    std::vector<VkImageView> layerViews_;
    ImageDesc desc_;
    uint64_t serial_ = 0;
};

struct SamplerDesc {
    VkFilter filter = VK_FILTER_LINEAR;
    VkSamplerMipmapMode mipmap = VK_SAMPLER_MIPMAP_MODE_LINEAR;
    VkSamplerAddressMode address = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    bool transparentBorder = false;  // CLAMP_TO_BORDER reads (0,0,0,0) instead of opaque white
    float maxAnisotropy = 1.0f;
};

class Sampler {
public:
    Sampler() = default;
    Sampler(const Context& ctx, const SamplerDesc& desc);
    ~Sampler() { reset(); }
    Sampler(Sampler&& o) noexcept { *this = std::move(o); }
    Sampler& operator=(Sampler&& o) noexcept;
    Sampler(const Sampler&) = delete;
    Sampler& operator=(const Sampler&) = delete;
    VkSampler handle() const { return sampler_; }
    void reset();

private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkSampler sampler_ = VK_NULL_HANDLE;
};

bool isDepthFormat(VkFormat f);

}  // namespace dvsgi::gpu
