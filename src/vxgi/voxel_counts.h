// How many voxels the last frame occupied, for the bench's bytes model
// (bench/bytes_model.h). For now a read-back of the fragment counts and the
// static flags, counted on the host: blocking and slow at large N, so call it
// outside timed frames. A GPU-side count of the occupied-voxel list can
// replace it behind the same interface.
#pragma once

#include <cstdint>

namespace dvsgi::gpu {
class Context;
}

namespace dvsgi::vxgi {

class VoxelVolumes;

struct VoxelCounts {
    uint64_t occupied = 0;  // fragment count (CH_COUNT) > 0
    uint64_t dynamic = 0;   // occupied and not flagged VOXEL_FLAG_STATIC
};

// The volumes must be idle (no frame in flight) and are left in GENERAL, all
// later work ordered after the read-back. The read-back goes through at most
// `stagingBytes` of host memory at a time (z slabs of the grid).
VoxelCounts countVoxels(const gpu::Context& ctx, const VoxelVolumes& volumes, uint64_t stagingBytes = 64ull << 20);

}  // namespace dvsgi::vxgi
