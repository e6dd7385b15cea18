#include "vxgi/clipmap.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

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

float clipBaseVoxelSize(const scene::Bounds& bounds, uint32_t n, uint32_t levels) {
    const glm::vec3 size = bounds.valid() ? bounds.max - bounds.min : glm::vec3(2.0f);
    const float side = std::max({size.x, size.y, size.z, 1e-3f});
    return 2.0f * side / (float(n) * std::ldexp(1.0f, int(levels) - 1));
}

glm::ivec3 clipWindowMin(const glm::vec3& centre, float voxelSize, uint32_t n) {
    glm::ivec3 m;
    for (int a = 0; a < 3; ++a) {
        const double lowest = std::floor(double(centre[a]) / double(voxelSize)) - double(n / 2);
        m[a] = floorDiv(int(lowest) + kClipSnapVoxels / 2, kClipSnapVoxels) * kClipSnapVoxels;
    }
    return m;
}

GridSpec clipLevelGrid(const glm::ivec3& windowMin, float voxelSize, uint32_t n) {
    GridSpec g;
    g.origin = glm::vec3(windowMin) * voxelSize;
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
    d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
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

ClipScrollPass::ClipScrollPass(const gpu::Context& ctx) : ctx_(ctx) {
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_SCROLL_ACCUM, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_SCROLL_DIRECT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_SCROLL_INDEX, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_SCROLL_LIST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs}};
    layout.pushConstantBytes = sizeof(sh::ClipScrollPush);
    layout.pushConstantStages = cs;
    pipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kScroll), layout, "clipmap scroll");
}

void ClipScrollPass::record(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& v,
                            const glm::ivec3& oldMin, const glm::ivec3& newMin, gpu::GpuTimers* timers) const {
    gpu::GpuTimerScope timer(timers, cmd, "clipmap scroll");
    tracker.image(v.accum, gpu::use::ComputeWrite).image(v.direct, gpu::use::ComputeWrite);
    tracker.buffer(v.index, gpu::use::BufferComputeReadWrite);
    tracker.buffer(v.list, gpu::use::IndirectComputeReadWrite).flush(cmd);
    gpu::bind(cmd, pipeline_);
    gpu::Descriptors()
        .storageImage(sh::BIND_SCROLL_ACCUM, v.accum.view())
        .storageImage(sh::BIND_SCROLL_DIRECT, v.direct.view())
        .storageBuffer(sh::BIND_SCROLL_INDEX, v.index.handle())
        .storageBuffer(sh::BIND_SCROLL_LIST, v.list.handle())
        .push(ctx_, cmd, pipeline_);
    const sh::ClipScrollPush push{glm::ivec4(oldMin, int(v.grid.n)), glm::ivec4(newMin, int(v.grid.n))};
    gpu::pushConstants(cmd, pipeline_, VK_SHADER_STAGE_COMPUTE_BIT, push);
    dispatchOverList(cmd, v.list, offsetof(sh::VoxelListHeader, allGroups));
}

}  // namespace dvsgi::vxgi
