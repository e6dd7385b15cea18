// The voxel grid and the volumes that live on it (docs/ARCHITECTURE.md lists
// their formats). All volumes stay in the GENERAL layout for their lifetime.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/resources.h"
#include "shared/voxel_data.h"
#include "scene/scene.h"

namespace dvsgi::gpu {
class Tracker;
}

namespace dvsgi::vxgi {

struct GridSpec {
    glm::vec3 origin{0.0f};  // world position of the grid's minimum corner
    float voxelSize = 1.0f;  // edge of one voxel, metres
    uint32_t n = 128;        // voxels per edge
    // Storage voxel of grid voxel 0 (shader::VoxelGrid.wrap): a clipmap
    // level's window minimum modulo n; 0 for a fitted grid.
    glm::ivec3 wrap{0};
};

// A cube on the longest side of `bounds` plus four and a half voxels of margin
// on every side, so surfaces on the bounds never sit on the grid's edge and
// cones cross their whole footprint before leaving the grid. The lower bound
// of every axis, and the upper one of the longest, lies kFitLatticeOffset of a
// voxel from a voxel centre, so a wall there is one voxel layer, not two (a
// plane on a voxel face touches the voxels on both sides). The upper bounds of
// the shorter axes fall wherever the scene's extent puts them.
GridSpec fitGrid(const scene::Bounds& bounds, uint32_t n);
// Why not at the centre itself: the longest axis spans N - 9 voxels, an odd
// number for every power-of-two N, so its middle plane (the dividing wall of a
// symmetric pair of rooms) would then lie on a voxel face and be voxelized two
// layers thick. Shifted by this fraction it lies 0.05 of a voxel inside one,
// and planes at a quarter or a third of the longest axis at least 0.11 (test
// FitGrid.PlanesAtSimpleFractionsOfTheBoundsAreOffVoxelFaces). The lower
// bounds then lie 0.45 of a voxel above their voxels' lower faces, and the
// longest axis's upper bound 0.45 above its voxel's lower face (0.55 below
// the outer one). 0.55 above was measured too and moved cornell-lights by
// +1 %, within what any placement of the lattice does (docs/quality.md,
// "Where the grid falls on the scene").
inline constexpr float kFitLatticeOffset = -0.05f;
// A cube on the longest side of a user-given box (no margin added).
GridSpec gridForBox(const glm::vec3& boxMin, const glm::vec3& boxMax, uint32_t n);

uint32_t directionalMipCount(uint32_t n);  // (N/2)^3 down to 1^3

// The shader's view of a grid (shader::VoxelGrid).
shader::VoxelGrid gpuVoxelGrid(const GridSpec& g, uint32_t slots, const glm::ivec4& keep = glm::ivec4(0));

// Slots (occupied voxels that can be stored) an N^3 grid starts with: 12 N^2
// (a surface crosses about N^2 voxels per unit of area; the bench's
// occupied_voxels: Cornell 4.9 N^2 at 64^3-128^3, Sponza 4.2, 5.9, 7.5 and
// 8.9 N^2 at 64^3-512^3), whole rows, at most N^3. The renderer grows the
// storage when a voxelization runs out (Renderer::renderFrame), so the figure
// only decides how often a scene pays one more voxelization to grow.
uint32_t defaultSlotCapacity(uint32_t n);
// `wanted` rounded up to whole rows of VOXEL_SLOT_ROW, at most N^3 rounded up.
uint32_t roundSlotCapacity(uint32_t n, uint64_t wanted);

struct VolumeMemory {
    std::string name;
    std::string format;
    uint64_t bytes;
};
// What the volumes of an N^3 grid with `slots` slots take, before allocating anything.
// bounceRays: with the bounce's per-slot ray results (--bounce-trace rays);
// bounceRays or gatherRays (--gather-trace rays): with what rays read (vxgi::RayData).
std::vector<VolumeMemory> volumeMemory(uint32_t n, uint32_t slots, bool bounceRays = false, bool gatherRays = false);
// Their sum over N^3: the figure issue #14's compact-storage goal is stated in.
double voxelBytesPerGridVoxel(uint32_t n, uint32_t slots, bool bounceRays = false, bool gatherRays = false);

// A grid's dense volumes, in window coordinates: the radiance and the
// directional volumes filtered from it. Clipmap levels 1.. share one set
// (Renderer: each level clears the radiance, lights or bounces its voxels,
// filters and copies the result into the atlases before the next level runs),
// so six levels of 128^3 hold two sets instead of six (docs/clipmap.md).
struct DenseVolumes {
    gpu::Image radiance;     // RGBA16F, N^3: direct light + emission (+ bounces), a = opacity
    // RGBA16F, 6 (N/2) x (N/2) x (N/2) + mips: the six directional volumes side
    // by side along x (shader::directionalTexel), order -X +X -Y +Y -Z +Z.
    gpu::Image directional;
    uint64_t bytes() const { return radiance.memorySize() + directional.memorySize(); }
};

class VoxelVolumes {
    std::shared_ptr<DenseVolumes> dense_;  // first: radiance and directional refer into it

public:
    // slots: 0 = defaultSlotCapacity(grid.n); rounded with roundSlotCapacity.
    // dense: volumes of the same N another grid uses too (a clipmap level's
    // shared scratch); null = its own, zeroed.
    VoxelVolumes(const gpu::Context& ctx, const GridSpec& grid, uint32_t slots = 0,
                 std::shared_ptr<DenseVolumes> dense = nullptr);

    GridSpec grid;
    glm::ivec4 keptByScroll{0};  // the `keep` of the last setGrid (w != 0: a scroll's kept box)
    uint32_t directionalMips;
    uint32_t slots;       // slot capacity (whole rows of VOXEL_SLOT_ROW)
    gpu::Image accum;     // R32_SFLOAT, ROW x rows x VOXEL_CHANNELS: summed attributes per slot
    gpu::Image direct;    // RGBA16F, ROW x rows x 1: direct light + emission per slot, kept for the bounces; a = 1 + side code
    // RGBA32UI, ROW x rows x 1: a two-sided voxel's light per side, four
    // RGB9E5 values (lib/voxel_sides.glsl); with --edge-voxels faces an edge
    // voxel's direct light per axis face and in all (lib/voxel_rays.glsl,
    // facesSeen); other slots' texels are unused.
    gpu::Image sides;
    gpu::Image& radiance;     // DenseVolumes::radiance
    gpu::Image& directional;  // DenseVolumes::directional
    gpu::Buffer gridBuffer;                  // shader::VoxelGrid
    // uint32 per grid voxel (x fastest): slot + 1 | VOXEL_INDEX_STATIC, 0 = empty.
    gpu::Buffer index;
    // uint32 per slot: which eighths of the voxel its surface reaches per
    // axis (shared/voxel_data.h, VOXEL_EXTENT_*), OR-ed in by the compute and
    // geometry-shader voxelizers; 0 = not known (the whole voxel: pv).
    gpu::Buffer extents;
    // The occupied-voxel list (shared/voxel_list_pass.h): header, then one
    // packed coordinate per slot. Storage, indirect-dispatch arguments, fills.
    gpu::Buffer list;
    double bytesPerGridVoxel(bool bounceRays = false, bool gatherRays = false) const {
        return voxelBytesPerGridVoxel(grid.n, slots, bounceRays, gatherRays);
    }
    const std::shared_ptr<DenseVolumes>& dense() const { return dense_; }
    bool sharesDense() const { return dense_.use_count() > 1; }
    // What this grid alone holds: everything but shared dense volumes.
    uint64_t ownBytes() const;
    // Records a new grid (same n: a clipmap level's scrolled window) into
    // gridBuffer and `grid`; keep (shader::VoxelGrid.keep) limits the next
    // static voxelization to the voxels outside it.
    void setGrid(VkCommandBuffer cmd, gpu::Tracker& tracker, const GridSpec& g, const glm::ivec4& keep);
    // Every volume (image), for code that handles them all alike. Its own
    // start zeroed, in gpu::use::ComputeReadWrite; so does the index.
    std::vector<const gpu::Image*> all() const;
};

}  // namespace dvsgi::vxgi
