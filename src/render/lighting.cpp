#include "render/lighting.h"

#include "gpu/tracker.h"
#include "gpu/context.h"
#include "gpu/timers.h"
#include <cmath>

#include "shared/lighting_pass.h"
#include "shared/voxel_data.h"
#include "vxgi/cone_settings.h"
#include "vxgi/bounce.h"
#include "vxgi/clipmap.h"
#include "vxgi/volumes.h"

namespace dvsgi::render {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kComp[] = {
#include "shaders/lighting.comp.inc"
};
const uint32_t kCompClipmap[] = {
#include "shaders/lighting_clipmap.comp.inc"
};
const uint32_t kCompMapsOnly[] = {
#include "shaders/lighting_shadow_maps_only.comp.inc"
};
const uint32_t kCompAreaRays[] = {
#include "shaders/lighting_area_rays.comp.inc"
};
const vxgi::RayBindings kRayBindings{sh::BIND_LIGHT_RAY_SIDES, sh::BIND_LIGHT_RAY_INDEX, sh::BIND_LIGHT_RAY_NORMALS,
                                     sh::BIND_LIGHT_RAY_OCCUPANCY, sh::BIND_LIGHT_RAY_EXTENTS};

}  // namespace

LightingPass::LightingPass(const gpu::Context& ctx, bool clipmap) : ctx_(ctx) {
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_LIGHT_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_LIGHT_GBUF_BASE, sampled, cs},
                       {sh::BIND_LIGHT_GBUF_NORMAL, sampled, cs},
                       {sh::BIND_LIGHT_GBUF_EMISSION, sampled, cs},
                       {sh::BIND_LIGHT_DEPTH, sampled, cs},
                       {sh::BIND_LIGHT_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_LIGHT_SHADOW_VIEWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_LIGHT_SHADOW_MAP, sampled, cs},
                       {sh::BIND_LIGHT_SHADOW_GRADIENT, sampled, cs},
                       {sh::BIND_LIGHT_OUT_DIRECT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_LIGHT_VOXEL_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_LIGHT_VOXEL_RADIANCE, sampled, cs},
                       {sh::BIND_LIGHT_VOXEL_DIRECTIONAL, sampled, cs},
                       {sh::BIND_LIGHT_OUT_SHADOW, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs}};
    layout.pushConstantBytes = sizeof(sh::LightingPush);
    layout.pushConstantStages = cs;
    pipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kComp), layout, "lighting");
    if (clipmap) clipPipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kCompClipmap), layout, "lighting (clipmap)");
    mapsOnly_ = gpu::Pipeline(ctx, gpu::Spirv(kCompMapsOnly), layout, "lighting (shadow maps only)");
    gpu::LayoutDesc rays = layout;
    vxgi::addRayBindings(rays, kRayBindings);
    rays_ = gpu::Pipeline(ctx, gpu::Spirv(kCompAreaRays), rays, "lighting (area rays)");
}

void LightingPass::record(VkCommandBuffer cmd, gpu::Tracker& tracker, const LightingInputs& in,
                          const gpu::Image& direct, const gpu::Image& visibility, const ShadowConeSettings& cones,
                          const vxgi::ConeSettings& cone, gpu::GpuTimers* timers) const {
    gpu::GpuTimerScope timer(timers, cmd, "direct lighting");
    const GBuffer& g = in.gbuffer;
    const vxgi::VoxelVolumes& volumes = in.volumes;
    tracker.image(g.base, gpu::use::ShaderRead)
        .image(g.normal, gpu::use::ShaderRead)
        .image(g.emission, gpu::use::ShaderRead)
        .image(g.depth, gpu::use::DepthRead)
        .image(in.shadowMap, gpu::use::ShaderRead)
        .image(in.shadowGradient, gpu::use::ShaderRead)
        .image(volumes.radiance, gpu::use::ComputeRead);
    tracker.image(volumes.directional, gpu::use::ComputeRead);
    if (in.clip)
        tracker.image(in.clip->atlases.radiance, gpu::use::ComputeRead)
            .image(in.clip->atlases.directional, gpu::use::ComputeRead);
    const bool rays = in.areaLights && in.rays != nullptr && in.clip == nullptr;
    if (rays) vxgi::trackRayReads(tracker, volumes, *in.rays);
    tracker.image(direct, gpu::use::ComputeWrite, true).image(visibility, gpu::use::ComputeWrite, true).flush(cmd);
    const VkSampler volumeSampler = in.samplers.volume.handle();
    // Cones only where some light needs one; a fitted grid and a clipmap need none alike.
    const bool anyCone = cones.enabled || in.areaLights;
    const gpu::Pipeline& pipeline = !anyCone ? mapsOnly_ : in.clip ? clipPipeline_ : rays ? rays_ : pipeline_;
    gpu::bind(cmd, pipeline);
    const VkSampler point = in.samplers.point.handle();
    gpu::Descriptors d;
    if (rays) vxgi::bindRays(d, kRayBindings, volumes, *in.rays);
    d
        .uniformBuffer(sh::BIND_LIGHT_FRAME, in.frame.handle())
        .sampledImage(sh::BIND_LIGHT_GBUF_BASE, g.base.view(), point)
        .sampledImage(sh::BIND_LIGHT_GBUF_NORMAL, g.normal.view(), point)
        .sampledImage(sh::BIND_LIGHT_GBUF_EMISSION, g.emission.view(), point)
        .sampledImage(sh::BIND_LIGHT_DEPTH, g.depth.view(), point, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
        .storageBuffer(sh::BIND_LIGHT_LIGHTS, in.lights.handle())
        .storageBuffer(sh::BIND_LIGHT_SHADOW_VIEWS, in.views.handle())
        .sampledImage(sh::BIND_LIGHT_SHADOW_MAP, in.shadowMap.view(), point)
        .sampledImage(sh::BIND_LIGHT_SHADOW_GRADIENT, in.shadowGradient.view(), point)
        .storageImage(sh::BIND_LIGHT_OUT_DIRECT, direct.view())
        .uniformBuffer(sh::BIND_LIGHT_VOXEL_GRID, in.clip ? in.clip->levels.handle() : volumes.gridBuffer.handle())
        .sampledImage(sh::BIND_LIGHT_VOXEL_RADIANCE,
                      in.clip ? in.clip->atlases.radiance.view() : volumes.radiance.view(), volumeSampler,
                      VK_IMAGE_LAYOUT_GENERAL)
        .sampledImage(sh::BIND_LIGHT_VOXEL_DIRECTIONAL,
                      in.clip ? in.clip->atlases.directional.view() : volumes.directional.view(), volumeSampler,
                      VK_IMAGE_LAYOUT_GENERAL)
        .storageImage(sh::BIND_LIGHT_OUT_SHADOW, visibility.view())
        .push(ctx_, cmd, pipeline);
    const sh::LightingPush push{vxgi::gpuCone(cone, in.clip ? in.clip->coarsest : volumes.grid),
                            glm::vec4(cones.enabled ? 1.0f : 0.0f, std::tan(glm::radians(cones.apertureDegrees * 0.5f)),
                                      in.rayOffsetVoxels, 0.0f)};
    gpu::pushConstants(cmd, pipeline, VK_SHADER_STAGE_COMPUTE_BIT, push);
    vkCmdDispatch(cmd, gpu::groupCount(direct.desc().extent.width, sh::LIGHTING_GROUP),
                  gpu::groupCount(direct.desc().extent.height, sh::LIGHTING_GROUP), 1);
}

}  // namespace dvsgi::render
