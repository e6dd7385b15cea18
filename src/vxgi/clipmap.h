// Camera-following voxel clipmaps (docs/clipmap.md): L levels of N^3 voxels,
// level l's voxel 2^l times level 0's, each window centred on the camera and
// snapped to whole voxels of its level. The index and the list of a level are
// toroidal (shader::VoxelGrid.wrap: storage voxel = world voxel mod N), so a
// move keeps every voxel that stays in the window where it is: the scroll pass
// frees those that left, and static voxelization fills only the exposed slabs.
// The dense volumes (radiance, directional) are rebuilt every frame in window
// coordinates, so every per-voxel pass works on a level as on a fitted grid.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "scene/scene.h"
#include "shared/voxel_data.h"
#include "vxgi/volumes.h"

namespace dvsgi::gpu {
class GpuTimers;
class Tracker;
}

namespace dvsgi::vxgi {

// The scroll pass's timer scope: a frame whose timings hold it scrolled a
// level (the bench's flicker figures look for it).
inline constexpr const char* kClipmapScrollTimer = "clipmap scroll";

struct ClipmapSettings {
    uint32_t levels = 0;     // 0 = one grid fitted to the scene
    float voxelSize = 0.0f;  // level 0's voxel edge (m); 0 = clipBaseVoxelSize
};

// Windows move in steps of this many voxels of their level, so the cells of
// directional mips 0-2 (2-8 voxels) keep their place in the world (a scroll
// changes the filtered light only where voxels came or went), and a level's
// window lies on whole cells of the next level's mips 0 and 1, into which
// recordAtlasFold filters it.
inline constexpr int kClipSnapVoxels = 8;

// How far (in voxels of its level) a window may sit off the camera: half a
// snap step, one voxel for the camera's own, never more than a quarter window.
inline uint32_t clipSpareVoxels(uint32_t n) { return std::min<uint32_t>(kClipSnapVoxels / 2 + 1, n / 4); }
// Level 0's voxel edge when none is given: the coarsest level spans twice the
// scene's longest side, so its window holds the whole scene from anywhere in it,
// and more where the camera `eye` stands outside the scene far from its far face
// (the window then still holds the scene from there, clipSpareVoxels included).
float clipBaseVoxelSize(const scene::Bounds& bounds, uint32_t n, uint32_t levels, const glm::vec3& eye);
// Whether the coarsest level's window, placed around `eye`, holds the whole
// scene (the Renderer warns when a given --clipmap-voxel leaves part out).
bool clipCoarsestHolds(const scene::Bounds& bounds, const glm::vec3& eye, const glm::vec3& lattice, float voxelSize0,
                       uint32_t n, uint32_t levels);
// Where every level's voxels start: the scene's lower bounds at the centres of
// level 0's voxels (fitGrid puts them kFitLatticeOffset from the centres; a
// clipmap's voxel is not tied to the bounds' extent, so no plane is drawn to
// a face the way fitGrid's middle plane was). A wall on the bounds is then one
// voxel layer, not two; the coarser levels' voxels hold it at a quarter, an
// eighth, ... of their edge, never on a face). Levels share it, so they nest.
glm::vec3 clipLattice(const scene::Bounds& bounds, float voxelSize0);
// The minimum corner (in whole voxels of edge voxelSize from `lattice`) of an
// N^3 window centred on `centre`, snapped to kClipSnapVoxels.
glm::ivec3 clipWindowMin(const glm::vec3& centre, const glm::vec3& lattice, float voxelSize, uint32_t n);
// The grid of a window: origin at its minimum corner, wrap = minimum mod N.
GridSpec clipLevelGrid(const glm::ivec3& windowMin, const glm::vec3& lattice, float voxelSize, uint32_t n);
// What a clipmap cone tracer reads of the levels (level 0 first).
shader::ConeLevels coneLevels(const std::vector<const VoxelVolumes*>& levels);

// The levels' dense volumes stacked along z, level l at z = l x its depth
// (radiance N x N x L N; directional 6 (N/2) x N/2 x L N/2 with the levels'
// mips): what a clipmap cone tracer samples, so that it picks a level by
// arithmetic instead of by a branch per level (lib/cone_trace.glsl).
struct ClipAtlases {
    ClipAtlases(const gpu::Context& ctx, uint32_t n, uint32_t levels);
    gpu::Image radiance, directional;
    uint64_t bytes() const { return radiance.memorySize() + directional.memorySize(); }
};
// Copies level l's radiance and directional volumes (every mip) into the
// atlases; the level's volumes are left in gpu::use::CopySrcGeneral.
void recordAtlasCopy(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& level, uint32_t l,
                     const ClipAtlases& atlases);

// Where level l - 1's window covers level l, level l's directional mips in
// the atlas are replaced by level l - 1's next ones (mip k by mip k + 1: the
// same cells), for every k whose cells the windows' offset aligns with (0 and
// 1 always, kClipSnapVoxels): a coarse level then carries the light and the
// partial opacity its finer neighbour filtered from fine voxels, not those of
// its own coarse voxelization, in which any triangle makes a voxel opaque.
// Levels in order, so the filtered light climbs every level.
void recordAtlasFold(VkCommandBuffer cmd, gpu::Tracker& tracker, const std::vector<const VoxelVolumes*>& levels,
                     const ClipAtlases& atlases);

// The inputs of a cone tracer over clipmap levels: their grids
// (shader::ConeLevels) and the atlases filled from the same frame.
struct ClipTrace {
    const gpu::Buffer& levels;
    const ClipAtlases& atlases;
    const GridSpec& coarsest;  // how far cones may run
};

// Frees a level's static voxels that a move of its window from oldMin to
// newMin took out of it (clipmap_scroll.comp). Run with the old grid, after
// the dynamic voxels were cleared; then set the new grid and voxelize the
// static draws with keep = oldMin - newMin.
class ClipScrollPass {
public:
    explicit ClipScrollPass(const gpu::Context& ctx);
    void record(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes, const glm::ivec3& oldMin,
                const glm::ivec3& newMin, gpu::GpuTimers* timers) const;

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
};

}  // namespace dvsgi::vxgi
