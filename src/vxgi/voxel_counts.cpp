#include "vxgi/voxel_counts.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include "gpu/barriers.h"
#include "gpu/context.h"
#include "gpu/resources.h"
#include "shared/voxel_data.h"
#include "vxgi/volumes.h"

namespace dvsgi::vxgi {

namespace {

namespace sh = dvsgi::shader;

// The read-back runs outside the Renderer's tracker, in its own submission:
// it waits for any earlier access and leaves the volumes in GENERAL with every
// later command ordered after it.
constexpr gpu::ImageUse kAnyGeneral{VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                                    VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT};

}  // namespace

VoxelCounts countVoxels(const gpu::Context& ctx, const VoxelVolumes& volumes, uint64_t stagingBytes) {
    // In slabs: a 512^3 grid's counts alone are 512 MiB.
    const uint32_t n = volumes.grid.n;
    const uint64_t slice = uint64_t(n) * n;  // voxels per z layer
    const uint32_t depth = uint32_t(std::clamp<uint64_t>(stagingBytes / (slice * 5), 1, n));
    const VkDeviceSize countBytes = slice * depth * sizeof(float), flagBytes = slice * depth;
    const gpu::Buffer staging(ctx, countBytes + flagBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              gpu::MemoryUse::Readback, "voxel count read-back");
    const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VoxelCounts counts;
    std::vector<float> fragments(slice * depth);
    for (uint32_t z0 = 0; z0 < n; z0 += depth) {
        const uint32_t layers = std::min(depth, n - z0);
        ctx.submitAndWait([&](VkCommandBuffer cmd) {
            const VkImageMemoryBarrier2 before[] = {
                gpu::imageBarrier(volumes.accum, all, kAnyGeneral, gpu::use::TransferSrc),
                gpu::imageBarrier(volumes.flags, all, kAnyGeneral, gpu::use::TransferSrc)};
            VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
            dep.imageMemoryBarrierCount = 2;
            dep.pImageMemoryBarriers = before;
            vkCmdPipelineBarrier2(cmd, &dep);
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            // The fragment counts are slab CH_COUNT of the attribute volume.
            region.imageOffset = {0, 0, int32_t(sh::CH_COUNT * n + z0)};
            region.imageExtent = {n, n, layers};
            vkCmdCopyImageToBuffer(cmd, volumes.accum.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                   staging.handle(), 1, &region);
            region.bufferOffset = countBytes;
            region.imageOffset = {0, 0, int32_t(z0)};
            vkCmdCopyImageToBuffer(cmd, volumes.flags.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                   staging.handle(), 1, &region);
            const VkImageMemoryBarrier2 after[] = {
                gpu::imageBarrier(volumes.accum, all, gpu::use::TransferSrc, kAnyGeneral),
                gpu::imageBarrier(volumes.flags, all, gpu::use::TransferSrc, kAnyGeneral)};
            dep.pImageMemoryBarriers = after;
            vkCmdPipelineBarrier2(cmd, &dep);
        });
        const uint64_t voxels = slice * layers;
        std::memcpy(fragments.data(), staging.mapped(), voxels * sizeof(float));
        const uint8_t* flags = static_cast<const uint8_t*>(staging.mapped()) + countBytes;
        for (uint64_t i = 0; i < voxels; ++i) {
            if (!(fragments[i] > 0.0f)) continue;
            ++counts.occupied;
            if (flags[i] != sh::VOXEL_FLAG_STATIC) ++counts.dynamic;
        }
    }
    return counts;
}

}  // namespace dvsgi::vxgi
