#include "vxgi/voxel_counts.h"

#include <cstring>

#include "gpu/context.h"
#include "gpu/resources.h"
#include "shared/voxel_list_pass.h"
#include "vxgi/volumes.h"

namespace dvsgi::vxgi {

namespace sh = dvsgi::shader;

VoxelCounts countVoxels(const gpu::Context& ctx, const VoxelVolumes& volumes) {
    const gpu::Buffer staging(ctx, sizeof(sh::VoxelListHeader), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              gpu::MemoryUse::Readback, "voxel list header read-back");
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        // Its own submission, outside the Renderer's tracker: wait for every earlier write.
        VkMemoryBarrier2 before{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
        before.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        before.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
        before.dstStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
        before.dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT;
        VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dep.memoryBarrierCount = 1;
        dep.pMemoryBarriers = &before;
        vkCmdPipelineBarrier2(cmd, &dep);
        const VkBufferCopy region{0, 0, sizeof(sh::VoxelListHeader)};
        vkCmdCopyBuffer(cmd, volumes.list.handle(), staging.handle(), 1, &region);
        VkMemoryBarrier2 after{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
        after.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
        after.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        after.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
        after.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
        dep.pMemoryBarriers = &after;
        vkCmdPipelineBarrier2(cmd, &dep);
    });
    sh::VoxelListHeader header;
    std::memcpy(&header, staging.mapped(), sizeof(header));
    const uint32_t occupied = header.counts.x < header.counts.z ? header.counts.x : header.counts.z;
    const uint32_t statics = header.counts.y < occupied ? header.counts.y : occupied;
    return {occupied, occupied - statics};
}

}  // namespace dvsgi::vxgi
