// Host <-> device copies through staging buffers. These block (submit and
// wait): they run at load time and for read-back, never inside a frame.
#pragma once

#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/barriers.h"
#include "gpu/resources.h"

namespace dvsgi::gpu {

class Context;

// A device-local buffer filled with `bytes` (usage gains TRANSFER_DST).
Buffer createBuffer(const Context& ctx, const void* data, VkDeviceSize bytes, VkBufferUsageFlags usage,
                    const char* name);
void uploadBuffer(const Context& ctx, const Buffer& dst, const void* data, VkDeviceSize bytes);

// Uploads tightly packed texels into mip 0 (all layers, layer-major), builds
// the remaining mips with linear blits, and leaves the image in `finalUse`.
void uploadImage(const Context& ctx, const Image& image, const void* texels, VkDeviceSize bytes, ImageUse finalUse);

// Copies mip `mip` of a colour image, currently in `current`, to host memory
// (tightly packed), and returns it to `current`.
std::vector<uint8_t> readbackImage(const Context& ctx, const Image& image, ImageUse current, uint32_t mip = 0);

std::vector<uint8_t> readbackBuffer(const Context& ctx, const Buffer& buffer, VkDeviceSize bytes = VK_WHOLE_SIZE);

// Zeroes every mip and layer of a newly created colour image (contents
// undefined) and leaves it in use::ComputeReadWrite.
void recordZeroNewImage(VkCommandBuffer cmd, const Image& image);

uint32_t formatBytes(VkFormat format);

}  // namespace dvsgi::gpu
