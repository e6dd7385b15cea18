#include "vxgi/inject.h"

#include <cstddef>

#include "gpu/context.h"
#include "gpu/timers.h"
#include "gpu/tracker.h"
#include "shared/inject_pass.h"
#include "shared/voxel_list_pass.h"
#include "vxgi/voxel_list.h"
#include "vxgi/volumes.h"

namespace dvsgi::vxgi {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kInject[] = {
#include "shaders/inject.comp.inc"
};
const uint32_t kInjectOccupancy[] = {
#include "shaders/inject_ray_occupancy.comp.inc"
};

}  // namespace

InjectPass::InjectPass(const gpu::Context& ctx) : ctx_(ctx) {
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_INJECT_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_INJECT_ACCUM, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_INJECT_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_INJECT_SHADOW_VIEWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_INJECT_SHADOW_MAP, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, cs},
                       {sh::BIND_INJECT_SHADOW_GRADIENT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, cs},
                       {sh::BIND_INJECT_DIRECT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_INJECT_LIST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_INJECT_INDEX, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_INJECT_OUT_RADIANCE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_INJECT_SIDES, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_INJECT_EXTENTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs}};
    layout.pushConstantBytes = sizeof(sh::VoxelLightPush);
    layout.pushConstantStages = cs;
    pipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kInject), layout, "voxel inject");
    layout.bindings.push_back({sh::BIND_INJECT_RAY_OCCUPANCY, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs});
    occupancyPipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kInjectOccupancy), layout, "voxel inject (occupancy bits)");
}

void InjectPass::record(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v, const ShadowInputs& s,
                        const VoxelLightSettings& settings, gpu::GpuTimers* timers, const gpu::Buffer* occupancy) const {
    gpu::GpuTimerScope timer(timers, cmd, "voxel direct light");
    tracker.image(v.accum, gpu::use::ComputeRead)
        .image(s.shadowMap, gpu::use::ShaderRead)
        .image(s.shadowGradient, gpu::use::ShaderRead)
        .buffer(v.index, gpu::use::BufferComputeRead)
        .buffer(v.extents, gpu::use::BufferComputeRead)
        .image(v.direct, gpu::use::ComputeWrite)
        .image(v.radiance, gpu::use::ComputeWrite)  // occupied voxels only: the rest stays zero
        .image(v.sides, gpu::use::ComputeReadWrite)  // two-sided voxels only
        .buffer(v.list, gpu::use::IndirectComputeRead);
    if (occupancy) tracker.buffer(*occupancy, gpu::use::BufferComputeRead);
    tracker.flush(cmd);
    const gpu::Pipeline& pipeline = occupancy ? occupancyPipeline_ : pipeline_;
    gpu::bind(cmd, pipeline);
    gpu::Descriptors d;
    if (occupancy) d.storageBuffer(sh::BIND_INJECT_RAY_OCCUPANCY, occupancy->handle());
    d.uniformBuffer(sh::BIND_INJECT_GRID, v.gridBuffer.handle())
        .storageImage(sh::BIND_INJECT_ACCUM, v.accum.view())
        .storageBuffer(sh::BIND_INJECT_LIGHTS, s.lights.handle())
        .storageBuffer(sh::BIND_INJECT_SHADOW_VIEWS, s.views.handle())
        .sampledImage(sh::BIND_INJECT_SHADOW_MAP, s.shadowMap.view(), s.gatherSampler)
        .sampledImage(sh::BIND_INJECT_SHADOW_GRADIENT, s.shadowGradient.view(), s.gatherSampler)
        .storageImage(sh::BIND_INJECT_DIRECT, v.direct.view())
        .storageBuffer(sh::BIND_INJECT_LIST, v.list.handle())
        .storageBuffer(sh::BIND_INJECT_INDEX, v.index.handle())
        .storageImage(sh::BIND_INJECT_OUT_RADIANCE, v.radiance.view())
        .storageImage(sh::BIND_INJECT_SIDES, v.sides.view())
        .storageBuffer(sh::BIND_INJECT_EXTENTS, v.extents.handle())
        .push(ctx_, cmd, pipeline);
    const sh::VoxelLightPush push{
        glm::uvec4(s.lightCount, settings.normalWeighted ? 1u : 0u, uint32_t(settings.occlusion),
                   s.shadowsRendered ? 1u : 0u),
        glm::vec4(settings.softKappa, settings.shadowNormalOffset, settings.emissionInRadiance ? 1.0f : 0.0f,
                  settings.keepSideReflection ? 1.0f : 0.0f),
        glm::uvec4(settings.keepStaticRadiance ? 1u : 0u, edgeFacesLit(settings) ? 1u : 0u, 0u, 0u)};
    gpu::pushConstants(cmd, pipeline, VK_SHADER_STAGE_COMPUTE_BIT, push);
    dispatchOverList(cmd, v.list, offsetof(sh::VoxelListHeader, allGroups));
}

}  // namespace dvsgi::vxgi
