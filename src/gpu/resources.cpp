#include "gpu/resources.h"

#include <algorithm>
#include <atomic>

#include "gpu/check.h"
#include "gpu/context.h"
#include "gpu/fault.h"

namespace dvsgi::gpu {

namespace {

std::atomic<uint64_t> g_liveBytes{0}, g_liveAllocations{0};

[[noreturn]] void throwMemoryError(const Context& ctx, const char* name, uint64_t bytes, uint32_t heap,
                                   const std::string& what, VkResult r, uint64_t maxAllocation = 0) {
    DeviceMemoryError e(what, r);
    e.resource = name;
    e.bytes = bytes;
    e.heapBytes = heap < ctx.memory.memoryHeapCount ? ctx.memory.memoryHeaps[heap].size : 0;
    e.maxAllocation = maxAllocation ? maxAllocation : ctx.maxAllocationSize;
    e.device = ctx.deviceName;
    throw e;
}

uint32_t largestDeviceHeap(const Context& ctx) {
    uint32_t best = 0;
    for (uint32_t i = 0; i < ctx.memory.memoryHeapCount; ++i)
        if ((ctx.memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) &&
            ctx.memory.memoryHeaps[i].size > ctx.memory.memoryHeaps[best].size)
            best = i;
    return best;
}

VkDeviceMemory allocate(const Context& ctx, const VkMemoryRequirements& req, VkMemoryPropertyFlags flags,
                        const char* name) {
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    ai.memoryTypeIndex = ctx.findMemoryType(req.memoryTypeBits, flags);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    const uint32_t heap = ctx.memory.memoryTypes[ai.memoryTypeIndex].heapIndex;
    VkResult r = fault::allocation(name);
    // More than the heap holds is invalid usage (VUID-vkAllocateMemory-pAllocateInfo-01713),
    // more than maxMemoryAllocationSize may fail or worse: both are refused here.
    if (r == VK_SUCCESS && (req.size > ctx.memory.memoryHeaps[heap].size ||
                            (ctx.maxAllocationSize > 0 && req.size > ctx.maxAllocationSize)))
        r = VK_ERROR_OUT_OF_DEVICE_MEMORY;
    if (r == VK_SUCCESS) r = vkAllocateMemory(ctx.device, &ai, nullptr, &memory);
    if (r != VK_SUCCESS)
        throwMemoryError(ctx, name, req.size, heap,
                         std::string("out of GPU memory allocating ") + name + " (" + std::to_string(req.size >> 20) +
                             " MiB): " + resultName(r),
                         r);
    g_liveBytes += req.size;
    ++g_liveAllocations;
    return memory;
}

void release(VkDevice device, VkDeviceMemory memory, VkDeviceSize bytes) {
    vkFreeMemory(device, memory, nullptr);
    g_liveBytes -= bytes;
    --g_liveAllocations;
}

// Bytes per texel of the formats dvsgi creates images in; 0 = not listed.
uint64_t texelBytes(VkFormat f) {
    switch (f) {
        case VK_FORMAT_R8_UINT: case VK_FORMAT_R8_UNORM: return 1;
        case VK_FORMAT_R16_SFLOAT: case VK_FORMAT_D16_UNORM: return 2;
        case VK_FORMAT_R32_SFLOAT: case VK_FORMAT_R32_UINT: case VK_FORMAT_R32_SINT: case VK_FORMAT_D32_SFLOAT:
        case VK_FORMAT_R8G8B8A8_UNORM: case VK_FORMAT_R8G8B8A8_SRGB: case VK_FORMAT_B8G8R8A8_SRGB:
        case VK_FORMAT_D24_UNORM_S8_UINT: case VK_FORMAT_B10G11R11_UFLOAT_PACK32: return 4;
        case VK_FORMAT_R16G16B16A16_SFLOAT: case VK_FORMAT_R32G32_SFLOAT: case VK_FORMAT_D32_SFLOAT_S8_UINT: return 8;
        case VK_FORMAT_R32G32B32A32_SFLOAT: case VK_FORMAT_R32G32B32A32_UINT: return 16;
        default: return 0;
    }
}

// Texels of every mip and layer times the texel size: what the image will
// need at least, known before vkCreateImage.
uint64_t estimatedBytes(const ImageDesc& d) {
    uint64_t texels = 0;
    for (uint32_t m = 0; m < d.mipLevels; ++m)
        texels += uint64_t(std::max(d.extent.width >> m, 1u)) * std::max(d.extent.height >> m, 1u) *
                  std::max(d.extent.depth >> m, 1u);
    return texels * d.layers * texelBytes(d.format);
}

VkImageViewType viewType(const ImageDesc& d, uint32_t layers) {
    if (d.type == VK_IMAGE_TYPE_3D) return VK_IMAGE_VIEW_TYPE_3D;
    return layers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
}

}  // namespace

LiveMemory liveDeviceMemory() { return {g_liveBytes.load(), g_liveAllocations.load()}; }

uint64_t nextResourceSerial() {
    static std::atomic<uint64_t> next{1};
    return next.fetch_add(1);
}

bool isDepthFormat(VkFormat f) {
    return f == VK_FORMAT_D32_SFLOAT || f == VK_FORMAT_D16_UNORM || f == VK_FORMAT_D24_UNORM_S8_UINT ||
           f == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

Buffer::Buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use, const char* name)
    : device_(ctx.device), size_(size), serial_(nextResourceSerial()) {
    VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bci.size = size ? size : 16;  // zero-sized buffers are invalid; keep empty scenes legal
    bci.usage = usage;
    VK_CHECK(vkCreateBuffer(device_, &bci, nullptr, &buffer_));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device_, buffer_, &req);
    VkMemoryPropertyFlags flags = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    if (use == MemoryUse::Upload) flags = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    if (use == MemoryUse::Readback)
        flags = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT |
                VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
    try {
        memory_ = allocate(ctx, req, flags, name);
    } catch (const GpuError&) {
        if (use != MemoryUse::Readback) { reset(); throw; }
        try {
            memory_ = allocate(ctx, req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, name);
        } catch (...) {
            reset();
            throw;
        }
    }
    allocated_ = req.size;
    // A constructor that throws runs no destructor: free what exists so far.
    try {
        VK_CHECK(vkBindBufferMemory(device_, buffer_, memory_, 0));
        if (use != MemoryUse::Device) VK_CHECK(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
    } catch (...) {
        reset();
        throw;
    }
    ctx.nameObject(VK_OBJECT_TYPE_BUFFER, uint64_t(buffer_), name);
}

Buffer& Buffer::operator=(Buffer&& o) noexcept {
    if (this != &o) {
        reset();
        device_ = std::exchange(o.device_, VK_NULL_HANDLE);
        buffer_ = std::exchange(o.buffer_, VK_NULL_HANDLE);
        memory_ = std::exchange(o.memory_, VK_NULL_HANDLE);
        size_ = std::exchange(o.size_, 0);
        allocated_ = std::exchange(o.allocated_, 0);
        mapped_ = std::exchange(o.mapped_, nullptr);
        serial_ = std::exchange(o.serial_, 0);
    }
    return *this;
}

void Buffer::reset() {
    if (!device_) return;
    if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
    if (memory_) release(device_, memory_, allocated_);
    buffer_ = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
    mapped_ = nullptr;
    size_ = 0;
    allocated_ = 0;
}

Image::Image(const Context& ctx, const ImageDesc& desc)
    : device_(ctx.device), desc_(desc), serial_(nextResourceSerial()) {
    VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ici.imageType = desc.type;
    ici.format = desc.format;
    ici.extent = desc.extent;
    ici.mipLevels = desc.mipLevels;
    ici.arrayLayers = desc.layers;
    ici.samples = VK_SAMPLE_COUNT_1_BIT;
    ici.tiling = VK_IMAGE_TILING_OPTIMAL;
    ici.usage = desc.usage;
    ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    // An image larger than the heap, one allocation or the format's
    // maxResourceSize cannot exist; creating it anyway is invalid usage.
    const uint64_t estimate = estimatedBytes(desc);
    VkImageFormatProperties fp{};
    const VkResult fr = vkGetPhysicalDeviceImageFormatProperties(ctx.physical, desc.format, desc.type,
                                                                 VK_IMAGE_TILING_OPTIMAL, desc.usage, 0, &fp);
    const uint32_t heap = largestDeviceHeap(ctx);
    uint64_t largest = ctx.maxAllocationSize > 0 ? ctx.maxAllocationSize : UINT64_MAX;
    if (fr == VK_SUCCESS && fp.maxResourceSize > 0) largest = std::min<uint64_t>(largest, fp.maxResourceSize);
    if (estimate > std::min<uint64_t>(largest, ctx.memory.memoryHeaps[heap].size))
        throwMemoryError(ctx, desc.name, estimate, heap,
                         std::string("out of GPU memory creating ") + desc.name + " (" +
                             std::to_string(estimate >> 20) + " MiB)",
                         VK_ERROR_OUT_OF_DEVICE_MEMORY, largest);
    VkResult r = vkCreateImage(device_, &ici, nullptr, &image_);
    if (r == VK_ERROR_OUT_OF_DEVICE_MEMORY || r == VK_ERROR_OUT_OF_HOST_MEMORY)
        throwMemoryError(ctx, desc.name, 0, largestDeviceHeap(ctx),
                         std::string("out of memory creating ") + desc.name + ": " + resultName(r), r);
    if (r != VK_SUCCESS)
        throw GpuError(std::string("cannot create ") + desc.name + " (" + std::to_string(desc.extent.width) + "x" +
                           std::to_string(desc.extent.height) + "x" + std::to_string(desc.extent.depth) +
                           "): " + resultName(r),
                       r);
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device_, image_, &req);
    memorySize_ = req.size;
    try {
        memory_ = allocate(ctx, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, desc.name);
    } catch (...) {
        reset();
        throw;
    }
    ctx.nameObject(VK_OBJECT_TYPE_IMAGE, uint64_t(image_), desc.name);
    auto makeView = [&](uint32_t baseMip, uint32_t mips, uint32_t baseLayer, uint32_t layers) {
        VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        vci.image = image_;
        vci.viewType = viewType(desc_, layers);
        vci.format = desc_.format;
        vci.subresourceRange = {aspect(), baseMip, mips, baseLayer, layers};
        VkImageView v;
        VK_CHECK(vkCreateImageView(device_, &vci, nullptr, &v));
        return v;
    };
    // A constructor that throws runs no destructor: free what exists so far.
    try {
        VK_CHECK(vkBindImageMemory(device_, image_, memory_, 0));
        view_ = makeView(0, desc.mipLevels, 0, desc.layers);
        for (uint32_t m = 0; m < desc.mipLevels && desc.mipLevels > 1; ++m)
            mipViews_.push_back(makeView(m, 1, 0, desc.layers));
        if (desc.mipLevels == 1) mipViews_.push_back(view_);
        for (uint32_t l = 0; l < desc.layers && desc.layers > 1; ++l) layerViews_.push_back(makeView(0, 1, l, 1));
        if (desc.layers == 1) layerViews_.push_back(view_);
    } catch (...) {
        reset();
        throw;
    }
}

VkImageAspectFlags Image::aspect() const {
    return isDepthFormat(desc_.format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

Image& Image::operator=(Image&& o) noexcept {
    if (this != &o) {
        reset();
        device_ = std::exchange(o.device_, VK_NULL_HANDLE);
        image_ = std::exchange(o.image_, VK_NULL_HANDLE);
        memory_ = std::exchange(o.memory_, VK_NULL_HANDLE);
        memorySize_ = std::exchange(o.memorySize_, 0);
        view_ = std::exchange(o.view_, VK_NULL_HANDLE);
        mipViews_ = std::move(o.mipViews_);
        layerViews_ = std::move(o.layerViews_);
        desc_ = o.desc_;
        serial_ = std::exchange(o.serial_, 0);
    }
    return *this;
}

void Image::reset() {
    if (!device_) return;
    for (VkImageView v : mipViews_)
        if (v != view_) vkDestroyImageView(device_, v, nullptr);
    for (VkImageView v : layerViews_)
        if (v != view_) vkDestroyImageView(device_, v, nullptr);
    mipViews_.clear();
    layerViews_.clear();
    if (view_) vkDestroyImageView(device_, view_, nullptr);
    if (image_) vkDestroyImage(device_, image_, nullptr);
    if (memory_) release(device_, memory_, memorySize_);
    view_ = VK_NULL_HANDLE;
    image_ = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
}

Sampler::Sampler(const Context& ctx, const SamplerDesc& d) : device_(ctx.device) {
    VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sci.magFilter = d.filter;
    sci.minFilter = d.filter;
    sci.mipmapMode = d.mipmap;
    sci.addressModeU = sci.addressModeV = sci.addressModeW = d.address;
    sci.borderColor = d.transparentBorder ? VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK : VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
    sci.maxLod = VK_LOD_CLAMP_NONE;
    // Anisotropy is a quality hint: without the feature the sampler is plain trilinear.
    sci.anisotropyEnable = d.maxAnisotropy > 1.0f && ctx.features.samplerAnisotropy;
    sci.maxAnisotropy = sci.anisotropyEnable ? std::min(d.maxAnisotropy, ctx.properties.limits.maxSamplerAnisotropy) : 1.0f;
    VK_CHECK(vkCreateSampler(device_, &sci, nullptr, &sampler_));
}

Sampler& Sampler::operator=(Sampler&& o) noexcept {
    if (this != &o) {
        reset();
        device_ = std::exchange(o.device_, VK_NULL_HANDLE);
        sampler_ = std::exchange(o.sampler_, VK_NULL_HANDLE);
    }
    return *this;
}

void Sampler::reset() {
    if (device_ && sampler_) vkDestroySampler(device_, sampler_, nullptr);
    sampler_ = VK_NULL_HANDLE;
}

}  // namespace dvsgi::gpu
