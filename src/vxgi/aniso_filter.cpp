#include <algorithm>
#include <array>

#include "gpu/barriers.h"
#include "gpu/context.h"
#include "gpu/timers.h"
#include "vxgi/voxel_light.h"
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
                       {sh::BIND_ANISO_SOURCE_DIRS, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs, 6},
                       {sh::BIND_ANISO_TARGET_DIRS, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs, 6}};
    layout.pushConstantBytes = sizeof(sh::AnisoPush);
    layout.pushConstantStages = cs;
    pipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kAniso), layout, "anisotropic filtering");
}

void AnisoFilterPass::record(VkCommandBuffer cmd, const VoxelVolumes& v, gpu::GpuTimers* timers,
                             const char* timerName) const {
    gpu::GpuTimerScope timer(timers, cmd, timerName);
    gpu::bind(cmd, pipeline_);
    for (uint32_t level = 0; level < v.directionalMips; ++level) {
        std::array<VkImageView, 6> source, target;
        for (uint32_t d = 0; d < 6; ++d) {
            // Level 0 reads the radiance volume; the source-direction binding
            // still needs valid views, so it gets level 0 (unused there).
            source[d] = v.directional[d].mipView(level == 0 ? 0 : level - 1);
            target[d] = v.directional[d].mipView(level);
        }
        gpu::storageWritesVisible(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
        gpu::Descriptors()
            .storageImage(sh::BIND_ANISO_SOURCE, v.radiance.view())
            .storageImages(sh::BIND_ANISO_SOURCE_DIRS, source)
            .storageImages(sh::BIND_ANISO_TARGET_DIRS, target)
            .push(ctx_, cmd, pipeline_);
        const uint32_t size = std::max((v.grid.n / 2) >> level, 1u);
        const sh::AnisoPush push{glm::uvec4(size, level == 0 ? 1u : 0u, 0u, 0u)};
        gpu::pushConstants(cmd, pipeline_, VK_SHADER_STAGE_COMPUTE_BIT, push);
        const uint32_t groups = gpu::groupCount(size, 4);
        vkCmdDispatch(cmd, groups, groups, groups);
    }
    gpu::storageWritesVisible(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                              VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
}

}  // namespace dvsgi::vxgi
