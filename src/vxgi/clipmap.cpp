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

std::vector<VkImageView> ClipTrace::radianceViews() const {
    std::vector<VkImageView> views;
    for (uint32_t l = 0; l < sh::MAX_CLIP_LEVELS; ++l)
        views.push_back(volumes[std::min<size_t>(l, volumes.size() - 1)]->radiance.view());
    return views;
}

std::vector<VkImageView> ClipTrace::directionalViews() const {
    std::vector<VkImageView> views;
    for (uint32_t l = 0; l < sh::MAX_CLIP_LEVELS; ++l)
        views.push_back(volumes[std::min<size_t>(l, volumes.size() - 1)]->directional.view());
    return views;
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
