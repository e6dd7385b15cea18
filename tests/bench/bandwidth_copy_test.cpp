// The bench's copy kernel copies exactly, without validation messages, and
// its measurement reports what it measured. No timing is asserted.
#include <cstring>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "bench/bandwidth_copy.h"
#include "gpu/context.h"
#include "gpu/transfer.h"
#include "gpu_fixture.h"

namespace dvsgi::test {
namespace {

class BandwidthCopy : public GpuTest {};

TEST_F(BandwidthCopy, CopiesTheRequestedBytes) {
    // A destination larger than the copied range: the rest must stay untouched.
    const uint32_t words = 300'000 * 4;  // 300,000 uvec4, 4.8 MB
    std::vector<uint32_t> pattern(words);
    std::iota(pattern.begin(), pattern.end(), 7u);
    const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    const gpu::Buffer src = gpu::createBuffer(context(), pattern.data(), words * 4, usage, "copy test source");
    const std::vector<uint32_t> zeros(words + 4, 0u);
    const gpu::Buffer dst =
        gpu::createBuffer(context(), zeros.data(), zeros.size() * 4, usage, "copy test destination");
    const bench::BandwidthCopyPass pass(context());
    context().submitAndWait(
        [&](VkCommandBuffer cmd) { pass.record(cmd, src, dst, VkDeviceSize(words) * 4, nullptr, ""); });
    const std::vector<uint8_t> bytes = gpu::readbackBuffer(context(), dst);
    std::vector<uint32_t> got(bytes.size() / 4);
    std::memcpy(got.data(), bytes.data(), bytes.size());
    size_t wrong = 0;
    for (uint32_t i = 0; i < words; ++i) wrong += got[i] != pattern[i];
    EXPECT_EQ(wrong, 0u);
    for (uint32_t i = words; i < got.size(); ++i) EXPECT_EQ(got[i], 0u) << "wrote past the copied range at " << i;
}

TEST_F(BandwidthCopy, MeasurementReportsEveryRepetition) {
    const bench::CopyBandwidth b = bench::measureCopyBandwidth(context(), 4ull << 20, 3);
    std::printf("copy bandwidth, 4 MiB buffers: %.2f GB/s (median of %zu: %.3f ms)\n", b.gbps, b.samplesMs.size(),
                b.medianMs);
    EXPECT_EQ(b.bufferBytes, 4ull << 20);
    EXPECT_EQ(b.repetitions, 3u);
    ASSERT_EQ(b.samplesMs.size(), 3u);
    EXPECT_GT(b.medianMs, 0.0);
    EXPECT_NEAR(b.gbps, 2.0 * double(4ull << 20) / (b.medianMs * 1e6), 1e-9 * b.gbps);
}

TEST_F(BandwidthCopy, SizeFollowsTheHeap) {
    const uint64_t bytes = bench::copyBandwidthBytes(context());
    std::printf("copy bandwidth buffers: %llu MiB each\n", (unsigned long long)(bytes >> 20));
    EXPECT_GE(bytes, 16ull << 20);
    EXPECT_LE(bytes, 256ull << 20);
    EXPECT_LE(bytes, context().properties.limits.maxStorageBufferRange);
    EXPECT_EQ(bytes % 16, 0u);
}

}  // namespace
}  // namespace dvsgi::test
