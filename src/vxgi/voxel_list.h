// The occupied-voxel list's bookkeeping (shaders/shared/voxel_list_pass.h):
// reset, finishing after a voxelization (counts and the indirect dispatch
// arguments the per-voxel passes use) and dropping the dynamic entries.
#pragma once

#include <cstdint>
#include <memory>

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
    // Copies the header (shader::VoxelListHeader) into a host-readable buffer,
    // readable once the command buffer completed: how the host learns that a
    // voxelization ran out of slots (counts.w > 0).
    void copyHeader(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes,
                    const gpu::Buffer& hostBuffer) const;

private:
    void run(VkCommandBuffer cmd, gpu::Tracker& tracker, const VoxelVolumes& volumes, uint32_t mode) const;

    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
};

// Records the header of an empty list of `slots` slots into `list` (new
// volumes; the progressive voxelizer's new list each frame).
void recordEmptyList(VkCommandBuffer cmd, const gpu::Buffer& list, uint32_t slots);
// A host-readable buffer for VoxelListPass::copyHeader.
std::unique_ptr<gpu::Buffer> createListHeaderReadback(const gpu::Context& ctx);
// Recorded by each pass that runs over list entries: the indirect dispatch
// whose arguments sit at `argsOffset` in the list buffer.
void dispatchOverList(VkCommandBuffer cmd, const gpu::Buffer& list, VkDeviceSize argsOffset);
// The list buffer's size for `slots` slots (header + one entry per slot).
uint64_t voxelListBytes(uint32_t slots);
// Per-workgroup statistics entries that a pass over a list of `slots` entries may address.
uint32_t voxelListMaxGroups(uint32_t slots);

}  // namespace dvsgi::vxgi
