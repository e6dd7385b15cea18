// The occupied-voxel list's bookkeeping (shaders/shared/voxel_list_pass.h):
// reset, finishing after a voxelization (counts and the indirect dispatch
// arguments the per-voxel passes use), dropping the dynamic entries, and
// rebuilding it from the attribute volume for code that wrote the attributes
// itself (an upload).
#pragma once

#include <cstdint>

#include "gpu/pipeline.h"

namespace dvsgi::gpu {
class Buffer;
class Tracker;
}

namespace dvsgi::vxgi {

class VoxelVolumes;

class VoxelListPass {
public:
    explicit VoxelListPass(const gpu::Context& ctx);

    // Empties the list (the start of a static voxelization).
    void reset(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes) const;
    // After a voxelization appended to the list: counts and dispatch arguments.
    // staticVoxels: every entry so far is static (after the static voxelization).
    void finish(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes, bool staticVoxels) const;
    // Forgets the dynamic entries (after the dynamic clear zeroed their voxels).
    void dropDynamic(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes) const;
    // Rebuilds the list from the attribute volume's fragment counts, all as static.
    void rebuild(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes) const;

private:
    void run(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes, uint32_t mode,
             uint32_t invocations) const;

    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
};

// Recorded by each pass that runs over list entries: the indirect dispatch
// whose arguments sit at `argsOffset` in the list buffer.
void dispatchOverList(VkCommandBuffer cmd, const gpu::Buffer& list, VkDeviceSize argsOffset);
// The list buffer's size for an N^3 grid (header + one entry per voxel).
uint64_t voxelListBytes(uint32_t n);
// Per-workgroup statistics slots that a pass over the list may address.
uint32_t voxelListMaxGroups(uint32_t n);

}  // namespace dvsgi::vxgi
