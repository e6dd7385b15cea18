#include "gpu/barriers.h"

#include "gpu/resources.h"

namespace dvsgi::gpu {

namespace {

void recordImageBarrier(VkCommandBuffer cmd, const Image& image, VkImageSubresourceRange range, ImageUse from,
                        ImageUse to) {
    transition(cmd, image.handle(), range, from, to);
}


}  // namespace

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess) {
    VkMemoryBarrier2 b{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    b.srcStageMask = srcStages;
    b.srcAccessMask = srcAccess;
    b.dstStageMask = dstStages;
    b.dstAccessMask = dstAccess;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);
}

VkImageMemoryBarrier2 imageBarrier(const Image& image, VkImageSubresourceRange range, ImageUse from, ImageUse to) {
    return imageBarrier(image.handle(), range, from, to);
}

void transition(VkCommandBuffer cmd, VkImage image, VkImageSubresourceRange range, ImageUse from, ImageUse to) {
    if (!from.stages) from.stages = VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT;
    const VkImageMemoryBarrier2 b = imageBarrier(image, range, from, to);
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);
}

VkImageMemoryBarrier2 imageBarrier(VkImage image, VkImageSubresourceRange range, ImageUse from, ImageUse to) {
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask = from.stages;
    b.srcAccessMask = from.access;
    b.dstStageMask = to.stages;
    b.dstAccessMask = to.access;
    b.oldLayout = from.layout;
    b.newLayout = to.layout;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = range;
    return b;
}

void transition(VkCommandBuffer cmd, const Image& image, ImageUse from, ImageUse to) {
    recordImageBarrier(cmd, image, {image.aspect(), 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS}, from, to);
}

void transitionMip(VkCommandBuffer cmd, const Image& image, uint32_t mip, ImageUse from, ImageUse to) {
    recordImageBarrier(cmd, image, {image.aspect(), mip, 1, 0, VK_REMAINING_ARRAY_LAYERS}, from, to);
}

void computeWritesVisibleTo(VkCommandBuffer cmd, VkPipelineStageFlags2 stages, VkAccessFlags2 access) {
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, stages, access);
}

void storageWritesVisible(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStages, VkPipelineStageFlags2 dstStages) {
    // Each access bit is only legal with stages that can perform it.
    const VkPipelineStageFlags2 transfer = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
    const bool srcShader = (srcStages & ~transfer) != 0, srcTransfer = (srcStages & transfer) != 0;
    const bool dstShader = (dstStages & ~transfer) != 0, dstTransfer = (dstStages & transfer) != 0;
    VkAccessFlags2 srcAccess = 0, dstAccess = 0;
    if (srcShader) srcAccess |= VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
    if (srcTransfer) srcAccess |= VK_ACCESS_2_TRANSFER_WRITE_BIT;
    if (dstShader)
        dstAccess |= VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
    if (dstTransfer) dstAccess |= VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT;
    memoryBarrier(cmd, srcStages, srcAccess, dstStages, dstAccess);
}

void transferWritesVisibleToShaders(VkCommandBuffer cmd) {
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_SHADER_READ_BIT | VK_ACCESS_2_UNIFORM_READ_BIT);
}

}  // namespace dvsgi::gpu
