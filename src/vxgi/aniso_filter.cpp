#include "vxgi/aniso_filter.h"

#include <algorithm>
#include <cstddef>

#include "gpu/context.h"
#include "gpu/timers.h"
#include "gpu/tracker.h"
#include "shared/aniso_filter_pass.h"
#include "shared/voxel_list_pass.h"
#include "vxgi/volumes.h"
#include "vxgi/voxel_list.h"

namespace dvsgi::vxgi {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kAniso[] = {
#include "shaders/aniso_filter.comp.inc"
};
const uint32_t kAnisoBase[] = {
#include "shaders/aniso_filter_base_level.comp.inc"
};
const uint32_t kAnisoTwoSided[] = {
#include "shaders/aniso_filter_two_sided.comp.inc"
};

}  // namespace

AnisoFilterPass::AnisoFilterPass(const gpu::Context& ctx) : ctx_(ctx) {
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_ANISO_SOURCE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_ANISO_SOURCE_DIRS, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_ANISO_TARGET_DIRS, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs}};
    layout.pushConstantBytes = sizeof(sh::AnisoPush);
    layout.pushConstantStages = cs;
    pipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kAniso), layout, "anisotropic filtering");
    layout.bindings.insert(layout.bindings.end(), {{sh::BIND_ANISO_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                                                   {sh::BIND_ANISO_LIST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                                                   {sh::BIND_ANISO_INDEX, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                                                   {sh::BIND_ANISO_ACCUM, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs}});
    base_ = gpu::Pipeline(ctx, gpu::Spirv(kAnisoBase), layout, "anisotropic filtering (base level)");
    layout.bindings.insert(layout.bindings.end(), {{sh::BIND_ANISO_DIRECT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                                                   {sh::BIND_ANISO_SIDES, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs}});
    twoSided_ = gpu::Pipeline(ctx, gpu::Spirv(kAnisoTwoSided), layout, "anisotropic filtering (two-sided voxels)");
}

void AnisoFilterPass::record(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v, bool backsDark,
                             gpu::GpuTimers* timers, const char* timerName) const {
    gpu::GpuTimerScope timer(timers, cmd, timerName);
    recordBase(cmd, tracker, v, backsDark);
    recordTwoSided(cmd, tracker, v, backsDark);
    for (uint32_t level = 1; level < v.directionalMips; ++level) {
        // Each level reads the one below it.
        tracker.imageMip(v.directional, level - 1, gpu::use::ComputeRead);
        tracker.imageMip(v.directional, level, gpu::use::ComputeWrite, true);
        tracker.flush(cmd);
        gpu::bind(cmd, pipeline_);
        gpu::Descriptors()
            .storageImage(sh::BIND_ANISO_SOURCE, v.radiance.view())
            .storageImage(sh::BIND_ANISO_SOURCE_DIRS, v.directional.mipView(level - 1))
            .storageImage(sh::BIND_ANISO_TARGET_DIRS, v.directional.mipView(level))
            .push(ctx_, cmd, pipeline_);
        const uint32_t size = std::max((v.grid.n / 2) >> level, 1u);
        const sh::AnisoPush push{glm::uvec4(size, 0u, 0u, 0u)};
        gpu::pushConstants(cmd, pipeline_, VK_SHADER_STAGE_COMPUTE_BIT, push);
        const uint32_t groups = gpu::groupCount(size, sh::ANISO_GROUP);
        vkCmdDispatch(cmd, groups, groups, groups);
    }
}

// What both passes over level 0 bind: the radiance, level 0 itself (also as
// the unused upper-level source, which needs a valid view; the passes declare
// it read as well as written), the grid, the list, and the slot index and
// attributes for the voxels' normals.
gpu::Descriptors AnisoFilterPass::levelZeroBindings(const VoxelVolumes& v) {
    gpu::Descriptors d;
    d.storageImage(sh::BIND_ANISO_SOURCE, v.radiance.view())
        .storageImage(sh::BIND_ANISO_SOURCE_DIRS, v.directional.mipView(0))
        .storageImage(sh::BIND_ANISO_TARGET_DIRS, v.directional.mipView(0))
        .uniformBuffer(sh::BIND_ANISO_GRID, v.gridBuffer.handle())
        .storageBuffer(sh::BIND_ANISO_LIST, v.list.handle())
        .storageBuffer(sh::BIND_ANISO_INDEX, v.index.handle())
        .storageImage(sh::BIND_ANISO_ACCUM, v.accum.view());
    return d;
}

// What both passes over level 0 read.
void AnisoFilterPass::readLevelZero(gpu::Tracker& tracker, const VoxelVolumes& v) {
    tracker.image(v.radiance, gpu::use::ComputeRead)
        .image(v.accum, gpu::use::ComputeRead)
        .buffer(v.index, gpu::use::BufferComputeRead)
        .buffer(v.list, gpu::use::IndirectComputeRead)
        .imageMip(v.directional, 0, gpu::use::ComputeReadWrite);
}

// One invocation per list entry of `pipeline` over level 0.
void AnisoFilterPass::dispatchOverLevelZero(VkCommandBuffer cmd, const gpu::Pipeline& pipeline,
                                            const gpu::Descriptors& bindings, const VoxelVolumes& v,
                                            bool backsDark) const {
    gpu::bind(cmd, pipeline);
    bindings.push(ctx_, cmd, pipeline);
    const sh::AnisoPush push{glm::uvec4(v.grid.n / 2, backsDark ? 1u : 0u, 0u, 0u)};
    gpu::pushConstants(cmd, pipeline, VK_SHADER_STAGE_COMPUTE_BIT, push);
    dispatchOverList(cmd, v.list, offsetof(sh::VoxelListHeader, allGroups));
}

// The base level: cleared, then each cell that holds an occupied voxel
// composited once, by the cell's first occupied voxel in the list
// (aniso_filter.comp, DVSGI_BASE_LEVEL).
void AnisoFilterPass::recordBase(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v,
                                 bool backsDark) const {
    tracker.imageMip(v.directional, 0, gpu::use::ClearGeneral, true).flush(cmd);
    const VkClearColorValue zero{};
    const VkImageSubresourceRange mip0{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, v.directional.handle(), VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &mip0);
    readLevelZero(tracker, v);
    tracker.flush(cmd);
    dispatchOverLevelZero(cmd, base_, levelZeroBindings(v), v, backsDark);
}

// The cells holding two-sided voxels, again (aniso_filter.comp, DVSGI_TWO_SIDED).
void AnisoFilterPass::recordTwoSided(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v,
                                     bool backsDark) const {
    readLevelZero(tracker, v);
    tracker.image(v.direct, gpu::use::ComputeRead).image(v.sides, gpu::use::ComputeRead).flush(cmd);
    gpu::Descriptors bindings = levelZeroBindings(v);
    bindings.storageImage(sh::BIND_ANISO_DIRECT, v.direct.view())
        .storageImage(sh::BIND_ANISO_SIDES, v.sides.view());
    dispatchOverLevelZero(cmd, twoSided_, bindings, v, backsDark);
}

}  // namespace dvsgi::vxgi
