// Conservative voxelization of the scene into the voxel attribute volume
// (paper section V), and the per-frame clear of dynamic voxels. Two
// implementations write the same sums through lib/voxel_accumulate.glsl: the
// geometry-shader raster path (voxelize.vert/.geom/.frag) and the compute
// path (voxelize_compute.h, voxelize.comp).
#pragma once

#include <memory>

#include "gpu/pipeline.h"

namespace dvsgi::gpu {
class GpuTimers;
class Tracker;
}
namespace dvsgi::gpuscene {
class SceneGpu;
}

namespace dvsgi::vxgi {

class ComputeVoxelizer;
struct ComputeTiling;
class VoxelVolumes;

enum class VoxelizeMode { Static, Dynamic };

// Which voxelizer (--voxelizer). Geometry: one fragment per (pixel column,
// layer) of the dominant-axis projection, dilated (extras within one voxel).
// Compute: one sample per (triangle, voxel it touches), exact. Counts differ,
// averages agree. Auto: resolveVoxelizer's choice for the device. Pv:
// progressive screen-space voxelization from the frame's buffers
// (pv_voxelize.h); the Voxelizer then only clears, PvVoxelizer fills.
enum class VoxelizerKind { Geometry, Compute, Auto, Pv };

// Auto -> Compute or Geometry for this device (docs/benchmarks.md has the
// measurements behind it); other kinds are returned as they are.
VoxelizerKind resolveVoxelizer(const gpu::Context& ctx, VoxelizerKind kind);
const char* voxelizerName(VoxelizerKind kind);  // "geometry", "compute", "auto", "pv"

class Voxelizer {
public:
    // hardwareConservative: use VK_EXT_conservative_rasterization instead of
    // the geometry-shader dilation (only when the device has it; geometry
    // path only). kind: resolved with resolveVoxelizer.
    Voxelizer(const gpu::Context& ctx, const gpuscene::SceneGpu& scene, bool hardwareConservative,
              VoxelizerKind kind = VoxelizerKind::Geometry);
    ~Voxelizer();
    Voxelizer(const Voxelizer&) = delete;
    Voxelizer& operator=(const Voxelizer&) = delete;

    // Zeroes index, attributes, direct light and radiance of the whole grid,
    // whatever the list holds (the voxelization tests' fixtures; the Renderer
    // relies on new volumes starting zeroed). The occupied-voxel list is reset
    // beside it.
    void clearAll(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes,
                  gpu::GpuTimers* timers) const;
    // Zeroes the voxels and slots of the list's dynamic entries (what dynamic
    // geometry wrote last frame); VoxelListPass::dropDynamic then frees them.
    void clearDynamic(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes,
                      gpu::GpuTimers* timers) const;
    // Zeroes every voxel and slot the list holds (static and dynamic): the
    // start of a static voxelization, since no other voxel can hold anything
    // (new volumes start zeroed with an empty list). The list is reset beside it.
    void clearOccupied(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes,
                       gpu::GpuTimers* timers) const;
    // Voxelizes the static or the dynamic draws of the scene, appending newly
    // occupied voxels to the list (VoxelListPass::finish then counts them).
    void voxelize(VkCommandBuffer cmd, gpu::Tracker& tracker, const gpuscene::SceneGpu& scene,
                  const VoxelVolumes& volumes, VoxelizeMode mode, gpu::GpuTimers* timers) const;
    // Compute path only (ComputeVoxelizer::setTiling); tests use it.
    void setComputeTiling(ComputeTiling tiling);
    bool hardwareConservative() const { return hardware_; }
    VoxelizerKind kind() const { return kind_; }

private:
    void clearListed(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes, uint32_t scope) const;
    void voxelizeRaster(VkCommandBuffer cmd, const gpuscene::SceneGpu& scene, const VoxelVolumes& volumes,
                        bool dynamic) const;

    const gpu::Context& ctx_;
    bool hardware_;
    VoxelizerKind kind_;
    gpu::Pipeline voxelize_;  // geometry path only
    gpu::Pipeline clear_;
    std::unique_ptr<ComputeVoxelizer> compute_;
};

}  // namespace dvsgi::vxgi
