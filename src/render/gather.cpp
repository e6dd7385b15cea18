#include "render/gather.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "gpu/tracker.h"
#include "gpu/context.h"
#include "gpu/timers.h"
#include "shared/cone_resolve_pass.h"
#include "shared/gather_pass.h"
#include "shared/upsample_pass.h"
#include "shared/voxel_data.h"
#include "shared/scene_data.h"
#include "vxgi/bounce.h"
#include "vxgi/clipmap.h"
#include "vxgi/volumes.h"

namespace dvsgi::render {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kGather[] = {
#include "shaders/gather.comp.inc"
};
const uint32_t kGatherClipmap[] = {
#include "shaders/gather_clipmap.comp.inc"
};
const uint32_t kGatherRays[] = {
#include "shaders/gather_rays.comp.inc"
};
const uint32_t kConeResolve[] = {
#include "shaders/cone_resolve.comp.inc"
};
const uint32_t kUpsample[] = {
#include "shaders/upsample.comp.inc"
};
const vxgi::RayBindings kRayBindings{sh::BIND_GATHER_RAY_SIDES, sh::BIND_GATHER_RAY_INDEX, sh::BIND_GATHER_RAY_NORMALS,
                                     sh::BIND_GATHER_RAY_OCCUPANCY, sh::BIND_GATHER_RAY_EXTENTS};

}  // namespace

GatherPass::GatherPass(const gpu::Context& ctx, bool clipmap) : ctx_(ctx) {
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_CONE_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_GATHER_RADIANCE, sampled, cs},
                       {sh::BIND_CONE_DIRECTIONAL, sampled, cs},
                       {sh::BIND_GATHER_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_GATHER_BASE, sampled, cs},
                       {sh::BIND_GATHER_NORMAL, sampled, cs},
                       {sh::BIND_GATHER_DEPTH, sampled, cs},
                       {sh::BIND_GATHER_OUT_DIFFUSE, storage, cs},
                       {sh::BIND_GATHER_OUT_SPECULAR, storage, cs}};
    layout.pushConstantBytes = sizeof(sh::GatherPush);
    layout.pushConstantStages = cs;
    gather_ = gpu::Pipeline(ctx, gpu::Spirv(kGather), layout, "cone tracing");
    if (clipmap) clipGather_ = gpu::Pipeline(ctx, gpu::Spirv(kGatherClipmap), layout, "cone tracing (clipmap)");
    gpu::LayoutDesc rays = layout;
    vxgi::addRayBindings(rays, kRayBindings);
    rayGather_ = gpu::Pipeline(ctx, gpu::Spirv(kGatherRays), rays, "cone tracing (rays)");

    gpu::LayoutDesc resolve;
    resolve.bindings = {{sh::BIND_RESOLVE_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                        {sh::BIND_RESOLVE_NORMAL, sampled, cs},
                        {sh::BIND_RESOLVE_DEPTH, sampled, cs},
                        {sh::BIND_RESOLVE_TRACED, storage, cs},
                        {sh::BIND_RESOLVE_OUT, storage, cs}};
    resolve.pushConstantBytes = sizeof(sh::ConeResolvePush);
    resolve.pushConstantStages = cs;
    resolve_ = gpu::Pipeline(ctx, gpu::Spirv(kConeResolve), resolve, "cone set resolve");

    gpu::LayoutDesc up;
    up.bindings = {{sh::BIND_UP_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                   {sh::BIND_UP_NORMAL, sampled, cs},
                   {sh::BIND_UP_DEPTH, sampled, cs},
                   {sh::BIND_UP_LOW_DIFFUSE, storage, cs},
                   {sh::BIND_UP_LOW_SPECULAR, storage, cs},
                   {sh::BIND_UP_OUT_DIFFUSE, storage, cs},
                   {sh::BIND_UP_OUT_SPECULAR, storage, cs}};
    up.pushConstantBytes = sizeof(sh::UpsamplePush);
    up.pushConstantStages = cs;
    upsample_ = gpu::Pipeline(ctx, gpu::Spirv(kUpsample), up, "upsample");
}

uint32_t resolvePasses(const GatherSettings& s, bool rays, uint32_t coneSet) {
    if (rays) return s.spin ? s.rayFilterPasses : 0u;
    return s.spin && coneSet == sh::CONE_SET_6 && s.fixedTurn < 0 ? 1u : 0u;
}

void GatherPass::recordResolve(VkCommandBuffer cmd, gpu::Tracker& tracker, const GatherInputs& in, uint32_t passes,
                               bool rays, const gpu::Image& turned, const gpu::Image& resolved,
                               gpu::GpuTimers* timers) const {
    gpu::GpuTimerScope timer(timers, cmd, "cone set resolve");
    const GBuffer& g = in.gbuffer;
    const VkSampler point = in.samplers.point.handle();
    const uint32_t width = turned.desc().extent.width, height = turned.desc().extent.height;
    const glm::uvec4 sizes(width, height, g.depth.desc().extent.width, g.depth.desc().extent.height);
    // The voxel edge the rays' filter measures its reach in; 0: no reach (the turned cones).
    const uint32_t reachVoxel = std::bit_cast<uint32_t>(rays ? in.volumes.grid.voxelSize : 0.0f);
    gpu::bind(cmd, resolve_);
    const gpu::Image* from = passes % 2 ? &turned : &resolved;
    for (uint32_t k = 0; k < passes; ++k) {
        const gpu::Image* to = from == &turned ? &resolved : &turned;
        tracker.image(*from, gpu::use::ComputeRead).image(*to, gpu::use::ComputeWrite, true).flush(cmd);
        gpu::Descriptors()
            .uniformBuffer(sh::BIND_RESOLVE_FRAME, in.frame.handle())
            .sampledImage(sh::BIND_RESOLVE_NORMAL, g.normal.view(), point)
            .sampledImage(sh::BIND_RESOLVE_DEPTH, g.depth.view(), point, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
            .storageImage(sh::BIND_RESOLVE_TRACED, from->view())
            .storageImage(sh::BIND_RESOLVE_OUT, to->view())
            .push(ctx_, cmd, resolve_);
        const sh::ConeResolvePush push{sizes, glm::uvec4(1u << k, reachVoxel, 0u, 0u)};
        gpu::pushConstants(cmd, resolve_, VK_SHADER_STAGE_COMPUTE_BIT, push);
        vkCmdDispatch(cmd, gpu::groupCount(width, sh::RESOLVE_GROUP), gpu::groupCount(height, sh::RESOLVE_GROUP), 1);
        from = to;
    }
}

void GatherPass::record(VkCommandBuffer cmd, gpu::Tracker& tracker, const GatherInputs& in, const GatherTargets& out,
                        const GatherSettings& s, const vxgi::ConeSettings& cone, gpu::GpuTimers* timers) const {
    const bool reduced = out.traceDiffuse != nullptr;
    const gpu::Image& outD = reduced ? *out.traceDiffuse : out.diffuse;
    const bool rays = in.rays != nullptr && in.clip == nullptr && s.trace == GatherTrace::Rays;
    // With the turned six cones the gather writes the turned term, resolved
    // into outD; rays differ from pixel to pixel and are filtered the same
    // way, more than once (recordResolve's ping-pong ends in outD).
    const bool spin = !rays && s.spin && cone.coneSet == sh::CONE_SET_6;
    const uint32_t passes = resolvePasses(s, rays, cone.coneSet);
    const bool resolve = passes > 0;
    const gpu::Image& tracedD = passes % 2 ? out.turnedDiffuse : outD;
    const gpu::Image& outS = reduced ? *out.traceSpecular : out.specular;
    const GBuffer& g = in.gbuffer;
    const vxgi::VoxelVolumes& v = in.volumes;
    const uint32_t traceWidth = outD.desc().extent.width, traceHeight = outD.desc().extent.height;
    const VkSampler point = in.samplers.point.handle();
    {
        gpu::GpuTimerScope timer(timers, cmd, "cone tracing");
        tracker.image(g.base, gpu::use::ShaderRead)
            .image(g.normal, gpu::use::ShaderRead)
            .image(g.depth, gpu::use::DepthRead)
            .image(v.radiance, gpu::use::ComputeRead);
        tracker.image(v.directional, gpu::use::ComputeRead);
        if (in.clip)
            tracker.image(in.clip->atlases.radiance, gpu::use::ComputeRead)
                .image(in.clip->atlases.directional, gpu::use::ComputeRead);
        if (rays) vxgi::trackRayReads(tracker, v, *in.rays);
        tracker.image(tracedD, gpu::use::ComputeWrite, true).image(outS, gpu::use::ComputeWrite, true).flush(cmd);
        const VkSampler volumeSampler = in.samplers.volume.handle();
        const gpu::Pipeline& pipeline = in.clip ? clipGather_ : rays ? rayGather_ : gather_;
        gpu::bind(cmd, pipeline);
        gpu::Descriptors d;
        if (in.clip) {
            d.uniformBuffer(sh::BIND_CONE_GRID, in.clip->levels.handle())
                .sampledImage(sh::BIND_GATHER_RADIANCE, in.clip->atlases.radiance.view(), volumeSampler,
                              VK_IMAGE_LAYOUT_GENERAL)
                .sampledImage(sh::BIND_CONE_DIRECTIONAL, in.clip->atlases.directional.view(), volumeSampler,
                              VK_IMAGE_LAYOUT_GENERAL);
        } else {
            d.uniformBuffer(sh::BIND_CONE_GRID, v.gridBuffer.handle())
                .sampledImage(sh::BIND_GATHER_RADIANCE, v.radiance.view(), volumeSampler, VK_IMAGE_LAYOUT_GENERAL)
                .sampledImage(sh::BIND_CONE_DIRECTIONAL, v.directional.view(), volumeSampler, VK_IMAGE_LAYOUT_GENERAL);
        }
        d.uniformBuffer(sh::BIND_GATHER_FRAME, in.frame.handle())
            .sampledImage(sh::BIND_GATHER_BASE, g.base.view(), point)
            .sampledImage(sh::BIND_GATHER_NORMAL, g.normal.view(), point)
            .sampledImage(sh::BIND_GATHER_DEPTH, g.depth.view(), point, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
            .storageImage(sh::BIND_GATHER_OUT_DIFFUSE, tracedD.view())
            .storageImage(sh::BIND_GATHER_OUT_SPECULAR, outS.view());
        if (rays) vxgi::bindRays(d, kRayBindings, v, *in.rays);
        d.push(ctx_, cmd, pipeline);
        sh::GatherPush push{};
        // Cones may run as far as the largest grid reaches.
        push.cone = vxgi::gpuCone(cone, in.clip ? in.clip->coarsest : v.grid);
        push.params = glm::vec4(0.0f, s.aoLambda, 0.0f, std::tan(glm::radians(s.minSpecularDegrees)));
        const uint32_t turn = !spin ? 0u : resolve ? 1u : 2u + uint32_t(s.fixedTurn) % sh::CONE_SPIN_STEPS;
        push.flags = glm::uvec4(turn, s.specular ? 1u : 0u, traceWidth, traceHeight);
        push.rays = glm::uvec4(s.rays, std::bit_cast<uint32_t>(s.rayOffsetVoxels), in.backsDark ? 1u : 0u, 0u);
        gpu::pushConstants(cmd, pipeline, VK_SHADER_STAGE_COMPUTE_BIT, push);
        vkCmdDispatch(cmd, gpu::groupCount(traceWidth, sh::GATHER_GROUP), gpu::groupCount(traceHeight, sh::GATHER_GROUP), 1);
    }
    if (resolve) recordResolve(cmd, tracker, in, passes, rays, out.turnedDiffuse, outD, timers);
    if (!reduced) return;
    gpu::GpuTimerScope timer(timers, cmd, "upsample");
    const uint32_t width = out.diffuse.desc().extent.width, height = out.diffuse.desc().extent.height;
    tracker.image(outD, gpu::use::ComputeRead)
        .image(outS, gpu::use::ComputeRead)
        .image(out.diffuse, gpu::use::ComputeWrite, true)
        .image(out.specular, gpu::use::ComputeWrite, true)
        .flush(cmd);
    gpu::bind(cmd, upsample_);
    gpu::Descriptors()
        .uniformBuffer(sh::BIND_UP_FRAME, in.frame.handle())
        .sampledImage(sh::BIND_UP_NORMAL, g.normal.view(), point)
        .sampledImage(sh::BIND_UP_DEPTH, g.depth.view(), point, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
        .storageImage(sh::BIND_UP_LOW_DIFFUSE, outD.view())
        .storageImage(sh::BIND_UP_LOW_SPECULAR, outS.view())
        .storageImage(sh::BIND_UP_OUT_DIFFUSE, out.diffuse.view())
        .storageImage(sh::BIND_UP_OUT_SPECULAR, out.specular.view())
        .push(ctx_, cmd, upsample_);
    const sh::UpsamplePush push{glm::uvec4(traceWidth, traceHeight, width, height)};
    gpu::pushConstants(cmd, upsample_, VK_SHADER_STAGE_COMPUTE_BIT, push);
    vkCmdDispatch(cmd, gpu::groupCount(width, sh::UPSAMPLE_GROUP), gpu::groupCount(height, sh::UPSAMPLE_GROUP), 1);
}

}  // namespace dvsgi::render
