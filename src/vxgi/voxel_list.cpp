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

// Groups of an over-the-list dispatch laid out as rows (see VOXEL_LIST_ROW).
void dispatchRows(VkCommandBuffer cmd, uint64_t invocations) {
    const uint64_t groups = (invocations + sh::VOXEL_LIST_GROUP - 1) / sh::VOXEL_LIST_GROUP;
    const uint64_t x = groups < sh::VOXEL_LIST_ROW ? groups : sh::VOXEL_LIST_ROW;
    if (x == 0) return;
    vkCmdDispatch(cmd, uint32_t(x), uint32_t((groups + x - 1) / x), 1);
}

}  // namespace

uint64_t voxelListBytes(uint32_t n) { return sizeof(sh::VoxelListHeader) + uint64_t(n) * n * n * sizeof(uint32_t); }

uint32_t voxelListMaxGroups(uint32_t n) {
    const uint64_t groups = (uint64_t(n) * n * n + sh::VOXEL_LIST_GROUP - 1) / sh::VOXEL_LIST_GROUP;
    return uint32_t(groups + sh::VOXEL_LIST_ROW);  // the last row may be partly past the end
}

void dispatchOverList(VkCommandBuffer cmd, const gpu::Buffer& list, VkDeviceSize argsOffset) {
    vkCmdDispatchIndirect(cmd, list.handle(), argsOffset);
}

VoxelListPass::VoxelListPass(const gpu::Context& ctx) : ctx_(ctx) {
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_LIST_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_LIST_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_LIST_ACCUM, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs}};
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

void VoxelListPass::run(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v, uint32_t mode,
                        uint32_t invocations) const {
    // The shader reads the attributes only to scan, but binds them always, and
    // validation checks what a pipeline may access.
    tracker.buffer(v.list, gpu::use::BufferComputeReadWrite).image(v.accum, gpu::use::ComputeRead).flush(cmd);
    gpu::bind(cmd, pipeline_);
    gpu::Descriptors()
        .uniformBuffer(sh::BIND_LIST_GRID, v.gridBuffer.handle())
        .storageBuffer(sh::BIND_LIST_BUFFER, v.list.handle())
        .storageImage(sh::BIND_LIST_ACCUM, v.accum.view())
        .push(ctx_, cmd, pipeline_);
    const sh::VoxelListPush push{glm::uvec4(mode, 0u, 0u, 0u)};
    gpu::pushConstants(cmd, pipeline_, VK_SHADER_STAGE_COMPUTE_BIT, push);
    dispatchRows(cmd, invocations);
}

void VoxelListPass::finish(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v,
                           bool staticVoxels) const {
    run(cmd, tracker, v, staticVoxels ? sh::LIST_FINISH_STATIC : sh::LIST_FINISH, 1);
}

void VoxelListPass::dropDynamic(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v) const {
    run(cmd, tracker, v, sh::LIST_DROP_DYNAMIC, 1);
}

void VoxelListPass::rebuild(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v) const {
    reset(cmd, tracker, v);
    const uint64_t n = v.grid.n;
    run(cmd, tracker, v, sh::LIST_SCAN, uint32_t(n * n * n));
    finish(cmd, tracker, v, true);
}

}  // namespace dvsgi::vxgi
