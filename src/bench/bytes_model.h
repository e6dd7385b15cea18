// The bytes each pass of a frame must at least read and write, from resource
// sizes and occupied-voxel counts: `dvsgi bench` divides them by the passes'
// GPU times to report achieved GB/s and the fraction of the device's copy
// bandwidth (bench/bandwidth_copy.h). docs/benchmarks.md ("The bytes model")
// states every formula and what each leaves out.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace dvsgi::bench {

struct ModelInputs {
    uint32_t voxels = 0;          // N of the N^3 grid
    uint32_t slots = 0;           // voxel slot capacity (0: vxgi::defaultSlotCapacity)
    uint64_t occupiedVoxels = 0;  // fragment count > 0 after the frame (vxgi::countVoxels)
    uint64_t dynamicVoxels = 0;   // occupied and not flagged static
    uint32_t outputWidth = 0, outputHeight = 0;
    uint32_t internalWidth = 0, internalHeight = 0;  // output x supersample: G-buffer and screen terms
    uint32_t traceWidth = 0, traceHeight = 0;        // cone-tracing size (internal x trace scale)
    uint32_t shadowMapSize = 0, shadowViews = 0;     // D32 + RG16F layers rendered per frame
    uint64_t staticGeometryBytes = 0;   // vertex + index bytes of the static draws
    uint64_t dynamicGeometryBytes = 0;  // the same for the dynamic draws
    uint32_t bounces = 1;  // voxel bounces per frame, each followed by a re-filtering
    bool bounceRays = false;  // the bounce marches rays (--bounce-trace rays): three dispatches, and with
                              // bounces > 0 no filtering before the first
    bool temporal = false;  // the temporal accumulation of the indirect term runs (with voxels)
    uint32_t resolvePasses = 0;  // runs of the resolve's tent (render::resolvePasses): turned cones 1, rays
                                 // --gather-ray-filter
    bool backsDark = false;    // the filter reads the voxels' normals (--voxel-backs-dark on)
};

struct PassTraffic {
    std::string name;  // the renderer's timer name
    uint64_t readBytes = 0, writtenBytes = 0;
    uint64_t bytes() const { return readBytes + writtenBytes; }
};

// Every pass the model covers, in frame order. Passes that do not run for
// these inputs (upsample at full trace size, the voxel passes without voxels)
// are left out.
std::vector<PassTraffic> passTraffic(const ModelInputs& in);

// The pass of that timer name, or null.
const PassTraffic* findPass(const std::vector<PassTraffic>& passes, const std::string& name);

// Bytes per second in units of 1e9 from bytes and milliseconds (0 when ms <= 0).
double gigabytesPerSecond(uint64_t bytes, double ms);

}  // namespace dvsgi::bench
