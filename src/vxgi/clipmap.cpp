#include "vxgi/clipmap.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "gpu/barriers.h"
#include "gpu/context.h"
#include "gpu/timers.h"
#include "gpu/tracker.h"
#include "shared/clipmap_pass.h"
#include "shared/voxel_list_pass.h"
#include "vxgi/voxel_list.h"

namespace dvsgi::vxgi {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kScroll[] = {
#include "shaders/clipmap_scroll.comp.inc"
};

int floorDiv(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

}  // namespace

float clipBaseVoxelSize(const scene::Bounds& bounds, uint32_t n, uint32_t levels, const glm::vec3& eye) {
    const glm::vec3 size = bounds.valid() ? bounds.max - bounds.min : glm::vec3(2.0f);
    float half = std::max({size.x, size.y, size.z, 1e-3f});
    if (bounds.valid()) {
        // A camera outside the scene (a Cornell box seen from its open side)
        // needs a window that reaches the far face; the window sits up to a
        // snap step and a voxel off the camera, so that many coarse voxels
        // are kept spare.
        const glm::vec3 reach = glm::max(eye - bounds.min, bounds.max - eye);
        const float spare = float(clipSpareVoxels(n));
        half = std::max(half, std::max({reach.x, reach.y, reach.z}) * float(n) / (float(n) - 2.0f * spare));
    }
    return 2.0f * half / (float(n) * std::ldexp(1.0f, int(levels) - 1));
}

bool clipCoarsestHolds(const scene::Bounds& bounds, const glm::vec3& eye, const glm::vec3& lattice, float voxelSize0,
                       uint32_t n, uint32_t levels) {
    if (!bounds.valid()) return true;
    const float size = voxelSize0 * std::ldexp(1.0f, int(levels) - 1);
    const GridSpec g = clipLevelGrid(clipWindowMin(eye, lattice, size, n), lattice, size, n);
    const glm::vec3 hi = g.origin + glm::vec3(float(n) * size);
    return glm::all(glm::greaterThanEqual(bounds.min, g.origin)) && glm::all(glm::lessThanEqual(bounds.max, hi));
}

glm::vec3 clipLattice(const scene::Bounds& bounds, float voxelSize0) {
    if (!bounds.valid()) return glm::vec3(0.0f);
    // Reduced modulo the voxel so the origin stays near 0 (float precision).
    const glm::vec3 o = bounds.min - 0.5f * voxelSize0;
    return o - voxelSize0 * glm::floor(o / voxelSize0);
}

glm::ivec3 clipWindowMin(const glm::vec3& centre, const glm::vec3& lattice, float voxelSize, uint32_t n) {
    glm::ivec3 m;
    for (int a = 0; a < 3; ++a) {
        const double lowest = std::floor(double(centre[a] - lattice[a]) / double(voxelSize)) - double(n / 2);
        m[a] = floorDiv(int(lowest) + kClipSnapVoxels / 2, kClipSnapVoxels) * kClipSnapVoxels;
    }
    return m;
}

GridSpec clipLevelGrid(const glm::ivec3& windowMin, const glm::vec3& lattice, float voxelSize, uint32_t n) {
    GridSpec g;
    g.origin = lattice + glm::vec3(windowMin) * voxelSize;
    g.voxelSize = voxelSize;
    g.n = n;
    const int ni = int(n);
    g.wrap = glm::ivec3(((windowMin.x % ni) + ni) % ni, ((windowMin.y % ni) + ni) % ni, ((windowMin.z % ni) + ni) % ni);
    return g;
}

sh::ConeLevels coneLevels(const std::vector<const VoxelVolumes*>& levels) {
    sh::ConeLevels c{};
    for (size_t l = 0; l < levels.size() && l < sh::MAX_CLIP_LEVELS; ++l)
        c.level[l] = gpuVoxelGrid(levels[l]->grid, levels[l]->slots);
    c.count = glm::uvec4(uint32_t(std::min<size_t>(levels.size(), sh::MAX_CLIP_LEVELS)), 0u, 0u, 0u);
    return c;
}

ClipAtlases::ClipAtlases(const gpu::Context& ctx, uint32_t n, uint32_t levels) {
    gpu::ImageDesc d;
    d.type = VK_IMAGE_TYPE_3D;
    d.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    // Transfer source: recordAtlasFold copies within the directional atlas;
    // tests and debugging read both back.
    d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    d.extent = {n, n, n * levels};
    d.name = "clipmap radiance atlas";
    radiance = gpu::Image(ctx, d);
    d.extent = {sh::DIRECTIONAL_VOLUMES * (n / 2), n / 2, (n / 2) * levels};
    d.mipLevels = directionalMipCount(n);
    d.name = "clipmap directional atlas";
    directional = gpu::Image(ctx, d);
}

void recordAtlasCopy(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v, uint32_t l,
                     const ClipAtlases& atlases) {
    tracker.image(v.radiance, gpu::use::CopySrcGeneral).image(v.directional, gpu::use::CopySrcGeneral);
    // Each level's slab is written whole: the rest of the atlas keeps its contents.
    tracker.image(atlases.radiance, gpu::use::CopyDstGeneral).image(atlases.directional, gpu::use::CopyDstGeneral);
    tracker.flush(cmd);
    const uint32_t n = v.grid.n;
    VkImageCopy r{};
    r.srcSubresource = r.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    r.dstOffset = {0, 0, int32_t(n * l)};
    r.extent = {n, n, n};
    vkCmdCopyImage(cmd, v.radiance.handle(), VK_IMAGE_LAYOUT_GENERAL, atlases.radiance.handle(),
                   VK_IMAGE_LAYOUT_GENERAL, 1, &r);
    std::vector<VkImageCopy> mips;
    for (uint32_t k = 0; k < v.directionalMips; ++k) {
        const uint32_t side = std::max(1u, (n / 2) >> k);
        VkImageCopy m{};
        m.srcSubresource = m.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, k, 0, 1};
        m.dstOffset = {0, 0, int32_t(side * l)};
        m.extent = {sh::DIRECTIONAL_VOLUMES * side, side, side};
        mips.push_back(m);
    }
    vkCmdCopyImage(cmd, v.directional.handle(), VK_IMAGE_LAYOUT_GENERAL, atlases.directional.handle(),
                   VK_IMAGE_LAYOUT_GENERAL, uint32_t(mips.size()), mips.data());
}

void recordAtlasFold(VkCommandBuffer cmd, gpu::Tracker& tracker, const std::vector<const VoxelVolumes*>& levels,
                     const ClipAtlases& atlases) {
    tracker.image(atlases.directional, gpu::use::CopyDstGeneral).flush(cmd);
    for (size_t l = 1; l < levels.size(); ++l) {
        const GridSpec& fine = levels[l - 1]->grid;
        const GridSpec& coarse = levels[l]->grid;
        // The fine window's corner in voxels of the coarse level, from the
        // coarse one's (whole: the levels share their lattice, windows snap).
        const glm::ivec3 offset = glm::ivec3(glm::round((fine.origin - coarse.origin) / coarse.voxelSize));
        std::vector<VkImageCopy> regions;
        for (uint32_t k = 0; k + 1 < levels[l]->directionalMips; ++k) {
            const int cell = 2 << k;  // voxels of the coarse level per cell of its mip k
            if (offset.x % cell || offset.y % cell || offset.z % cell) break;
            const uint32_t side = (coarse.n / 2) >> k, half = side / 2;
            const glm::ivec3 at = offset / cell;
            for (uint32_t d = 0; d < sh::DIRECTIONAL_VOLUMES; ++d) {
                VkImageCopy r{};
                r.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, k + 1, 0, 1};
                r.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, k, 0, 1};
                r.srcOffset = {int32_t(d * half), 0, int32_t((l - 1) * half)};
                r.dstOffset = {int32_t(d * side) + at.x, at.y, int32_t(l * side) + at.z};
                r.extent = {half, half, half};
                regions.push_back(r);
            }
        }
        // Level l - 1's mips may have been written by its own fold just before.
        gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT);
        if (!regions.empty())
            vkCmdCopyImage(cmd, atlases.directional.handle(), VK_IMAGE_LAYOUT_GENERAL, atlases.directional.handle(),
                           VK_IMAGE_LAYOUT_GENERAL, uint32_t(regions.size()), regions.data());
    }
}

ClipScrollPass::ClipScrollPass(const gpu::Context& ctx) : ctx_(ctx) {
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_SCROLL_ACCUM, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_SCROLL_DIRECT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_SCROLL_INDEX, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_SCROLL_LIST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_SCROLL_EXTENTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs}};
    layout.pushConstantBytes = sizeof(sh::ClipScrollPush);
    layout.pushConstantStages = cs;
    pipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kScroll), layout, "clipmap scroll");
}

void ClipScrollPass::record(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v,
                            const glm::ivec3& oldMin, const glm::ivec3& newMin, gpu::GpuTimers* timers) const {
    gpu::GpuTimerScope timer(timers, cmd, kClipmapScrollTimer);
    tracker.image(v.accum, gpu::use::ComputeWrite).image(v.direct, gpu::use::ComputeWrite);
    tracker.buffer(v.index, gpu::use::BufferComputeReadWrite).buffer(v.extents, gpu::use::BufferComputeWrite);
    tracker.buffer(v.list, gpu::use::IndirectComputeReadWrite).flush(cmd);
    gpu::bind(cmd, pipeline_);
    gpu::Descriptors()
        .storageImage(sh::BIND_SCROLL_ACCUM, v.accum.view())
        .storageImage(sh::BIND_SCROLL_DIRECT, v.direct.view())
        .storageBuffer(sh::BIND_SCROLL_INDEX, v.index.handle())
        .storageBuffer(sh::BIND_SCROLL_LIST, v.list.handle())
        .storageBuffer(sh::BIND_SCROLL_EXTENTS, v.extents.handle())
        .push(ctx_, cmd, pipeline_);
    const sh::ClipScrollPush push{glm::ivec4(oldMin, int(v.grid.n)), glm::ivec4(newMin, int(v.grid.n))};
    gpu::pushConstants(cmd, pipeline_, VK_SHADER_STAGE_COMPUTE_BIT, push);
    dispatchOverList(cmd, v.list, offsetof(sh::VoxelListHeader, allGroups));
}

}  // namespace dvsgi::vxgi
