#include "vxgi/pv_voxelize.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

#include "gpu/context.h"
#include "gpu/timers.h"
#include "gpu/tracker.h"
#include "shared/pv_pass.h"
#include "shared/voxel_list_pass.h"
#include "vxgi/voxel_list.h"
#include "vxgi/volumes.h"

namespace dvsgi::vxgi {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kCleanup[] = {
#include "shaders/pv_cleanup.comp.inc"
};
const uint32_t kInject[] = {
#include "shaders/pv_inject.comp.inc"
};
const uint32_t kBand[] = {
#include "shaders/pv_band.comp.inc"
};

// A voxel the camera sees in the depth band keeps one fragment's worth of its
// old sums: this frame's samples outweigh it, yet a voxel that no sample
// happens to land in keeps its material. Other survivors are capped only so
// that the float sums of voxels seen for a long time keep their precision.
constexpr float kBandWeight = 1.0f;
constexpr float kMaxWeight = 4096.0f;

}  // namespace

glm::uvec2 pvInjectionGrid(uint32_t width, uint32_t height, const PvSettings& settings) {
    const uint32_t longer = std::max(width, height);
    if (settings.grid == 0 || settings.grid >= longer) return {width, height};
    const double scale = double(settings.grid) / double(longer);
    return {std::max(1u, uint32_t(std::lround(width * scale))), std::max(1u, uint32_t(std::lround(height * scale)))};
}

PvVoxelizer::PvVoxelizer(const gpu::Context& ctx) : ctx_(ctx) {
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::LayoutDesc cleanup;
    cleanup.bindings = {{sh::BIND_PV_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                        {sh::BIND_PV_ACCUM, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                        {sh::BIND_PV_LIST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                        {sh::BIND_PV_INDEX, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                        {sh::BIND_PV_RADIANCE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                        {sh::BIND_PV_OLD_ACCUM, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                        {sh::BIND_PV_OLD_LIST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                        {sh::BIND_PV_VIEWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                        {sh::BIND_PV_CAMERA_DEPTH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, cs},
                        {sh::BIND_PV_SHADOW_DEPTH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, cs}};
    cleanup.pushConstantBytes = sizeof(sh::PvCleanupPush);
    cleanup.pushConstantStages = cs;
    cleanup_ = gpu::Pipeline(ctx, gpu::Spirv(kCleanup), cleanup, "pv cleanup");
    gpu::LayoutDesc inject;
    inject.bindings = {{sh::BIND_PV_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_PV_ACCUM, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_PV_LIST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_PV_INDEX, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_PV_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_PV_CAMERA_DEPTH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, cs},
                       {sh::BIND_PV_GBUFFER_BASE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, cs},
                       {sh::BIND_PV_GBUFFER_NORMAL, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, cs},
                       {sh::BIND_PV_GBUFFER_EMISSION, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, cs}};
    inject.pushConstantBytes = sizeof(sh::PvInjectPush);
    inject.pushConstantStages = cs;
    inject_ = gpu::Pipeline(ctx, gpu::Spirv(kInject), inject, "pv inject");
    inject.pushConstantBytes = sizeof(sh::PvBandPush);
    band_ = gpu::Pipeline(ctx, gpu::Spirv(kBand), inject, "pv inject (single pass)");
}

uint64_t PvVoxelizer::memoryBytes() const {
    return (otherAccum_ ? otherAccum_.memorySize() : 0) + (otherList_ ? otherList_.size() : 0);
}

void PvVoxelizer::cleanup(VkCommandBuffer cmd, gpu::Tracker& tracker, VoxelVolumes& v, const PvDepthInputs& depth,
                          gpu::GpuTimers* timers) {
    gpu::GpuTimerScope timer(timers, cmd, "pv cleanup");
    // The other half of the pair follows the volumes' size (they grow when
    // slots run out, and start over empty then).
    const VkExtent3D e = v.accum.desc().extent;
    const VkExtent3D o = otherAccum_ ? otherAccum_.desc().extent : VkExtent3D{};
    if (e.width != o.width || e.height != o.height || e.depth != o.depth) {
        gpu::ImageDesc d = v.accum.desc();
        d.name = "voxel attributes (pv, other)";
        otherAccum_ = gpu::Image(ctx_, d);
        otherList_ = gpu::Buffer(ctx_, v.list.size(),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                                     VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                 gpu::MemoryUse::Device, "occupied-voxel list (pv, other)");
    }
    std::swap(v.accum, otherAccum_);
    std::swap(v.list, otherList_);
    const gpu::Image& oldAccum = otherAccum_;
    const gpu::Buffer& oldList = otherList_;

    // The new sums start at zero (new slots are claimed onto zeros), the new
    // list empty with the volumes' capacity.
    tracker.image(v.accum, gpu::use::ClearGeneral, true).buffer(v.list, gpu::use::BufferTransferWrite).flush(cmd);
    const VkClearColorValue zero{};
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, v.accum.handle(), VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &range);
    recordEmptyList(cmd, v.list, v.slots);

    tracker.image(v.accum, gpu::use::ComputeWrite)
        .buffer(v.list, gpu::use::BufferComputeReadWrite)
        .buffer(v.index, gpu::use::BufferComputeWrite)
        .image(v.radiance, gpu::use::ComputeWrite)
        .image(oldAccum, gpu::use::ComputeRead)
        .buffer(oldList, gpu::use::IndirectComputeRead)
        .buffer(depth.views, gpu::use::BufferComputeRead)
        .image(depth.cameraDepth, gpu::use::DepthRead)
        .image(depth.shadowMap, gpu::use::ShaderRead)
        .flush(cmd);
    gpu::bind(cmd, cleanup_);
    gpu::Descriptors()
        .uniformBuffer(sh::BIND_PV_GRID, v.gridBuffer.handle())
        .storageImage(sh::BIND_PV_ACCUM, v.accum.view())
        .storageBuffer(sh::BIND_PV_LIST, v.list.handle())
        .storageBuffer(sh::BIND_PV_INDEX, v.index.handle())
        .storageImage(sh::BIND_PV_RADIANCE, v.radiance.view())
        .storageImage(sh::BIND_PV_OLD_ACCUM, oldAccum.view())
        .storageBuffer(sh::BIND_PV_OLD_LIST, oldList.handle())
        .storageBuffer(sh::BIND_PV_VIEWS, depth.views.handle())
        .sampledImage(sh::BIND_PV_CAMERA_DEPTH, depth.cameraDepth.view(), depth.pointSampler,
                      VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
        .sampledImage(sh::BIND_PV_SHADOW_DEPTH, depth.shadowMap.view(), depth.pointSampler)
        .push(ctx_, cmd, cleanup_);
    const VkExtent3D camera = depth.cameraDepth.desc().extent;
    const sh::PvCleanupPush push{
        glm::uvec4(depth.viewCount, camera.width, camera.height, depth.shadowMap.desc().extent.width),
        glm::vec4(kBandWeight, kMaxWeight, 0.5f * std::sqrt(3.0f) * v.grid.voxelSize, 0.0f)};
    gpu::pushConstants(cmd, cleanup_, VK_SHADER_STAGE_COMPUTE_BIT, push);
    dispatchOverList(cmd, oldList, offsetof(sh::VoxelListHeader, allGroups));
}

void PvVoxelizer::inject(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v, const PvGBufferInputs& g,
                         const PvSettings& settings, gpu::GpuTimers* timers) const {
    gpu::GpuTimerScope timer(timers, cmd, "pv inject");
    tracker.image(v.accum, gpu::use::ComputeReadWrite)
        .buffer(v.list, gpu::use::BufferComputeReadWrite)
        .buffer(v.index, gpu::use::BufferComputeReadWrite)
        .image(g.depth, gpu::use::DepthRead)
        .image(g.base, gpu::use::ShaderRead)
        .image(g.normal, gpu::use::ShaderRead)
        .image(g.emission, gpu::use::ShaderRead)
        .flush(cmd);
    const gpu::Pipeline& pipeline = settings.singlePass ? band_ : inject_;
    gpu::bind(cmd, pipeline);
    gpu::Descriptors()
        .uniformBuffer(sh::BIND_PV_GRID, v.gridBuffer.handle())
        .storageImage(sh::BIND_PV_ACCUM, v.accum.view())
        .storageBuffer(sh::BIND_PV_LIST, v.list.handle())
        .storageBuffer(sh::BIND_PV_INDEX, v.index.handle())
        .uniformBuffer(sh::BIND_PV_FRAME, g.frame.handle())
        .sampledImage(sh::BIND_PV_CAMERA_DEPTH, g.depth.view(), g.pointSampler, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
        .sampledImage(sh::BIND_PV_GBUFFER_BASE, g.base.view(), g.pointSampler)
        .sampledImage(sh::BIND_PV_GBUFFER_NORMAL, g.normal.view(), g.pointSampler)
        .sampledImage(sh::BIND_PV_GBUFFER_EMISSION, g.emission.view(), g.pointSampler)
        .push(ctx_, cmd, pipeline);
    const VkExtent3D size = g.depth.desc().extent;
    if (settings.singlePass) {
        const uint32_t n = v.grid.n, groups = (n + sh::PV_BAND_GROUP - 1) / sh::PV_BAND_GROUP;
        gpu::pushConstants(cmd, band_, VK_SHADER_STAGE_COMPUTE_BIT,
                           sh::PvBandPush{glm::uvec4(size.width, size.height, n, 0u),
                                          glm::vec4(0.5f * std::sqrt(3.0f) * v.grid.voxelSize, 0.0f, 0.0f, 0.0f)});
        vkCmdDispatch(cmd, groups, groups, groups);
        return;
    }
    const glm::uvec2 cells = pvInjectionGrid(size.width, size.height, settings);
    gpu::pushConstants(cmd, inject_, VK_SHADER_STAGE_COMPUTE_BIT,
                       sh::PvInjectPush{glm::uvec4(size.width, size.height, cells.x, cells.y)});
    vkCmdDispatch(cmd, (cells.x + sh::PV_INJECT_GROUP - 1) / sh::PV_INJECT_GROUP,
                  (cells.y + sh::PV_INJECT_GROUP - 1) / sh::PV_INJECT_GROUP, 1);
}

}  // namespace dvsgi::vxgi
