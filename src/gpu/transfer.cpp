#include "gpu/transfer.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "gpu/barriers.h"
#include "gpu/context.h"

namespace dvsgi::gpu {

void recordZeroNewImage(VkCommandBuffer cmd, const Image& image) {
    transition(cmd, image, use::Undefined, use::TransferDst);
    const VkClearColorValue zero{};
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, VK_REMAINING_MIP_LEVELS, 0,
                                        VK_REMAINING_ARRAY_LAYERS};
    vkCmdClearColorImage(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
    transition(cmd, image, use::TransferDst, use::ComputeReadWrite);
}

uint32_t formatBytes(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R8_UNORM: case VK_FORMAT_R8_UINT: return 1;
        case VK_FORMAT_R16_SFLOAT: return 2;
        case VK_FORMAT_R8G8B8A8_UNORM: case VK_FORMAT_R8G8B8A8_SRGB: case VK_FORMAT_R32_UINT:
        case VK_FORMAT_R32_SFLOAT: case VK_FORMAT_R32_SINT: case VK_FORMAT_D32_SFLOAT:
        case VK_FORMAT_B10G11R11_UFLOAT_PACK32: case VK_FORMAT_A2B10G10R10_UNORM_PACK32: return 4;
        case VK_FORMAT_R16G16B16A16_SFLOAT: case VK_FORMAT_R32G32_SFLOAT: return 8;
        case VK_FORMAT_R32G32B32A32_SFLOAT: case VK_FORMAT_R32G32B32A32_UINT: return 16;
        default: throw std::runtime_error("formatBytes: unhandled VkFormat " + std::to_string(int(format)));
    }
}

Buffer createBuffer(const Context& ctx, const void* data, VkDeviceSize bytes, VkBufferUsageFlags usage,
                    const char* name) {
    Buffer b(ctx, bytes, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Device, name);
    if (bytes && data) uploadBuffer(ctx, b, data, bytes);
    return b;
}

void uploadBuffer(const Context& ctx, const Buffer& dst, const void* data, VkDeviceSize bytes) {
    Buffer staging(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload, "staging");
    std::memcpy(staging.mapped(), data, bytes);
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        VkBufferCopy region{0, 0, bytes};
        vkCmdCopyBuffer(cmd, staging.handle(), dst.handle(), 1, &region);
        transferWritesVisibleToShaders(cmd);
    });
}

void uploadImage(const Context& ctx, const Image& image, const void* texels, VkDeviceSize bytes, ImageUse finalUse) {
    const ImageDesc& d = image.desc();
    Buffer staging(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload, "staging");
    std::memcpy(staging.mapped(), texels, bytes);
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        transition(cmd, image, use::Undefined, use::TransferDst);
        VkBufferImageCopy region{};
        region.imageSubresource = {image.aspect(), 0, 0, d.layers};
        region.imageExtent = d.extent;
        vkCmdCopyBufferToImage(cmd, staging.handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        int32_t w = int32_t(d.extent.width), h = int32_t(d.extent.height), z = int32_t(d.extent.depth);
        for (uint32_t m = 1; m < d.mipLevels; ++m) {
            transitionMip(cmd, image, m - 1, use::TransferDst, use::TransferSrc);
            VkImageBlit blit{};
            blit.srcSubresource = {image.aspect(), m - 1, 0, d.layers};
            blit.srcOffsets[1] = {w, h, z};
            w = std::max(w / 2, 1), h = std::max(h / 2, 1), z = std::max(z / 2, 1);
            blit.dstSubresource = {image.aspect(), m, 0, d.layers};
            blit.dstOffsets[1] = {w, h, z};
            vkCmdBlitImage(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.handle(),
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
            transitionMip(cmd, image, m - 1, use::TransferSrc, finalUse);
        }
        transitionMip(cmd, image, d.mipLevels - 1, use::TransferDst, finalUse);
    });
}

std::vector<uint8_t> readbackImage(const Context& ctx, const Image& image, ImageUse current, uint32_t mip) {
    const ImageDesc& d = image.desc();
    const uint32_t w = std::max(d.extent.width >> mip, 1u), h = std::max(d.extent.height >> mip, 1u),
                   z = std::max(d.extent.depth >> mip, 1u);
    const VkDeviceSize bytes = VkDeviceSize(w) * h * z * d.layers * formatBytes(d.format);
    Buffer staging(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback, "readback");
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        transitionMip(cmd, image, mip, current, use::TransferSrc);
        VkBufferImageCopy region{};
        region.imageSubresource = {image.aspect(), mip, 0, d.layers};
        region.imageExtent = {w, h, z};
        vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.handle(), 1, &region);
        transitionMip(cmd, image, mip, use::TransferSrc, current);
    });
    std::vector<uint8_t> out(bytes);
    std::memcpy(out.data(), staging.mapped(), bytes);
    return out;
}

std::vector<uint8_t> readbackBuffer(const Context& ctx, const Buffer& buffer, VkDeviceSize bytes) {
    // The first `bytes` (all of it by default): a small header needs no copy of the rest.
    const VkDeviceSize size = bytes == VK_WHOLE_SIZE ? buffer.size() : std::min(bytes, buffer.size());
    Buffer staging(ctx, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback, "readback");
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        const VkBufferCopy region{0, 0, size};
        vkCmdCopyBuffer(cmd, buffer.handle(), staging.handle(), 1, &region);
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    });
    std::vector<uint8_t> out(size);
    std::memcpy(out.data(), staging.mapped(), size);
    return out;
}

}  // namespace dvsgi::gpu
