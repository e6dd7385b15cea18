#include "vxgi/voxelize.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "gpu/tracker.h"
#include "gpu/context.h"
#include "gpu/timers.h"
#include "gpuscene/scene_gpu.h"
#include "shared/voxel_list_pass.h"
#include "shared/voxelize_pass.h"
#include "vxgi/voxel_list.h"
#include "vxgi/volumes.h"
#include "vxgi/voxelize_compute.h"

namespace dvsgi::vxgi {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kVert[] = {
#include "shaders/voxelize.vert.inc"
};
const uint32_t kGeom[] = {
#include "shaders/voxelize.geom.inc"
};
const uint32_t kFrag[] = {
#include "shaders/voxelize.frag.inc"
};
const uint32_t kClear[] = {
#include "shaders/clear_listed.comp.inc"
};

// What Auto picks on CPU devices (lavapipe), from the bench runs in
// docs/benchmarks.md.
constexpr VoxelizerKind kCpuVoxelizer = VoxelizerKind::Compute;

}  // namespace

VoxelizerKind resolveVoxelizer(const gpu::Context& ctx, VoxelizerKind kind) {
    if (kind != VoxelizerKind::Auto) return kind;
    if (!ctx.features.float64) return VoxelizerKind::Geometry;
    switch (ctx.properties.deviceType) {
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return kCpuVoxelizer;
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        // Not measured yet: large GPUs have few raster units per SM (Hopper's
        // are few), and the geometry shader serializes primitives, while
        // the compute path spreads large triangles over tiles. A GPU bench run
        // must confirm it (docs/benchmarks.md).
        return VoxelizerKind::Compute;
    default:
        return VoxelizerKind::Geometry;  // unmeasured: the path the suite has always run
    }
}

const char* voxelizerName(VoxelizerKind kind) {
    switch (kind) {
    case VoxelizerKind::Geometry: return "geometry";
    case VoxelizerKind::Compute: return "compute";
    case VoxelizerKind::Auto: return "auto";
    case VoxelizerKind::Pv: return "pv";
    }
    return "?";
}

Voxelizer::Voxelizer(const gpu::Context& ctx, const gpuscene::SceneGpu& scene, bool hardwareConservative,
                     VoxelizerKind kind)
    : ctx_(ctx), hardware_(hardwareConservative && ctx.features.conservativeRaster), kind_(resolveVoxelizer(ctx, kind)) {
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::LayoutDesc clearLayout;
    clearLayout.bindings = {{sh::BIND_CLEAR_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                            {sh::BIND_CLEAR_ACCUM, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                            {sh::BIND_CLEAR_LIST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                            {sh::BIND_CLEAR_DIRECT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                            {sh::BIND_CLEAR_RADIANCE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                            {sh::BIND_CLEAR_INDEX, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                            {sh::BIND_CLEAR_EXTENTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs}};
    clearLayout.pushConstantBytes = sizeof(sh::ClearListedPush);
    clearLayout.pushConstantStages = cs;
    clear_ = gpu::Pipeline(ctx, gpu::Spirv(kClear), clearLayout, "clear listed voxels");
    if (kind_ == VoxelizerKind::Pv) {
        hardware_ = false;
        return;
    }
    if (kind_ == VoxelizerKind::Compute) {
        hardware_ = false;
        compute_ = std::make_unique<ComputeVoxelizer>(ctx, scene);
        return;
    }

    gpu::GraphicsDesc g;
    g.vertex = kVert;
    g.geometry = kGeom;
    g.fragment = kFrag;
    g.depthTest = false;
    g.depthWrite = false;
    g.conservative = hardware_;
    const VkShaderStageFlags vgf =
        VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_VOX_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, vgf},
                       {sh::BIND_VOX_DRAWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT},
                       {sh::BIND_VOX_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT},
                       {sh::BIND_VOX_ACCUM, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_FRAGMENT_BIT},
                       {sh::BIND_VOX_INDEX, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT},
                       {sh::BIND_VOX_LIST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT},
                       {sh::BIND_VOX_EXTENTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT}};
    layout.extraSet = scene.textureTable->layout();
    layout.pushConstantBytes = sizeof(sh::VoxelizePush);
    layout.pushConstantStages = vgf;
    voxelize_ = gpu::Pipeline(ctx, g, layout, "voxelize");
}

Voxelizer::~Voxelizer() = default;

void Voxelizer::clearAll(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v,
                         gpu::GpuTimers* timers) const {
    gpu::GpuTimerScope timer(timers, cmd, "clear all voxels");
    // Direct light and radiance too: the per-voxel passes write only occupied
    // voxels, so voxels the new static geometry leaves empty must read zero.
    const gpu::Image* cleared[] = {&v.accum, &v.direct, &v.radiance};
    for (const gpu::Image* img : cleared) tracker.image(*img, gpu::use::ClearGeneral, true);
    tracker.buffer(v.index, gpu::use::BufferTransferWrite).flush(cmd);
    vkCmdFillBuffer(cmd, v.index.handle(), 0, VK_WHOLE_SIZE, 0);
    const VkClearColorValue zero{};
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    for (const gpu::Image* img : cleared)
        vkCmdClearColorImage(cmd, img->handle(), VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &range);
}

void Voxelizer::clearDynamic(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v,
                             gpu::GpuTimers* timers) const {
    gpu::GpuTimerScope timer(timers, cmd, "clear dynamic voxels");
    clearListed(cmd, tracker, v, sh::CLEAR_LISTED_DYNAMIC);
}

void Voxelizer::clearOccupied(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v,
                              gpu::GpuTimers* timers) const {
    gpu::GpuTimerScope timer(timers, cmd, "clear occupied voxels");
    clearListed(cmd, tracker, v, sh::CLEAR_LISTED_ALL);
}

void Voxelizer::clearListed(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v, uint32_t scope) const {
    tracker.image(v.accum, gpu::use::ComputeWrite)
        .image(v.direct, gpu::use::ComputeWrite)
        .image(v.radiance, gpu::use::ComputeWrite)
        .buffer(v.index, gpu::use::BufferComputeWrite)
        .buffer(v.extents, gpu::use::BufferComputeWrite)
        .buffer(v.list, gpu::use::IndirectComputeRead)
        .flush(cmd);
    gpu::bind(cmd, clear_);
    gpu::Descriptors()
        .uniformBuffer(sh::BIND_CLEAR_GRID, v.gridBuffer.handle())
        .storageImage(sh::BIND_CLEAR_ACCUM, v.accum.view())
        .storageBuffer(sh::BIND_CLEAR_LIST, v.list.handle())
        .storageImage(sh::BIND_CLEAR_DIRECT, v.direct.view())
        .storageImage(sh::BIND_CLEAR_RADIANCE, v.radiance.view())
        .storageBuffer(sh::BIND_CLEAR_INDEX, v.index.handle())
        .storageBuffer(sh::BIND_CLEAR_EXTENTS, v.extents.handle())
        .push(ctx_, cmd, clear_);
    gpu::pushConstants(cmd, clear_, VK_SHADER_STAGE_COMPUTE_BIT, sh::ClearListedPush{glm::uvec4(scope, 0u, 0u, 0u)});
    dispatchOverList(cmd, v.list,
                     scope == sh::CLEAR_LISTED_ALL ? offsetof(sh::VoxelListHeader, allGroups)
                                                   : offsetof(sh::VoxelListHeader, dynamicGroups));
}

void Voxelizer::voxelize(VkCommandBuffer cmd, gpu::Tracker& tracker, const gpuscene::SceneGpu& scene,
                         const VoxelVolumes& v, VoxelizeMode mode, gpu::GpuTimers* timers) const {
    const bool dynamic = mode == VoxelizeMode::Dynamic;
    if (kind_ == VoxelizerKind::Pv) throw std::logic_error("the pv voxelizer is PvVoxelizer's; Voxelizer only clears");
    gpu::GpuTimerScope timer(timers, cmd, dynamic ? "voxelize dynamic" : "voxelize static");
    if (compute_) {
        compute_->voxelize(cmd, tracker, scene, v, mode);
        return;
    }
    tracker.image(v.accum, gpu::use::VoxelizeReadWrite)
        .buffer(v.index, gpu::use::FragmentReadWrite)
        .buffer(v.list, gpu::use::FragmentReadWrite)
        .buffer(v.extents, gpu::use::FragmentReadWrite)
        .flush(cmd);
    voxelizeRaster(cmd, scene, v, dynamic);
}

void Voxelizer::voxelizeRaster(VkCommandBuffer cmd, const gpuscene::SceneGpu& scene, const VoxelVolumes& v,
                               bool dynamic) const {
    const uint32_t n = v.grid.n;
    const VkRect2D area{{0, 0}, {n, n}};
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = area;  // no attachments: fragments only write the volumes
    ri.layerCount = 1;
    vkCmdBeginRendering(cmd, &ri);
    gpu::bind(cmd, voxelize_);
    gpu::Descriptors()
        .uniformBuffer(sh::BIND_VOX_GRID, v.gridBuffer.handle())
        .storageBuffer(sh::BIND_VOX_DRAWS, scene.draws.handle())
        .storageBuffer(sh::BIND_VOX_MATERIALS, scene.materials.handle())
        .storageImage(sh::BIND_VOX_ACCUM, v.accum.view())
        .storageBuffer(sh::BIND_VOX_INDEX, v.index.handle())
        .storageBuffer(sh::BIND_VOX_LIST, v.list.handle())
        .storageBuffer(sh::BIND_VOX_EXTENTS, v.extents.handle())
        .push(ctx_, cmd, voxelize_);
    scene.bindGeometry(cmd, voxelize_.layout());
    const VkViewport viewport{0, 0, float(n), float(n), 0, 1};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &area);
    const VkShaderStageFlags vgf =
        VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    // The dilation must outgrow the rasterizer's vertex snapping (see
    // voxelize.geom): two steps of its sub-pixel grid, 1/128 pixel at 8 bits.
    const int subPixelBits = int(std::max(ctx_.properties.limits.subPixelPrecisionBits, 1u));
    const float margin = std::ldexp(1.0f, 1 - subPixelBits);
    const uint32_t marginBits = std::bit_cast<uint32_t>(margin);
    for (uint32_t i = 0; i < scene.ranges.size(); ++i) {
        const gpuscene::DrawRange& r = scene.ranges[i];
        if (r.dynamic != dynamic) continue;
        const sh::VoxelizePush push{glm::uvec4(i, 0, 0, 0),
                                    glm::uvec4(dynamic ? sh::VOXELIZE_DYNAMIC : sh::VOXELIZE_STATIC,
                                               hardware_ ? 0u : 1u, marginBits, 0u)};
        gpu::pushConstants(cmd, voxelize_, vgf, push);
        vkCmdDrawIndexed(cmd, r.indexCount, 1, r.firstIndex, r.vertexOffset, 0);
    }
    vkCmdEndRendering(cmd);
}

void Voxelizer::setComputeTiling(ComputeTiling tiling) {
    if (compute_) compute_->setTiling(tiling);
}

}  // namespace dvsgi::vxgi
