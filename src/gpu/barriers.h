// Synchronization2 barriers named by what the next pass does with a resource.
// A pass states how it leaves an image (ImageUse) and the next pass asks for
// the use it needs; transition() derives stages, accesses and layouts.
#pragma once

#include <vulkan/vulkan.h>

namespace dvsgi::gpu {

class Image;

struct ImageUse {
    VkImageLayout layout;
    VkPipelineStageFlags2 stages;
    VkAccessFlags2 access;
};

namespace use {
inline constexpr ImageUse Undefined{VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE};
inline constexpr ImageUse ComputeWrite{VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                       VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
inline constexpr ImageUse ComputeReadWrite{VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                           VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
// Sampled or read as storage by compute, fragment or geometry shaders.
inline constexpr ImageUse ShaderRead{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                     VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                                         VK_PIPELINE_STAGE_2_GEOMETRY_SHADER_BIT,
                                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
inline constexpr ImageUse ColorAttachment{VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                          VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                          VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT};
inline constexpr ImageUse DepthAttachment{VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                                          VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                                              VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                                          VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                                              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT};
inline constexpr ImageUse DepthRead{VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL,
                                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                    VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
// The voxel volumes live in GENERAL: compute reads (sampled or storage), the
// voxelizer's fragment atomics, transfer clears and copies all use it.
inline constexpr ImageUse ComputeRead{VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                      VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
inline constexpr ImageUse VoxelizeReadWrite{VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                            VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
inline constexpr ImageUse ClearGeneral{VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                                       VK_ACCESS_2_TRANSFER_WRITE_BIT};
inline constexpr ImageUse CopySrcGeneral{VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                                         VK_ACCESS_2_TRANSFER_READ_BIT};
inline constexpr ImageUse CopyDstGeneral{VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                                         VK_ACCESS_2_TRANSFER_WRITE_BIT};
inline constexpr ImageUse TransferSrc{VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                                      VK_ACCESS_2_TRANSFER_READ_BIT};
inline constexpr ImageUse TransferDst{VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                                      VK_ACCESS_2_TRANSFER_WRITE_BIT};
}  // namespace use

// How a pass uses a buffer (buffers have no layout).
struct BufferUse {
    VkPipelineStageFlags2 stages;
    VkAccessFlags2 access;
};

namespace use {
inline constexpr BufferUse BufferComputeRead{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                             VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
inline constexpr BufferUse BufferComputeWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                              VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
inline constexpr BufferUse BufferComputeReadWrite{
    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
// A compute pass whose dispatch size comes from the buffer (vkCmdDispatchIndirect)
// and whose shader reads it too.
inline constexpr BufferUse IndirectComputeRead{
    VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
    VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
// As IndirectComputeRead, with the shader writing it too (the clipmap scroll
// marks entries and counts them; the dispatch arguments are read before).
inline constexpr BufferUse IndirectComputeReadWrite{
    VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
    VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
// The voxelizer's fragments appending to a list.
inline constexpr BufferUse FragmentReadWrite{
    VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
// vkCmdFillBuffer / vkCmdCopyBuffer destination.
inline constexpr BufferUse BufferTransferWrite{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT};
// vkCmdCopyBuffer source.
inline constexpr BufferUse BufferTransferRead{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};
// A uniform buffer any stage of any pass may read (the voxel grid).
inline constexpr BufferUse BufferUniformRead{VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_UNIFORM_READ_BIT};
inline constexpr BufferUse HostRead{VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT};
}  // namespace use

// The barrier from one use to another over `range`, not recorded (the tracker
// batches these).
VkImageMemoryBarrier2 imageBarrier(const Image& image, VkImageSubresourceRange range, ImageUse from, ImageUse to);
// The same for an image dvsgi does not own (a swapchain image), and recorded at once.
VkImageMemoryBarrier2 imageBarrier(VkImage image, VkImageSubresourceRange range, ImageUse from, ImageUse to);
void transition(VkCommandBuffer cmd, VkImage image, VkImageSubresourceRange range, ImageUse from, ImageUse to);
// Whole image (all mips and layers) from one use to another.
void transition(VkCommandBuffer cmd, const Image& image, ImageUse from, ImageUse to);
// One mip level (all layers): for building mip chains level by level.
void transitionMip(VkCommandBuffer cmd, const Image& image, uint32_t mip, ImageUse from, ImageUse to);

// A global memory dependency (every resource) from the src stages' accesses
// to the dst stages' accesses: for submissions outside the tracker.
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess);
// Makes compute-shader writes to buffers/images visible to the stages given.
void computeWritesVisibleTo(VkCommandBuffer cmd, VkPipelineStageFlags2 stages, VkAccessFlags2 access);
// Makes storage writes of `srcStages` (images kept in GENERAL layout, such as
// the voxel volumes) visible to storage reads and writes of `dstStages`.
void storageWritesVisible(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStages, VkPipelineStageFlags2 dstStages);
// Makes transfer writes (uploads, clears) visible to every shader stage.
void transferWritesVisibleToShaders(VkCommandBuffer cmd);

}  // namespace dvsgi::gpu
