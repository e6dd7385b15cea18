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
    base_ = gpu::Pipeline(ctx, gpu::Spirv(kAnisoBase), layout, "anisotropic filtering (base level)");
    layout.bindings.insert(layout.bindings.end(), {{sh::BIND_ANISO_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                                                   {sh::BIND_ANISO_INDEX, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                                                   {sh::BIND_ANISO_DIRECT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                                                   {sh::BIND_ANISO_SIDES, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                                                   {sh::BIND_ANISO_LIST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs}});
    twoSided_ = gpu::Pipeline(ctx, gpu::Spirv(kAnisoTwoSided), layout, "anisotropic filtering (two-sided voxels)");
}

void AnisoFilterPass::record(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v,
                             gpu::GpuTimers* timers, const char* timerName) const {
    gpu::GpuTimerScope timer(timers, cmd, timerName);
    for (uint32_t level = 0; level < v.directionalMips; ++level) {
        // Level 0 reads the radiance volume, every other level the one below it.
        // At level 0 the unused source binding still needs a valid view: it
        // gets the target level itself, so that level is declared read as
        // well as written.
        const VkImageView source = v.directional.mipView(level == 0 ? 0 : level - 1);
        if (level == 0) tracker.image(v.radiance, gpu::use::ComputeRead);
        if (level > 0) tracker.imageMip(v.directional, level - 1, gpu::use::ComputeRead);
        tracker.imageMip(v.directional, level, level == 0 ? gpu::use::ComputeReadWrite : gpu::use::ComputeWrite, true);
        tracker.flush(cmd);
        const gpu::Pipeline& pipeline = level == 0 ? base_ : pipeline_;
        gpu::bind(cmd, pipeline);
        gpu::Descriptors()
            .storageImage(sh::BIND_ANISO_SOURCE, v.radiance.view())
            .storageImage(sh::BIND_ANISO_SOURCE_DIRS, source)
            .storageImage(sh::BIND_ANISO_TARGET_DIRS, v.directional.mipView(level))
            .push(ctx_, cmd, pipeline);
        const uint32_t size = std::max((v.grid.n / 2) >> level, 1u);
        const sh::AnisoPush push{glm::uvec4(size, 0u, 0u, 0u)};
        gpu::pushConstants(cmd, pipeline, VK_SHADER_STAGE_COMPUTE_BIT, push);
        const uint32_t groups = gpu::groupCount(size, sh::ANISO_GROUP);
        vkCmdDispatch(cmd, groups, groups, groups);
        if (level == 0) recordTwoSided(cmd, tracker, v);
    }
}

// The cells holding two-sided voxels, again (aniso_filter.comp, DVSGI_TWO_SIDED).
void AnisoFilterPass::recordTwoSided(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v) const {
    tracker.image(v.direct, gpu::use::ComputeRead)
        .image(v.sides, gpu::use::ComputeRead)
        .buffer(v.index, gpu::use::BufferComputeRead)
        .buffer(v.list, gpu::use::IndirectComputeRead)
        .imageMip(v.directional, 0, gpu::use::ComputeReadWrite)
        .flush(cmd);
    gpu::bind(cmd, twoSided_);
    gpu::Descriptors()
        .storageImage(sh::BIND_ANISO_SOURCE, v.radiance.view())
        .storageImage(sh::BIND_ANISO_SOURCE_DIRS, v.directional.mipView(0))
        .storageImage(sh::BIND_ANISO_TARGET_DIRS, v.directional.mipView(0))
        .uniformBuffer(sh::BIND_ANISO_GRID, v.gridBuffer.handle())
        .storageBuffer(sh::BIND_ANISO_INDEX, v.index.handle())
        .storageImage(sh::BIND_ANISO_DIRECT, v.direct.view())
        .storageImage(sh::BIND_ANISO_SIDES, v.sides.view())
        .storageBuffer(sh::BIND_ANISO_LIST, v.list.handle())
        .push(ctx_, cmd, twoSided_);
    const sh::AnisoPush push{glm::uvec4(v.grid.n / 2, 0u, 0u, 0u)};
    gpu::pushConstants(cmd, twoSided_, VK_SHADER_STAGE_COMPUTE_BIT, push);
    dispatchOverList(cmd, v.list, offsetof(sh::VoxelListHeader, allGroups));
}

}  // namespace dvsgi::vxgi
