#include "vxgi/volumes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "gpu/barriers.h"
#include "gpu/context.h"
#include "gpu/transfer.h"
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"
#include "vxgi/voxel_list.h"

namespace dvsgi::vxgi {

namespace sh = dvsgi::shader;

GridSpec fitGrid(const scene::Bounds& bounds, uint32_t n) {
    if (!bounds.valid()) return GridSpec{glm::vec3(-1.0f), 2.0f / float(n), n};
    const glm::vec3 extent = bounds.max - bounds.min;
    const float longest = std::max({extent.x, extent.y, extent.z, 1e-4f});
    // longest + 8 voxels = N voxels: a margin of four voxels on each side puts
    // walls on the scene's edge inside the grid, where cones cross their whole
    // trilinear footprint before leaving (with one voxel, cones left through
    // the edge cells of a closed box at partial opacity and lost energy).
    const float voxel = longest / float(std::max(n, 9u) - 8);
    const float edge = voxel * float(n);
    GridSpec g;
    g.n = n;
    g.voxelSize = voxel;
    g.origin = (bounds.min + bounds.max) * 0.5f - glm::vec3(edge * 0.5f);
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

std::vector<VolumeMemory> volumeMemory(uint32_t n) {
    const uint64_t n3 = uint64_t(n) * n * n;
    uint64_t directional = 0;
    for (uint64_t s = n / 2; s >= 1; s /= 2) directional += s * s * s * 8;
    return {
        {"voxel attributes (13 channels)", "R32_SFLOAT", n3 * sh::VOXEL_CHANNELS * 4},
        {"static flags", "R8_UINT", n3},
        {"voxel direct light", "R16G16B16A16_SFLOAT", n3 * 8},
        {"radiance", "R16G16B16A16_SFLOAT", n3 * 8},
        {"directional volumes (6, with mips)", "R16G16B16A16_SFLOAT", directional * 6},
        {"occupied-voxel list", "uint32 buffer", voxelListBytes(n)},
    };
}

double voxelBytesPerGridVoxel(uint32_t n) {
    uint64_t total = 0;
    for (const VolumeMemory& m : volumeMemory(n)) total += m.bytes;
    return double(total) / (double(n) * n * n);
}

VoxelVolumes::VoxelVolumes(const gpu::Context& ctx, const GridSpec& g) : grid(g), directionalMips(directionalMipCount(g.n)) {
    const VkPhysicalDeviceLimits& limits = ctx.properties.limits;
    if (g.n < 8 || (g.n & (g.n - 1)) != 0)
        throw std::runtime_error("voxels: " + std::to_string(g.n) + " is not a power of two of at least 8");
    if (uint64_t(g.n) * sh::VOXEL_CHANNELS > limits.maxImageDimension3D)
        throw std::runtime_error("voxels: " + std::to_string(g.n) + "^3 needs 3D images of depth " +
                                 std::to_string(g.n * sh::VOXEL_CHANNELS) + " but " + ctx.deviceName +
                                 " allows " + std::to_string(limits.maxImageDimension3D));
    if (!ctx.features.atomicFloat)
        throw std::runtime_error(ctx.deviceName + " lacks shaderImageFloat32AtomicAdd, which voxelization needs");

    const VkImageUsageFlags storage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                      VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    gpu::ImageDesc d;
    d.type = VK_IMAGE_TYPE_3D;
    d.format = VK_FORMAT_R32_SFLOAT;
    d.extent = {g.n, g.n, g.n * sh::VOXEL_CHANNELS};
    d.usage = storage;
    d.name = "voxel attributes";
    accum = gpu::Image(ctx, d);
    d.format = VK_FORMAT_R8_UINT;
    d.extent = {g.n, g.n, g.n};
    d.name = "voxel static flags";
    flags = gpu::Image(ctx, d);
    d.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    d.usage = storage | VK_IMAGE_USAGE_SAMPLED_BIT;
    d.name = "voxel radiance";
    radiance = gpu::Image(ctx, d);
    d.usage = storage;
    d.name = "voxel direct light";
    direct = gpu::Image(ctx, d);
    d.usage = storage | VK_IMAGE_USAGE_SAMPLED_BIT;
    d.extent = {g.n / 2, g.n / 2, g.n / 2};
    d.mipLevels = directionalMips;
    d.name = "directional volume";
    for (gpu::Image& v : directional) v = gpu::Image(ctx, d);

    const sh::VoxelGrid gpuGrid{glm::vec4(g.origin, g.voxelSize), glm::uvec4(g.n, sh::VOXEL_CHANNELS, directionalMips, 0)};
    gridBuffer = gpu::createBuffer(ctx, &gpuGrid, sizeof(gpuGrid), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, "voxel grid");

    list = gpu::Buffer(ctx, voxelListBytes(g.n),
                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                           VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                       gpu::MemoryUse::Device, "occupied-voxel list");

    // Everything starts zeroed and stays in GENERAL from here on; the list
    // starts empty with its capacity written once.
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        sh::VoxelListHeader header{};
        header.counts.z = g.n * g.n * g.n;
        header.allGroups.z = header.dynamicGroups.z = 1;
        vkCmdUpdateBuffer(cmd, list.handle(), 0, sizeof(header), &header);
        const VkClearColorValue zero{};
        for (const gpu::Image* img : all()) {
            gpu::transition(cmd, *img, gpu::use::Undefined, gpu::use::TransferDst);
            const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, VK_REMAINING_MIP_LEVELS, 0, 1};
            vkCmdClearColorImage(cmd, img->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
            gpu::transition(cmd, *img, gpu::use::TransferDst, gpu::use::ComputeReadWrite);
        }
    });
}

std::vector<const gpu::Image*> VoxelVolumes::all() const {
    std::vector<const gpu::Image*> images = {&accum, &flags, &direct, &radiance};
    for (const gpu::Image& v : directional) images.push_back(&v);
    return images;
}

}  // namespace dvsgi::vxgi
