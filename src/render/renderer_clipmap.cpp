// The Renderer's clipmap (--clipmap L, docs/clipmap.md): L levels of N^3 that
// follow the camera. Each frame every level's window is placed around the
// camera; a level whose window moved frees the voxels that left it (the scroll
// pass) and voxelizes only the slabs it exposed, then every level runs the
// per-voxel passes as a fitted grid does; cones trace across the levels.
#include "render/renderer.h"

#include <cstring>
#include <stdexcept>
#include <string>

#include "gpu/context.h"
#include "gpu/timers.h"
#include "gpu/tracker.h"
#include "gpuscene/scene_gpu.h"
#include "shared/voxel_list_pass.h"
#include "vxgi/aniso_filter.h"
#include "vxgi/voxel_list.h"
#include "vxgi/voxelize.h"

namespace dvsgi::render {

namespace sh = dvsgi::shader;

namespace {

std::unique_ptr<gpu::Buffer> coneLevelsBuffer(const gpu::Context& ctx, const char* name) {
    return std::make_unique<gpu::Buffer>(ctx, sizeof(sh::ConeLevels),
                                         VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                         gpu::MemoryUse::Device, name);
}

// Zeroes every mip of a GENERAL-layout image (its old contents discarded).
void clearImage(VkCommandBuffer cmd, gpu::Tracker& tracker, const gpu::Image& image) {
    tracker.image(image, gpu::use::ClearGeneral, true).flush(cmd);
    const VkClearColorValue zero{};
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, VK_REMAINING_MIP_LEVELS, 0, 1};
    vkCmdClearColorImage(cmd, image.handle(), VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &range);
}

}  // namespace

// Levels 1.. share level 1's dense volumes (null before level 1 exists).
std::shared_ptr<vxgi::DenseVolumes> Renderer::clipScratch() const {
    return clip_.size() > 1 && clip_[1].volumes ? clip_[1].volumes->dense() : nullptr;
}

std::vector<const vxgi::VoxelVolumes*> Renderer::levelVolumes() const {
    std::vector<const vxgi::VoxelVolumes*> v{volumes_.get()};
    for (size_t l = 1; l < clip_.size(); ++l) v.push_back(clip_[l].volumes.get());
    return v;
}

// Level 0's voxel edge: --clipmap-voxel, or the size that lets the coarsest
// level's window hold the whole scene from the starting camera.
float Renderer::clipBaseVoxel() const {
    const RenderSettings& s = settings_;
    return s.clipmap.voxelSize > 0.0f
               ? s.clipmap.voxelSize
               : vxgi::clipBaseVoxelSize(sceneGpu_->bounds, s.voxels, s.clipmap.levels, glm::vec3(camera_.world[3]));
}

// Called by the constructor once volumes_ (level 0) exists; the levels start
// unplaced, so the first frame voxelizes each from scratch around the camera.
void Renderer::createClipmap() {
    const RenderSettings& s = settings_;
    const uint32_t levels = s.clipmap.levels;
    if (levels > sh::MAX_CLIP_LEVELS)
        throw std::runtime_error("clipmap: " + std::to_string(levels) + " levels; at most " +
                                 std::to_string(sh::MAX_CLIP_LEVELS));
    if (pv_) throw std::runtime_error("clipmap: not with --voxelizer pv (its cleanup keeps one fitted grid)");
    if (s.hasVoxelBox) throw std::runtime_error("clipmap: not with --voxel-box (the levels follow the camera)");
    const float base = clipBaseVoxel();
    clipLattice_ = vxgi::clipLattice(sceneGpu_->bounds, base);
    // Geometry outside every window gets no voxel light and casts no voxel
    // shadow: say so rather than render a silently different image.
    if (!vxgi::clipCoarsestHolds(sceneGpu_->bounds, glm::vec3(camera_.world[3]), clipLattice_, base, s.voxels, levels))
        warnings_.push_back("--clipmap " + std::to_string(levels) + " with --clipmap-voxel " + std::to_string(base) +
                            ": the coarsest level's window around the camera leaves part of the scene out "
                            "(no indirect light from it); use more levels or a larger voxel, or 0 to fit the scene");
    clip_.resize(levels);
    for (uint32_t l = 0; l < levels; ++l) {
        const float size = base * float(1u << l);
        const vxgi::GridSpec grid = vxgi::clipLevelGrid(glm::ivec3(0), clipLattice_, size, s.voxels);
        if (l == 0) {
            volumes_ = std::make_unique<vxgi::VoxelVolumes>(ctx_, grid, s.voxelSlots);
        } else {
            clip_[l].volumes = std::make_unique<vxgi::VoxelVolumes>(ctx_, grid, s.voxelSlots, clipScratch());
            clip_[l].header = vxgi::createListHeaderReadback(ctx_);
            for (const gpu::Image* v : clip_[l].volumes->all()) tracker_.assume(*v, gpu::use::ComputeReadWrite);
        }
    }
    scroll_ = std::make_unique<vxgi::ClipScrollPass>(ctx_);
    coneLevels_ = coneLevelsBuffer(ctx_, "clipmap levels");
    coneHistory_ = coneLevelsBuffer(ctx_, "clipmap levels (filtered)");
    atlases_ = std::make_unique<vxgi::ClipAtlases>(ctx_, s.voxels, levels);
    // Zeroed once; every filtering then rewrites each level's slab.
    ctx_.submitAndWait([&](VkCommandBuffer cmd) {
        clearImage(cmd, tracker_, atlases_->radiance);
        clearImage(cmd, tracker_, atlases_->directional);
    });
}

// A level voxelized from scratch at windowMin: what it held is cleared (with
// its old grid), the list restarts, and level 0's radiance volume, whose cells
// are in window coordinates, is cleared whole (the other levels clear their
// shared one before every use: recordLevels).
void Renderer::recordClipmapStatic(VkCommandBuffer cmd, size_t l, const glm::ivec3& windowMin) {
    gpu::GpuTimers* t = timers_.get();
    vxgi::VoxelVolumes& v = level(l);
    voxelizer_->clearOccupied(cmd, tracker_, v, t);
    list_->reset(cmd, tracker_, v);
    v.setGrid(cmd, tracker_, vxgi::clipLevelGrid(windowMin, clipLattice_, v.grid.voxelSize, v.grid.n), glm::ivec4(0));
    if (l == 0) clearImage(cmd, tracker_, v.radiance);
    voxelizer_->voxelize(cmd, tracker_, *sceneGpu_, v, vxgi::VoxelizeMode::Static, t);
    list_->finish(cmd, tracker_, v, true);
    clip_[l].windowMin = windowMin;
    clip_[l].placed = true;
}

void Renderer::recordClipmapVoxels(VkCommandBuffer cmd) {
    gpu::GpuTimers* t = timers_.get();
    // What the directional volumes hold now: last frame's windows.
    gpu::recordUniformUpdate(cmd, tracker_, *coneHistory_, &coneLevelsHost_, sizeof(coneLevelsHost_));
    directionalLevels_ = coneHistory_.get();
    const glm::vec3 eye = glm::vec3(camera_.world[3]);
    for (size_t l = 0; l < clip_.size(); ++l) {
        vxgi::VoxelVolumes& v = level(l);
        ClipLevel& c = clip_[l];
        const glm::ivec3 want = vxgi::clipWindowMin(eye, clipLattice_, v.grid.voxelSize, v.grid.n);
        if (staticDirty_ || !c.placed) {
            recordClipmapStatic(cmd, l, want);
        } else {
            voxelizer_->clearDynamic(cmd, tracker_, v, t);
            list_->dropDynamic(cmd, tracker_, v);
            if (want != c.windowMin) {
                // Toroidal storage: the voxels that stay keep their slots;
                // only the exposed slabs are voxelized.
                scroll_->record(cmd, tracker_, v, c.windowMin, want, t);
                v.setGrid(cmd, tracker_, vxgi::clipLevelGrid(want, clipLattice_, v.grid.voxelSize, v.grid.n),
                          glm::ivec4(c.windowMin - want, 1));
                if (l == 0) clearImage(cmd, tracker_, v.radiance);
                voxelizer_->voxelize(cmd, tracker_, *sceneGpu_, v, vxgi::VoxelizeMode::Static, t);
                list_->finish(cmd, tracker_, v, true);
                c.windowMin = want;
            }
        }
        voxelizer_->voxelize(cmd, tracker_, *sceneGpu_, v, vxgi::VoxelizeMode::Dynamic, t);
        list_->finish(cmd, tracker_, v, false);
        list_->copyHeader(cmd, tracker_, v, levelHeader(l));
    }
    coneLevelsHost_ = vxgi::coneLevels(levelVolumes());
    gpu::recordUniformUpdate(cmd, tracker_, *coneLevels_, &coneLevelsHost_, sizeof(coneLevelsHost_));
}

// Levels 1.. share one set of dense volumes (vxgi::DenseVolumes): each level
// in turn clears the radiance, runs `pass` on its voxels (which writes every
// occupied voxel's radiance), filters it and copies the result into the
// atlases, before the next level reuses them. A level's bounce traces only its
// own and coarser levels, whose slabs still hold what it must read.
void Renderer::recordLevels(VkCommandBuffer cmd, const char* filterTimer,
                            const std::function<void(size_t, const vxgi::VoxelVolumes&)>& pass, bool filter) {
    const std::vector<const vxgi::VoxelVolumes*> levels = levelVolumes();
    for (size_t l = 0; l < levels.size(); ++l) {
        if (l > 0) {
            gpu::GpuTimerScope scope(timers_.get(), cmd, "clipmap scratch clear");
            clearImage(cmd, tracker_, levels[l]->radiance);
        }
        pass(l, *levels[l]);
        if (!filter && clip_.empty()) continue;
        aniso_->record(cmd, tracker_, *levels[l], settings_.voxelLight.backsDark, timers_.get(), filterTimer);
        if (clip_.empty()) continue;
        gpu::GpuTimerScope scope(timers_.get(), cmd, "clipmap atlas copy");
        vxgi::recordAtlasCopy(cmd, tracker_, *levels[l], uint32_t(l), *atlases_);
    }
    if (clip_.empty()) return;
    {
        gpu::GpuTimerScope scope(timers_.get(), cmd, "clipmap atlas copy");
        vxgi::recordAtlasFold(cmd, tracker_, levels, *atlases_);
    }
    directionalLevels_ = coneLevels_.get();
}

// Scrolls leave freed entries in a level's list; once they are half of its
// static entries the level is voxelized from scratch, which compacts it.
void Renderer::readClipmapHeaders() {
    for (size_t l = 0; l < clip_.size(); ++l) {
        sh::VoxelListHeader header;
        std::memcpy(&header, levelHeader(l).mapped(), sizeof(header));
        if (2ull * header.allGroups.w > header.counts.y) clip_[l].placed = false;
    }
}

}  // namespace dvsgi::render
