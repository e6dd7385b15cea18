#include "vxgi/voxel_counts.h"

#include <cstring>

#include "gpu/transfer.h"
#include "shared/voxel_list_pass.h"
#include "vxgi/volumes.h"

namespace dvsgi::vxgi {

namespace sh = dvsgi::shader;

VoxelCounts countVoxels(const gpu::Context& ctx, const VoxelVolumes& volumes) {
    const std::vector<uint8_t> bytes = gpu::readbackBuffer(ctx, volumes.list, sizeof(sh::VoxelListHeader));
    sh::VoxelListHeader header;
    std::memcpy(&header, bytes.data(), sizeof(header));
    const uint32_t occupied = header.counts.x < header.counts.z ? header.counts.x : header.counts.z;
    const uint32_t statics = header.counts.y < occupied ? header.counts.y : occupied;
    return {occupied, occupied - statics};
}

}  // namespace dvsgi::vxgi
