// How many voxels the last frame occupied, for the bench's bytes model
// (bench/bytes_model.h): the occupied-voxel list's header, read back. Blocking
// (a submission and a wait), so call it outside timed frames.
#pragma once

#include <cstdint>

namespace dvsgi::gpu {
class Context;
}

namespace dvsgi::vxgi {

class VoxelVolumes;

struct VoxelCounts {
    uint64_t occupied = 0;  // entries of the occupied-voxel list (fragment count > 0)
    uint64_t dynamic = 0;   // of them, written by dynamic geometry this frame (not flagged static)
};

// The volumes must be idle (no frame in flight).
VoxelCounts countVoxels(const gpu::Context& ctx, const VoxelVolumes& volumes);

}  // namespace dvsgi::vxgi
