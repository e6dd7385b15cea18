// dvsgi render --voxel-dump: every occupied voxel of the fitted grid as one
// row of a NumPy .npy table, for checking the voxels' light against a tracer
// (scripts/voxel-truth.py) or any other analysis outside the renderer.
#pragma once

#include <string>

namespace dvsgi::gpu {
class Context;
}
namespace dvsgi::vxgi {
class VoxelVolumes;
}

namespace dvsgi::app {

// The columns of a row, in order (float32 each).
inline constexpr const char* kVoxelDumpColumns =
    "grid x, y, z; centre x, y, z (world, metres); normal x, y, z (unit, from the squared-normal sums; 0 where "
    "opposite faces cancel); albedo r, g, b; direct light r, g, b; radiance r, g, b (direct + reflected, as the "
    "radiance volume holds it: a two-sided voxel shows its darker side); side code (0 one-sided, 1-3 two-sided "
    "along x, y, z, 4 several axes); fragment count; a voxel two-sided along one axis: its +axis side's light "
    "r, g, b and its -axis side's (direct + reflected, what a ray meeting that side sees; 0 otherwise)";
inline constexpr int kVoxelDumpColumnCount = 26;

// Reads the volumes back (waits for the device) and writes the table;
// throws image::IoError naming --voxel-dump and the path when it cannot write.
void writeVoxelDump(const std::string& path, const gpu::Context& ctx, const vxgi::VoxelVolumes& volumes);

}  // namespace dvsgi::app
