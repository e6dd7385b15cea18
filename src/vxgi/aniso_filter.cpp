#include "vxgi/aniso_filter.h"

#include <algorithm>

#include "gpu/context.h"
#include "gpu/timers.h"
#include "gpu/tracker.h"
#include "shared/aniso_filter_pass.h"
#include "vxgi/volumes.h"

namespace dvsgi::vxgi {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kAniso[] = {
#include "shaders/aniso_filter.comp.inc"
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
}

void AnisoFilterPass::record(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v,
                             gpu::GpuTimers* timers, const char* timerName) const {
    gpu::GpuTimerScope timer(timers, cmd, timerName);
    gpu::bind(cmd, pipeline_);
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
        gpu::Descriptors()
            .storageImage(sh::BIND_ANISO_SOURCE, v.radiance.view())
            .storageImage(sh::BIND_ANISO_SOURCE_DIRS, source)
            .storageImage(sh::BIND_ANISO_TARGET_DIRS, v.directional.mipView(level))
            .push(ctx_, cmd, pipeline_);
        const uint32_t size = std::max((v.grid.n / 2) >> level, 1u);
        const sh::AnisoPush push{glm::uvec4(size, level == 0 ? 1u : 0u, 0u, 0u)};
        gpu::pushConstants(cmd, pipeline_, VK_SHADER_STAGE_COMPUTE_BIT, push);
        const uint32_t groups = gpu::groupCount(size, sh::ANISO_GROUP);
        vkCmdDispatch(cmd, groups, groups, groups);
    }
}

}  // namespace dvsgi::vxgi
