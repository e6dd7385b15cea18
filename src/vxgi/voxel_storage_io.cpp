#include "vxgi/voxel_storage_io.h"

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include <glm/gtc/packing.hpp>

#include "gpu/barriers.h"
#include "gpu/transfer.h"
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"
#include "vxgi/volumes.h"
#include "vxgi/voxel_list.h"

namespace dvsgi::vxgi {

namespace {

namespace sh = dvsgi::shader;

// The slot of an index value, or -1 for an empty voxel.
int64_t slotOf(uint32_t value) { return int64_t(sh::indexSlot(value)) - 1; }

template <typename T>
std::vector<T> wordsOf(const std::vector<uint8_t>& bytes) {
    std::vector<T> out(bytes.size() / sizeof(T));
    std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
    return out;
}

template <typename T>
std::vector<T> readAs(const gpu::Context& ctx, const gpu::Image& image) {
    return wordsOf<T>(gpu::readbackImage(ctx, image, gpu::use::ComputeReadWrite));
}

}  // namespace

DenseAttributes::DenseAttributes(uint32_t n) : n(n), data(size_t(n) * n * n * sh::VOXEL_CHANNELS, 0.0f) {}

std::vector<uint32_t> readVoxelIndex(const gpu::Context& ctx, const VoxelVolumes& v) {
    return wordsOf<uint32_t>(gpu::readbackBuffer(ctx, v.index));
}

DenseAttributes readAttributes(const gpu::Context& ctx, const VoxelVolumes& v) {
    const std::vector<uint32_t> index = readVoxelIndex(ctx, v);
    const std::vector<float> slots = readAs<float>(ctx, v.accum);  // channel-major: c * slots + slot
    DenseAttributes out(v.grid.n);
    const size_t n3 = index.size();
    for (size_t i = 0; i < n3; ++i) {
        const int64_t slot = slotOf(index[i]);
        if (slot < 0) continue;
        for (uint32_t c = 0; c < sh::VOXEL_CHANNELS; ++c) out.data[c * n3 + i] = slots[size_t(c) * v.slots + size_t(slot)];
    }
    return out;
}

std::vector<glm::vec4> readDirectLight(const gpu::Context& ctx, const VoxelVolumes& v) {
    const std::vector<uint32_t> index = readVoxelIndex(ctx, v);
    const std::vector<uint16_t> halves = readAs<uint16_t>(ctx, v.direct);
    std::vector<glm::vec4> out(index.size(), glm::vec4(0.0f));
    for (size_t i = 0; i < index.size(); ++i) {
        const int64_t slot = slotOf(index[i]);
        if (slot < 0) continue;
        for (int c = 0; c < 4; ++c) out[i][c] = glm::unpackHalf1x16(halves[size_t(slot) * 4 + size_t(c)]);
    }
    return out;
}

std::vector<glm::vec4> readRadiance(const gpu::Context& ctx, const VoxelVolumes& v) {
    const std::vector<uint16_t> halves = readAs<uint16_t>(ctx, v.radiance);
    std::vector<glm::vec4> out(halves.size() / 4);
    for (size_t i = 0; i < out.size(); ++i)
        for (int c = 0; c < 4; ++c) out[i][c] = glm::unpackHalf1x16(halves[i * 4 + size_t(c)]);
    return out;
}

std::vector<glm::uvec4> readSideLight(const gpu::Context& ctx, const VoxelVolumes& v) {
    const std::vector<uint32_t> index = readVoxelIndex(ctx, v);
    const std::vector<uint32_t> words = readAs<uint32_t>(ctx, v.sides);
    std::vector<glm::uvec4> out(index.size(), glm::uvec4(0u));
    for (size_t i = 0; i < index.size(); ++i) {
        const int64_t slot = slotOf(index[i]);
        if (slot < 0) continue;
        for (int c = 0; c < 4; ++c) out[i][c] = words[size_t(slot) * 4 + size_t(c)];
    }
    return out;
}

glm::vec3 unpackRgb9e5(uint32_t word) {
    const float scale = std::ldexp(1.0f, int(word >> 27) - 24);
    return glm::vec3(float(word & 511u), float((word >> 9) & 511u), float((word >> 18) & 511u)) * scale;
}

void uploadAttributes(const gpu::Context& ctx, const VoxelVolumes& v, const DenseAttributes& a) {
    if (a.n != v.grid.n) throw std::invalid_argument("uploadAttributes: the attributes' grid differs from the volumes'");
    const size_t n3 = size_t(a.n) * a.n * a.n;
    std::vector<uint32_t> index(n3, 0);
    std::vector<float> slots(size_t(v.slots) * sh::VOXEL_CHANNELS, 0.0f);
    std::vector<uint32_t> list(sizeof(sh::VoxelListHeader) / sizeof(uint32_t), 0);
    uint32_t count = 0;
    for (size_t i = 0; i < n3; ++i) {
        if (a.data[sh::CH_COUNT * n3 + i] <= 0.0f) continue;
        if (count == v.slots)
            throw std::runtime_error("uploadAttributes: more occupied voxels than the " + std::to_string(v.slots) +
                                     " slots");
        for (uint32_t c = 0; c < sh::VOXEL_CHANNELS; ++c) slots[size_t(c) * v.slots + count] = a.data[c * n3 + i];
        index[i] = (count + 1) | sh::VOXEL_INDEX_STATIC;
        list.push_back(sh::packVoxel(glm::ivec3(i % a.n, i / a.n % a.n, i / (size_t(a.n) * a.n))));
        ++count;
    }
    sh::VoxelListHeader header{};
    header.counts = glm::uvec4(count, count, v.slots, 0);
    header.allGroups = sh::voxelListDispatch(count);
    header.dynamicGroups = sh::voxelListDispatch(0);
    std::memcpy(list.data(), &header, sizeof(header));
    gpu::uploadBuffer(ctx, v.index, index.data(), index.size() * sizeof(uint32_t));
    gpu::uploadImage(ctx, v.accum, slots.data(), slots.size() * sizeof(float), gpu::use::ComputeReadWrite);
    gpu::uploadBuffer(ctx, v.list, list.data(), list.size() * sizeof(uint32_t));
}

}  // namespace dvsgi::vxgi
