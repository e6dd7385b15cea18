#include "vxgi/volumes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "gpu/barriers.h"
#include "gpu/context.h"
#include "gpu/tracker.h"
#include "gpu/transfer.h"
#include "shared/voxel_data.h"
#include "shared/bounce_pass.h"
#include "shared/voxel_list_pass.h"
#include "vxgi/bounce.h"
#include "vxgi/voxel_list.h"

namespace dvsgi::vxgi {

namespace sh = dvsgi::shader;

GridSpec fitGrid(const scene::Bounds& bounds, uint32_t n) {
    if (!bounds.valid()) return GridSpec{glm::vec3(-1.0f), 2.0f / float(n), n};
    const glm::vec3 extent = bounds.max - bounds.min;
    const float longest = std::max({extent.x, extent.y, extent.z, 1e-4f});
    // longest + 9 voxels = N voxels: a margin of four and a half voxels on each
    // side puts walls on the scene's edge inside the grid, where cones cross
    // their whole trilinear footprint before leaving (with one voxel, cones
    // left through the edge cells of a closed box at partial opacity and lost
    // energy), and near voxel centres: a plane on a voxel face touches the
    // voxels on both sides, so walls on the bounds (rooms, the Cornell box)
    // were two voxels thick, half a voxel nearer every receiver, and indirect
    // light came out 4-19 % too bright per bounce (docs/quality.md).
    const float voxel = longest / float(std::max(n, 10u) - 9);
    const float edge = voxel * float(n);
    GridSpec g;
    g.n = n;
    g.voxelSize = voxel;
    g.origin = (bounds.min + bounds.max) * 0.5f - glm::vec3(edge * 0.5f);
    // Every axis's lower bound kFitLatticeOffset from a voxel centre.
    for (int a = 0; a < 3; ++a) {
        const float k = (bounds.min[a] - g.origin[a]) / voxel;
        g.origin[a] = bounds.min[a] - (std::floor(k) + 0.5f + kFitLatticeOffset) * voxel;
    }
    return g;
}

GridSpec gridForBox(const glm::vec3& boxMin, const glm::vec3& boxMax, uint32_t n) {
    const glm::vec3 extent = boxMax - boxMin;
    const float edge = std::max({extent.x, extent.y, extent.z});
    GridSpec g;
    g.n = n;
    g.voxelSize = edge / float(n);
    g.origin = (boxMin + boxMax) * 0.5f - glm::vec3(edge * 0.5f);
    return g;
}

uint32_t directionalMipCount(uint32_t n) {
    return uint32_t(std::log2(double(std::max(n / 2, 1u)))) + 1;
}

uint32_t roundSlotCapacity(uint32_t n, uint64_t wanted) {
    const uint64_t row = sh::VOXEL_SLOT_ROW;
    const uint64_t all = (uint64_t(n) * n * n + row - 1) / row * row;
    const uint64_t slots = std::min((std::max<uint64_t>(wanted, 1) + row - 1) / row * row, all);
    return uint32_t(slots);
}

uint32_t defaultSlotCapacity(uint32_t n) { return roundSlotCapacity(n, 12ull * n * n); }

std::vector<VolumeMemory> volumeMemory(uint32_t n, uint32_t slots, bool bounceRays, bool gatherRays) {
    const uint64_t n3 = uint64_t(n) * n * n;
    uint64_t directional = 0;
    for (uint64_t s = n / 2; s >= 1; s /= 2) directional += s * s * s * 8;
    std::vector<VolumeMemory> items = {
        {"voxel slot index", "uint32 buffer", n3 * 4},
        {"voxel attributes (" + std::to_string(sh::VOXEL_CHANNELS) + " channels per slot)", "R32_SFLOAT",
         uint64_t(slots) * sh::VOXEL_CHANNELS * 4},
        {"voxel extents (per slot)", "uint32 buffer", uint64_t(slots) * 4},
        {"voxel direct light (per slot)", "R16G16B16A16_SFLOAT", uint64_t(slots) * 8},
        {"voxel side light (per slot)", "R32G32B32A32_UINT", uint64_t(slots) * 16},
        {"radiance", "R16G16B16A16_SFLOAT", n3 * 8},
        {"directional volumes (6, with mips)", "R16G16B16A16_SFLOAT", directional * 6},
        {"occupied-voxel list", "uint32 buffer", voxelListBytes(slots)},
    };
    // BouncePass's (tracedImageDesc) and RayData's (rayNormalsImageDesc, rayOccupancyBytes).
    if (bounceRays)
        items.push_back({"voxel bounce rays' light (per slot)", "R32G32_UINT", uint64_t(slots) * sh::BOUNCE_RAYS_SLOT_BYTES});
    if (bounceRays || gatherRays) {
        items.push_back({"voxel rays' normals (per slot)", "R32_UINT", uint64_t(slots) * sh::BOUNCE_RAY_NORMAL_SLOT_BYTES});
        items.push_back({"voxel rays' occupancy bits", "uint32 buffer", rayOccupancyBytes(n)});
    }
    return items;
}

double voxelBytesPerGridVoxel(uint32_t n, uint32_t slots, bool bounceRays, bool gatherRays) {
    uint64_t total = 0;
    for (const VolumeMemory& m : volumeMemory(n, slots, bounceRays, gatherRays)) total += m.bytes;
    return double(total) / (double(n) * n * n);
}

VoxelVolumes::VoxelVolumes(const gpu::Context& ctx, const GridSpec& g, uint32_t slotCount,
                           std::shared_ptr<DenseVolumes> shared)
    : dense_(shared ? std::move(shared) : std::make_shared<DenseVolumes>()),
      grid(g),
      directionalMips(directionalMipCount(g.n)),
      slots(roundSlotCapacity(g.n, slotCount ? slotCount : defaultSlotCapacity(g.n))),
      radiance(dense_->radiance),
      directional(dense_->directional) {
    const VkPhysicalDeviceLimits& limits = ctx.properties.limits;
    if (g.n < 8 || (g.n & (g.n - 1)) != 0)
        throw std::runtime_error("voxels: " + std::to_string(g.n) + " is not a power of two of at least 8");
    const uint32_t atlasWidth = sh::DIRECTIONAL_VOLUMES * (g.n / 2);
    if (g.n > limits.maxImageDimension3D || atlasWidth > limits.maxImageDimension3D ||
        sh::VOXEL_SLOT_ROW > limits.maxImageDimension3D || slots / sh::VOXEL_SLOT_ROW > limits.maxImageDimension3D)
        throw std::runtime_error("voxels: " + std::to_string(g.n) + "^3 with " + std::to_string(slots) +
                                 " voxel slots needs 3D images of " + std::to_string(std::max(g.n, atlasWidth)) +
                                 " and " + std::to_string(sh::VOXEL_SLOT_ROW) + " x " +
                                 std::to_string(slots / sh::VOXEL_SLOT_ROW) + " texels, but " + ctx.deviceName +
                                 " allows " + std::to_string(limits.maxImageDimension3D) + " per side");
    const uint64_t indexBytes = uint64_t(g.n) * g.n * g.n * sizeof(uint32_t);
    const uint64_t bufferBytes = std::max(indexBytes, voxelListBytes(slots));
    if (bufferBytes > limits.maxStorageBufferRange)
        throw std::runtime_error("voxels: " + std::to_string(g.n) + "^3 needs a " +
                                 std::to_string(bufferBytes >> 20) + " MiB storage buffer (the slot index), but " +
                                 ctx.deviceName + " allows " + std::to_string(limits.maxStorageBufferRange >> 20) +
                                 " MiB; use fewer voxels");
    if (!ctx.features.atomicFloat)
        throw std::runtime_error(ctx.deviceName + " lacks shaderImageFloat32AtomicAdd, which voxelization needs");

    const VkImageUsageFlags storage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                      VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    gpu::ImageDesc d;
    d.type = VK_IMAGE_TYPE_3D;
    const uint32_t rows = slots / sh::VOXEL_SLOT_ROW;
    d.format = VK_FORMAT_R32_SFLOAT;
    d.extent = {sh::VOXEL_SLOT_ROW, rows, sh::VOXEL_CHANNELS};
    d.usage = storage;
    d.name = "voxel attributes";
    accum = gpu::Image(ctx, d);
    d.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    d.extent = {sh::VOXEL_SLOT_ROW, rows, 1};
    d.name = "voxel direct light";
    direct = gpu::Image(ctx, d);
    d.format = VK_FORMAT_R32G32B32A32_UINT;
    d.name = "voxel side light";
    sides = gpu::Image(ctx, d);
    const bool ownDense = !radiance.handle();
    if (ownDense) {
        d.extent = {g.n, g.n, g.n};
        d.format = VK_FORMAT_R16G16B16A16_SFLOAT;
        d.usage = storage | VK_IMAGE_USAGE_SAMPLED_BIT;
        d.name = "voxel radiance";
        radiance = gpu::Image(ctx, d);
        d.extent = {sh::DIRECTIONAL_VOLUMES * (g.n / 2), g.n / 2, g.n / 2};
        d.mipLevels = directionalMips;
        d.name = "directional volumes";
        directional = gpu::Image(ctx, d);
    } else if (radiance.desc().extent.width != g.n) {
        throw std::logic_error("voxels: shared dense volumes of " + std::to_string(radiance.desc().extent.width) +
                               "^3 given to a " + std::to_string(g.n) + "^3 grid");
    }

    const sh::VoxelGrid gpuGrid = gpuVoxelGrid(g, slots);
    gridBuffer = gpu::createBuffer(ctx, &gpuGrid, sizeof(gpuGrid),
                                   VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, "voxel grid");

    list = gpu::Buffer(ctx, voxelListBytes(slots),
                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                           VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                       gpu::MemoryUse::Device, "occupied-voxel list");
    index = gpu::Buffer(ctx, uint64_t(g.n) * g.n * g.n * sizeof(uint32_t),
                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                            VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                        gpu::MemoryUse::Device, "voxel slot index");
    extents = gpu::Buffer(ctx, uint64_t(slots) * sizeof(uint32_t),
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                              VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                          gpu::MemoryUse::Device, "voxel extents");

    // Everything starts zeroed and stays in GENERAL from here on; the list
    // starts empty with its capacity written once.
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        recordEmptyList(cmd, list, slots);
        vkCmdFillBuffer(cmd, index.handle(), 0, VK_WHOLE_SIZE, 0);
        vkCmdFillBuffer(cmd, extents.handle(), 0, VK_WHOLE_SIZE, 0);
        gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                           VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
        // Shared dense volumes may hold another grid's data: their user clears them.
        for (const gpu::Image* img : all())
            if (ownDense || (img != &radiance && img != &directional)) gpu::recordZeroNewImage(cmd, *img);
    });
}

sh::VoxelGrid gpuVoxelGrid(const GridSpec& g, uint32_t slots, const glm::ivec4& keep) {
    sh::VoxelGrid v{};
    v.originSize = glm::vec4(g.origin, g.voxelSize);
    v.dims = glm::uvec4(g.n, sh::VOXEL_CHANNELS, directionalMipCount(g.n), slots);
    v.wrap = glm::ivec4(g.wrap, 0);
    v.keep = keep;
    return v;
}

void VoxelVolumes::setGrid(VkCommandBuffer cmd, gpu::Tracker& tracker, const GridSpec& g, const glm::ivec4& keep) {
    grid = g;
    keptByScroll = keep;
    const sh::VoxelGrid v = gpuVoxelGrid(g, slots, keep);
    gpu::recordUniformUpdate(cmd, tracker, gridBuffer, &v, sizeof(v));
}

uint64_t VoxelVolumes::ownBytes() const {
    const uint64_t sparse = index.size() + extents.size() + accum.memorySize() + direct.memorySize() + sides.memorySize() + list.size();
    return sparse + (sharesDense() ? 0 : dense_->bytes());
}

std::vector<const gpu::Image*> VoxelVolumes::all() const {
    return {&accum, &direct, &sides, &radiance, &directional};
}

}  // namespace dvsgi::vxgi
