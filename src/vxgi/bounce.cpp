#include "vxgi/bounce.h"

#include <algorithm>
#include <bit>
#include <cstddef>

#include "gpu/context.h"
#include "gpu/timers.h"
#include "gpu/tracker.h"
#include "shared/bounce_pass.h"
#include "shared/voxel_list_pass.h"
#include "vxgi/clipmap.h"
#include "vxgi/voxel_list.h"
#include "vxgi/volumes.h"

namespace dvsgi::vxgi {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kBounce[] = {
#include "shaders/bounce.comp.inc"
};
const uint32_t kBounceClipmap[] = {
#include "shaders/bounce_clipmap.comp.inc"
};
const uint32_t kBounceRayNormals[] = {
#include "shaders/bounce_ray_normals.comp.inc"
};
const uint32_t kBounceRayTrace[] = {
#include "shaders/bounce_ray_trace.comp.inc"
};
const uint32_t kBounceTraced[] = {
#include "shaders/bounce_traced.comp.inc"
};

}  // namespace

gpu::ImageDesc historyImageDesc(uint32_t slots) {
    gpu::ImageDesc d;
    d.type = VK_IMAGE_TYPE_3D;
    d.format = VK_FORMAT_R32G32B32A32_UINT;
    d.extent = {sh::VOXEL_SLOT_ROW, std::max(slots / sh::VOXEL_SLOT_ROW, 1u), 1};
    d.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    d.name = "voxel radiance history";
    return d;
}

static_assert(sh::BOUNCE_RAYS_SLOT_BYTES == 2 * sizeof(uint32_t), "tracedImageDesc's texel is RG32UI");

namespace {

// A storage image with one `format` texel per slot, laid out as the history.
gpu::ImageDesc slotImageDesc(uint32_t slots, VkFormat format, const char* name) {
    gpu::ImageDesc d = historyImageDesc(slots);
    d.format = format;
    d.usage = VK_IMAGE_USAGE_STORAGE_BIT;
    d.name = name;
    return d;
}

}  // namespace

gpu::ImageDesc tracedImageDesc(uint32_t slots) {
    return slotImageDesc(slots, VK_FORMAT_R32G32_UINT, "voxel bounce rays' light");
}

static_assert(sh::BOUNCE_RAY_NORMAL_SLOT_BYTES == sizeof(uint32_t), "rayNormalsImageDesc's texel is R32UI");
static_assert(3 * sh::RAY_NORMAL_BITS <= 30 && sh::RAY_NORMAL_SCALE < float(1u << (sh::RAY_NORMAL_BITS - 1)) &&
                  sh::RAY_NORMAL_FACES_BIT == 1u << 30 && sh::RAY_NORMAL_EXTENTS_BIT == 1u << 31,
              "a packed ray normal's three axes fit one word below its two flags");

gpu::ImageDesc rayNormalsImageDesc(uint32_t slots) {
    return slotImageDesc(slots, VK_FORMAT_R32_UINT, "voxel rays' normals");
}

VkDeviceSize rayOccupancyBytes(uint32_t n) {
    return VkDeviceSize(sh::rayOccupancyOffset(n, sh::RAY_OCCUPANCY_LEVELS)) * sizeof(uint32_t);
}

void addRayBindings(gpu::LayoutDesc& layout, const RayBindings& b) {
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    layout.bindings.push_back({b.sides, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs});
    layout.bindings.push_back({b.index, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs});
    layout.bindings.push_back({b.normals, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs});
    layout.bindings.push_back({b.occupancy, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs});
    layout.bindings.push_back({b.extents, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs});
}

void trackRayReads(gpu::Tracker& tracker, const VoxelVolumes& v, const RayData& rays) {
    tracker.image(v.sides, gpu::use::ComputeRead)
        .image(rays.normals, gpu::use::ComputeRead)
        .buffer(v.index, gpu::use::BufferComputeRead)
        .buffer(rays.occupancy, gpu::use::BufferComputeRead)
        .buffer(v.extents, gpu::use::BufferComputeRead);
}

void bindRays(gpu::Descriptors& d, const RayBindings& b, const VoxelVolumes& v, const RayData& rays) {
    d.storageImage(b.sides, v.sides.view())
        .storageBuffer(b.index, v.index.handle())
        .storageImage(b.normals, rays.normals.view())
        .storageBuffer(b.occupancy, rays.occupancy.handle())
        .storageBuffer(b.extents, v.extents.handle());
}

BouncePass::BouncePass(const gpu::Context& ctx, bool clipmap) : ctx_(ctx) {
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_CONE_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_CONE_DIRECTIONAL, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, cs},
                       {sh::BIND_BOUNCE_ACCUM, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_BOUNCE_DIRECT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_BOUNCE_OUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_BOUNCE_STATS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_BOUNCE_LIST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_BOUNCE_HISTORY, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_BOUNCE_SIDES, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs}};
    layout.pushConstantBytes = sizeof(sh::BouncePush);
    layout.pushConstantStages = cs;
    pipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kBounce), layout, "voxel bounce");
    gpu::LayoutDesc rays = layout;
    rays.bindings.push_back({sh::BIND_BOUNCE_TRACED, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs});
    rays.bindings.push_back({sh::BIND_BOUNCE_INDEX, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs});
    rays.bindings.push_back({sh::BIND_BOUNCE_RAY_NORMALS, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs});
    rays.bindings.push_back({sh::BIND_BOUNCE_RAY_OCCUPANCY, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs});
    rays.bindings.push_back({sh::BIND_BOUNCE_EXTENTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs});
    rayNormalsPipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kBounceRayNormals), rays, "voxel bounce rays' normals");
    rayPipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kBounceRayTrace), rays, "voxel bounce rays");
    rayShadePipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kBounceTraced), rays, "voxel bounce (rays' light)");
    if (clipmap) {
        layout.bindings.push_back({sh::BIND_BOUNCE_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs});
        layout.bindings.push_back({sh::BIND_BOUNCE_LEVELS_BEFORE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, cs});
        clipPipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kBounceClipmap), layout, "voxel bounce (clipmap)");
    }
    noStats_ = gpu::Buffer(ctx, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUse::Device, "bounce stats (unused)");
    gpu::ImageDesc d = historyImageDesc(0);
    d.name = "voxel radiance history (unused)";
    noHistory_ = gpu::Image(ctx, d);
}

uint32_t BouncePass::statsFloats(uint32_t slots) { return voxelListMaxGroups(slots) * sh::BOUNCE_STATS_FLOATS; }

void BouncePass::recordRayData(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v, RayData& rd,
                               gpu::GpuTimers* timers) const {
    gpu::GpuTimerScope timer(timers, cmd, "voxel rays' normals");
    recordRayNormals(cmd, tracker, v, rd);
}

void BouncePass::recordRayNormals(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v,
                                  RayData& rd) const {
    const gpu::ImageDesc want = rayNormalsImageDesc(v.slots);
    if (!rd.normals.handle() || rd.normals.desc().extent.height != want.extent.height)
        rd.normals = gpu::Image(ctx_, want);
    const VkDeviceSize occupancyBytes = rayOccupancyBytes(v.grid.n);
    if (!rd.occupancy.handle() || rd.occupancy.size() != occupancyBytes)
        rd.occupancy = gpu::Buffer(ctx_, occupancyBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                   gpu::MemoryUse::Device, "voxel rays' occupancy bits");
    // Set bit by bit from this frame's voxels.
    tracker.buffer(rd.occupancy, gpu::use::BufferTransferWrite).flush(cmd);
    vkCmdFillBuffer(cmd, rd.occupancy.handle(), 0, VK_WHOLE_SIZE, 0);
    tracker.buffer(rd.occupancy, gpu::use::BufferComputeReadWrite)
        .buffer(v.list, gpu::use::IndirectComputeRead)
        .image(v.accum, gpu::use::ComputeRead)
        .buffer(v.extents, gpu::use::BufferComputeRead)
        .image(rd.normals, gpu::use::ComputeWrite)
        .flush(cmd);
    gpu::bind(cmd, rayNormalsPipeline_);
    gpu::Descriptors()
        .uniformBuffer(sh::BIND_CONE_GRID, v.gridBuffer.handle())
        .storageImage(sh::BIND_BOUNCE_ACCUM, v.accum.view())
        .storageBuffer(sh::BIND_BOUNCE_LIST, v.list.handle())
        .storageImage(sh::BIND_BOUNCE_RAY_NORMALS, rd.normals.view())
        .storageBuffer(sh::BIND_BOUNCE_RAY_OCCUPANCY, rd.occupancy.handle())
        .storageBuffer(sh::BIND_BOUNCE_EXTENTS, v.extents.handle())
        .push(ctx_, cmd, rayNormalsPipeline_);
    sh::BouncePush push{};
    push.flags = glm::uvec4(rd.edgeFaces ? 1u : 0u, 0u, 0u, 0u);
    gpu::pushConstants(cmd, rayNormalsPipeline_, VK_SHADER_STAGE_COMPUTE_BIT, push);
    dispatchOverList(cmd, v.list, offsetof(sh::VoxelListHeader, allGroups));
    tracker.image(rd.normals, gpu::use::ComputeRead).buffer(rd.occupancy, gpu::use::BufferComputeRead).flush(cmd);
    rd.packed = true;
}

void BouncePass::record(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v, VkSampler volumeSampler,
                        const ConeSettings& cone, uint32_t rayCount, RayData* rayData, bool backsDark,
                        const gpu::Buffer* stats,
                        gpu::GpuTimers* timers, const ClipTrace* clip, uint32_t level,
                        const VoxelHistory* history) const {
    gpu::GpuTimerScope timer(timers, cmd, "voxel bounce");
    tracker.image(v.accum, gpu::use::ComputeRead).image(v.direct, gpu::use::ComputeRead);
    tracker.image(v.sides, gpu::use::ComputeReadWrite);
    tracker.image(v.directional, gpu::use::ComputeRead);
    if (clip) tracker.image(clip->atlases.directional, gpu::use::ComputeRead);
    if (clip) tracker.image(clip->atlases.radiance, gpu::use::ComputeRead);
    // Read and written: the statistics compare each voxel with its value before.
    tracker.image(v.radiance, gpu::use::ComputeReadWrite);
    tracker.buffer(v.list, gpu::use::IndirectComputeRead);
    const gpu::Image& historyImage = history ? *history->image : noHistory_;
    tracker.image(historyImage, gpu::use::ComputeReadWrite);
    if (stats) {
        // Only the dispatched groups write their slots: zero them all first.
        tracker.buffer(*stats, gpu::use::BufferTransferWrite).flush(cmd);
        vkCmdFillBuffer(cmd, stats->handle(), 0, VK_WHOLE_SIZE, 0);
        tracker.buffer(*stats, gpu::use::BufferComputeWrite);
    }
    const bool rays = rayCount > 0 && !clip && rayData;
    if (rays) {
        const gpu::ImageDesc want = tracedImageDesc(v.slots);
        if (!traced_.handle() || traced_.desc().extent.height != want.extent.height) traced_ = gpu::Image(ctx_, want);
        tracker.flush(cmd);
        if (!rayData->packed) recordRayNormals(cmd, tracker, v, *rayData);
        tracker.buffer(v.index, gpu::use::BufferComputeRead).buffer(v.extents, gpu::use::BufferComputeRead);
        // The rays read the radiance and side light that the shading pass after them writes.
        tracker.image(v.radiance, gpu::use::ComputeRead).image(v.sides, gpu::use::ComputeRead);
        tracker.image(traced_, gpu::use::ComputeWrite);
    }
    tracker.flush(cmd);
    const gpu::Pipeline& pipeline = rays ? rayShadePipeline_ : (clip ? clipPipeline_ : pipeline_);
    gpu::Descriptors d;
    if (clip) {
        d.uniformBuffer(sh::BIND_CONE_GRID, clip->levels.handle())
            .uniformBuffer(sh::BIND_BOUNCE_GRID, v.gridBuffer.handle())
            .sampledImage(sh::BIND_CONE_DIRECTIONAL, clip->atlases.directional.view(), volumeSampler,
                          VK_IMAGE_LAYOUT_GENERAL)
            .sampledImage(sh::BIND_BOUNCE_LEVELS_BEFORE, clip->atlases.radiance.view(), volumeSampler,
                          VK_IMAGE_LAYOUT_GENERAL);
    } else {
        d.uniformBuffer(sh::BIND_CONE_GRID, v.gridBuffer.handle())
            .sampledImage(sh::BIND_CONE_DIRECTIONAL, v.directional.view(), volumeSampler, VK_IMAGE_LAYOUT_GENERAL);
    }
    d.storageImage(sh::BIND_BOUNCE_ACCUM, v.accum.view())
        .storageImage(sh::BIND_BOUNCE_DIRECT, v.direct.view())
        .storageImage(sh::BIND_BOUNCE_OUT, v.radiance.view())
        .storageBuffer(sh::BIND_BOUNCE_STATS, stats ? stats->handle() : noStats_.handle())
        .storageBuffer(sh::BIND_BOUNCE_LIST, v.list.handle())
        .storageImage(sh::BIND_BOUNCE_HISTORY, historyImage.view())
        .storageImage(sh::BIND_BOUNCE_SIDES, v.sides.view());
    if (rays) {
        d.storageImage(sh::BIND_BOUNCE_TRACED, traced_.view())
            .storageBuffer(sh::BIND_BOUNCE_INDEX, v.index.handle())
            .storageImage(sh::BIND_BOUNCE_RAY_NORMALS, rayData->normals.view())
            .storageBuffer(sh::BIND_BOUNCE_RAY_OCCUPANCY, rayData->occupancy.handle())
            .storageBuffer(sh::BIND_BOUNCE_EXTENTS, v.extents.handle());
    }
    const glm::uvec4 blend = history ? glm::uvec4(history->tag, history->previousTag,
                                                  std::bit_cast<uint32_t>(history->alpha), 0u)
                                     : glm::uvec4(0u);
    const sh::BouncePush push{gpuCone(cone, clip ? clip->coarsest : v.grid),
                              glm::uvec4(stats ? 1u : 0u, level, backsDark ? 1u : 0u, rays ? rayCount : 0u), blend};
    if (rays) {
        gpu::bind(cmd, rayPipeline_);
        d.push(ctx_, cmd, rayPipeline_);
        gpu::pushConstants(cmd, rayPipeline_, VK_SHADER_STAGE_COMPUTE_BIT, push);
        dispatchOverList(cmd, v.list, offsetof(sh::VoxelListHeader, allGroups));
        tracker.image(traced_, gpu::use::ComputeRead);
        tracker.image(v.radiance, gpu::use::ComputeReadWrite).image(v.sides, gpu::use::ComputeReadWrite).flush(cmd);
    }
    gpu::bind(cmd, pipeline);
    d.push(ctx_, cmd, pipeline);
    gpu::pushConstants(cmd, pipeline, VK_SHADER_STAGE_COMPUTE_BIT, push);
    dispatchOverList(cmd, v.list, offsetof(sh::VoxelListHeader, allGroups));
    if (stats) tracker.buffer(*stats, gpu::use::HostRead).flush(cmd);
}

}  // namespace dvsgi::vxgi
