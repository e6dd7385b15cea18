#include "vxgi/voxel_list.h"

#include <cstddef>

#include "gpu/context.h"
#include "gpu/resources.h"
#include "gpu/tracker.h"
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"
#include "vxgi/volumes.h"

namespace dvsgi::vxgi {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kList[] = {
#include "shaders/voxel_list.comp.inc"
};

}  // namespace

uint64_t voxelListBytes(uint32_t slots) { return sizeof(sh::VoxelListHeader) + uint64_t(slots) * sizeof(uint32_t); }

uint32_t voxelListMaxGroups(uint32_t slots) {
    const uint64_t groups = (uint64_t(slots) + sh::VOXEL_LIST_GROUP - 1) / sh::VOXEL_LIST_GROUP;
    return uint32_t(groups + sh::VOXEL_LIST_ROW);  // the last row may be partly past the end
}

void recordEmptyList(VkCommandBuffer cmd, const gpu::Buffer& list, uint32_t slots) {
    sh::VoxelListHeader header{};
    header.counts.z = slots;
    header.allGroups.z = header.dynamicGroups.z = 1;
    vkCmdUpdateBuffer(cmd, list.handle(), 0, sizeof(header), &header);
}

std::unique_ptr<gpu::Buffer> createListHeaderReadback(const gpu::Context& ctx) {
    return std::make_unique<gpu::Buffer>(ctx, sizeof(sh::VoxelListHeader), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                         gpu::MemoryUse::Readback, "voxel list header");
}

void dispatchOverList(VkCommandBuffer cmd, const gpu::Buffer& list, VkDeviceSize argsOffset) {
    vkCmdDispatchIndirect(cmd, list.handle(), argsOffset);
}

VoxelListPass::VoxelListPass(const gpu::Context& ctx) : ctx_(ctx) {
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_LIST_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_LIST_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs}};
    layout.pushConstantBytes = sizeof(sh::VoxelListPush);
    layout.pushConstantStages = cs;
    pipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kList), layout, "voxel list");
}

void VoxelListPass::reset(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v) const {
    tracker.buffer(v.list, gpu::use::BufferTransferWrite).flush(cmd);
    // Everything but the capacity (counts.z), which the volumes wrote once.
    constexpr VkDeviceSize capacity = offsetof(sh::VoxelListHeader, counts) + 2 * sizeof(uint32_t);
    vkCmdFillBuffer(cmd, v.list.handle(), 0, capacity, 0);
    vkCmdFillBuffer(cmd, v.list.handle(), capacity + sizeof(uint32_t),
                    sizeof(sh::VoxelListHeader) - capacity - sizeof(uint32_t), 0);
}

void VoxelListPass::run(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v, uint32_t mode) const {
    tracker.buffer(v.list, gpu::use::BufferComputeReadWrite).flush(cmd);
    gpu::bind(cmd, pipeline_);
    gpu::Descriptors()
        .uniformBuffer(sh::BIND_LIST_GRID, v.gridBuffer.handle())
        .storageBuffer(sh::BIND_LIST_BUFFER, v.list.handle())
        .push(ctx_, cmd, pipeline_);
    const sh::VoxelListPush push{glm::uvec4(mode, 0u, 0u, 0u)};
    gpu::pushConstants(cmd, pipeline_, VK_SHADER_STAGE_COMPUTE_BIT, push);
    vkCmdDispatch(cmd, 1, 1, 1);
}

void VoxelListPass::finish(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v,
                           bool staticVoxels) const {
    run(cmd, tracker, v, staticVoxels ? sh::LIST_FINISH_STATIC : sh::LIST_FINISH);
}

void VoxelListPass::copyHeader(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v,
                               const gpu::Buffer& hostBuffer) const {
    tracker.buffer(v.list, gpu::use::BufferTransferRead).buffer(hostBuffer, gpu::use::BufferTransferWrite).flush(cmd);
    const VkBufferCopy region{0, 0, sizeof(sh::VoxelListHeader)};
    vkCmdCopyBuffer(cmd, v.list.handle(), hostBuffer.handle(), 1, &region);
    tracker.buffer(hostBuffer, gpu::use::HostRead).flush(cmd);
}

void VoxelListPass::dropDynamic(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v) const {
    run(cmd, tracker, v, sh::LIST_DROP_DYNAMIC);
}

}  // namespace dvsgi::vxgi
