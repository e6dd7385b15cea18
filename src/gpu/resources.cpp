#include "gpu/resources.h"

#include <algorithm>

#include "gpu/check.h"
#include "gpu/context.h"

namespace dvsgi::gpu {

namespace {

VkDeviceMemory allocate(const Context& ctx, const VkMemoryRequirements& req, VkMemoryPropertyFlags flags,
                        const char* name) {
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    ai.memoryTypeIndex = ctx.findMemoryType(req.memoryTypeBits, flags);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkResult r = vkAllocateMemory(ctx.device, &ai, nullptr, &memory);
    if (r != VK_SUCCESS)
        throw GpuError(std::string("out of GPU memory allocating ") + name + " (" +
                           std::to_string(req.size >> 20) + " MiB): " + resultName(r),
                       r);
    return memory;
}

VkImageViewType viewType(const ImageDesc& d, uint32_t layers) {
    if (d.type == VK_IMAGE_TYPE_3D) return VK_IMAGE_VIEW_TYPE_3D;
    return layers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
}

}  // namespace

bool isDepthFormat(VkFormat f) {
    return f == VK_FORMAT_D32_SFLOAT || f == VK_FORMAT_D16_UNORM || f == VK_FORMAT_D24_UNORM_S8_UINT ||
           f == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

Buffer::Buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use, const char* name)
    : device_(ctx.device), size_(size) {
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
        memory_ = allocate(ctx, req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, name);
    }
    VK_CHECK(vkBindBufferMemory(device_, buffer_, memory_, 0));
    ctx.nameObject(VK_OBJECT_TYPE_BUFFER, uint64_t(buffer_), name);
    if (use != MemoryUse::Device) VK_CHECK(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
}

Buffer& Buffer::operator=(Buffer&& o) noexcept {
    if (this != &o) {
        reset();
        device_ = std::exchange(o.device_, VK_NULL_HANDLE);
        buffer_ = std::exchange(o.buffer_, VK_NULL_HANDLE);
        memory_ = std::exchange(o.memory_, VK_NULL_HANDLE);
        size_ = std::exchange(o.size_, 0);
        mapped_ = std::exchange(o.mapped_, nullptr);
    }
    return *this;
}

void Buffer::reset() {
    if (!device_) return;
    if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
    if (memory_) vkFreeMemory(device_, memory_, nullptr);
    buffer_ = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
    mapped_ = nullptr;
    size_ = 0;
}

Image::Image(const Context& ctx, const ImageDesc& desc) : device_(ctx.device), desc_(desc) {
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
    VkResult r = vkCreateImage(device_, &ici, nullptr, &image_);
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
    VK_CHECK(vkBindImageMemory(device_, image_, memory_, 0));
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
    view_ = makeView(0, desc.mipLevels, 0, desc.layers);
    for (uint32_t m = 0; m < desc.mipLevels && desc.mipLevels > 1; ++m) mipViews_.push_back(makeView(m, 1, 0, desc.layers));
    if (desc.mipLevels == 1) mipViews_.push_back(view_);
    for (uint32_t l = 0; l < desc.layers && desc.layers > 1; ++l) layerViews_.push_back(makeView(0, 1, l, 1));
    if (desc.layers == 1) layerViews_.push_back(view_);
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
    if (memory_) vkFreeMemory(device_, memory_, nullptr);
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
    sci.compareEnable = d.compare;
    sci.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
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
