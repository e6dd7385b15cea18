// Efficiency per pass for `dvsgi bench`: the bytes model (bench/bytes_model.h)
// filled in from a measurement's renderer and voxel counts, achieved GB/s and
// the fraction of the device's copy bandwidth (bench/bandwidth_copy.h), in the
// JSON and as a second markdown table. docs/benchmarks.md explains the model.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/bandwidth_copy.h"
#include "bench_measurement.h"

namespace dvsgi::gpu {
class Context;
}
namespace dvsgi::render {
class Renderer;
}
namespace dvsgi::scene {
struct Scene;
}

namespace dvsgi::app {

// Triangles and geometry bytes (vertices + 32-bit indices) of the draws,
// static and dynamic as the renderer splits them: a draw is dynamic when its
// node or any ancestor is.
struct SceneGeometry {
    uint64_t staticTriangles = 0, dynamicTriangles = 0;
    uint64_t staticBytes = 0, dynamicBytes = 0;
};
SceneGeometry sceneGeometry(const scene::Scene& s);

// After the measured frames, outside every timed region: counts the occupied
// and dynamic voxels (vxgi::countVoxels) and fills m.voxelCounts and m.traffic
// for the renderer's sizes and `bounces` per frame.
void modelTraffic(const gpu::Context& ctx, const render::Renderer& renderer, const SceneGeometry& geometry,
                  uint32_t bounces, Measurement& m);

nlohmann::json copyBandwidthJson(const bench::CopyBandwidth& b);

// Adds `bytes`, `bytes_read`, `bytes_written`, `gbps` and `bandwidth_fraction`
// (null without a copy bandwidth) to the JSON of a pass the model covers, at
// its median time.
void addEfficiencyJson(const Measurement& m, const std::string& pass, double medianMs, double copyGbps,
                       nlohmann::json& json);
// The measurement's voxel counts, model inputs and whole-frame figures.
void addTrafficJson(const Measurement& m, double copyGbps, nlohmann::json& json);

// Rows = the modelled passes, columns = measurements; cells "GB/s (% of copy)".
void printEfficiencyTable(const std::vector<Measurement>& ms, double copyGbps);

}  // namespace dvsgi::app
