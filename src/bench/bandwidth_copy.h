// The device's copy bandwidth, measured with a compute kernel that streams one
// storage buffer into another (shaders/bandwidth_copy.comp). `dvsgi bench`
// divides every pass's modelled traffic (bench/bytes_model.h) by its time and
// compares the result with this figure. Not a rendering pass: nothing of the
// frame uses it.
#pragma once

#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/pipeline.h"
#include "gpu/resources.h"

namespace dvsgi::gpu {
class Context;
class GpuTimers;
}

namespace dvsgi::bench {

class BandwidthCopyPass {
public:
    explicit BandwidthCopyPass(const gpu::Context& ctx);
    // Copies the first `bytes` (a multiple of 16) of `src` into `dst`. The
    // caller orders it against other accesses to the two buffers.
    void record(VkCommandBuffer cmd, const gpu::Buffer& src, const gpu::Buffer& dst, VkDeviceSize bytes,
                gpu::GpuTimers* timers, const char* timerName) const;

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
};

struct CopyBandwidth {
    uint64_t bufferBytes = 0;       // each of source and destination
    uint32_t repetitions = 0;       // timed copies (after one untimed warm-up copy)
    std::vector<double> samplesMs;  // GPU time of each timed copy
    double medianMs = 0.0;
    double gbps = 0.0;              // (bytes read + bytes written) / median time, 1e9 bytes per second
};

// Buffer size for the measurement: 1/32 of the largest device-local heap,
// clamped to [16 MiB, 256 MiB] and to what one storage buffer and one
// allocation may hold. 256 MiB per buffer exceeds any GPU's last-level cache;
// lavapipe's 2 GiB heap gives 64 MiB, copied in well under a second.
uint64_t copyBandwidthBytes(const gpu::Context& ctx);

// One warm-up copy (pipeline compilation, first touch of the pages), then
// `repetitions` timed copies, one submission each.
CopyBandwidth measureCopyBandwidth(const gpu::Context& ctx, uint64_t bytes, uint32_t repetitions);

}  // namespace dvsgi::bench
