#include "render/voxel_view.h"

#include <algorithm>

#include "gpu/tracker.h"
#include "gpu/context.h"
#include "gpu/timers.h"
#include "shared/voxel_data.h"
#include "shared/voxel_view_pass.h"
#include "vxgi/volumes.h"

namespace dvsgi::render {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kComp[] = {
#include "shaders/voxel_view.comp.inc"
};

uint32_t shaderMode(ViewMode m) {
    switch (m) {
        case ViewMode::VoxelNormal: return sh::VIEW_NORMAL;
        case ViewMode::VoxelEmission: return sh::VIEW_EMISSION;
        case ViewMode::VoxelRadiance: return sh::VIEW_RADIANCE;
        case ViewMode::VoxelDirectional: return sh::VIEW_DIRECTIONAL;
        case ViewMode::VoxelAge: return sh::VIEW_AGE;
        default: return sh::VIEW_ALBEDO;
    }
}

}  // namespace

VoxelViewPass::VoxelViewPass(const gpu::Context& ctx) : ctx_(ctx) {
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_VIEW_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_VIEW_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_VIEW_ACCUM, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_VIEW_INDEX, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_VIEW_RADIANCE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_VIEW_DIRECTIONAL, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_VIEW_OUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_VIEW_LIST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_VIEW_DIRECT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_VIEW_SIDES, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs}};
    layout.pushConstantBytes = sizeof(sh::VoxelViewPush);
    layout.pushConstantStages = cs;
    pipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kComp), layout, "voxel view");
}

void VoxelViewPass::record(VkCommandBuffer cmd, gpu::Tracker& tracker, const vxgi::VoxelVolumes& v,
                           const gpu::Buffer& frame, const gpu::Image& output, const ViewSettings& view,
                           gpu::GpuTimers* timers) const {
    gpu::GpuTimerScope timer(timers, cmd, "voxel view");
    tracker.image(v.accum, gpu::use::ComputeRead).buffer(v.index, gpu::use::BufferComputeRead).image(v.radiance, gpu::use::ComputeRead);
    tracker.image(v.directional, gpu::use::ComputeRead).buffer(v.list, gpu::use::BufferComputeRead);
    tracker.image(v.direct, gpu::use::ComputeRead).image(v.sides, gpu::use::ComputeRead);
    tracker.image(output, gpu::use::ComputeWrite, true).flush(cmd);
    const uint32_t mip = std::min(view.mip, v.directionalMips - 1);
    const uint32_t w = output.desc().extent.width, h = output.desc().extent.height;
    gpu::bind(cmd, pipeline_);
    gpu::Descriptors()
        .uniformBuffer(sh::BIND_VIEW_GRID, v.gridBuffer.handle())
        .uniformBuffer(sh::BIND_VIEW_FRAME, frame.handle())
        .storageImage(sh::BIND_VIEW_ACCUM, v.accum.view())
        .storageBuffer(sh::BIND_VIEW_INDEX, v.index.handle())
        .storageImage(sh::BIND_VIEW_RADIANCE, v.radiance.view())
        .storageImage(sh::BIND_VIEW_DIRECTIONAL, v.directional.mipView(mip))
        .storageImage(sh::BIND_VIEW_OUT, output.view())
        .storageBuffer(sh::BIND_VIEW_LIST, v.list.handle())
        .storageImage(sh::BIND_VIEW_DIRECT, v.direct.view())
        .storageImage(sh::BIND_VIEW_SIDES, v.sides.view())
        .push(ctx_, cmd, pipeline_);
    const sh::VoxelViewPush push{glm::uvec4(shaderMode(view.mode), mip, w, h),
                                 glm::uvec4(std::min(view.direction, sh::DIRECTIONAL_VOLUMES - 1), 0u, 0u, 0u)};
    gpu::pushConstants(cmd, pipeline_, VK_SHADER_STAGE_COMPUTE_BIT, push);
    vkCmdDispatch(cmd, gpu::groupCount(w, sh::VIEW_GROUP), gpu::groupCount(h, sh::VIEW_GROUP), 1);
}

}  // namespace dvsgi::render
