#include "bench_efficiency.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "gpu/context.h"
#include "render/frame_resources.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "vxgi/voxel_counts.h"

namespace dvsgi::app {

namespace {

// Three significant digits, no exponent below 1000.
std::string figure(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, x >= 100.0 ? "%.0f" : "%.3g", x);
    return buf;
}

// The modelled bytes of the passes the frames ran.
uint64_t frameBytes(const Measurement& m) {
    uint64_t bytes = 0;
    for (const bench::PassTraffic& t : m.traffic)
        if (m.passes.samples.count(t.name)) bytes += t.bytes();
    return bytes;
}

nlohmann::json fraction(double gbps, double copyGbps) {
    return copyGbps > 0.0 ? nlohmann::json(gbps / copyGbps) : nlohmann::json(nullptr);
}

}  // namespace

SceneGeometry sceneGeometry(const scene::Scene& s) {
    SceneGeometry g;
    for (const scene::DrawItem& it : scene::drawItems(s, scene::worldMatrices(s))) {
        bool dynamic = false;
        for (int n = it.node; n >= 0 && size_t(n) < s.nodes.size(); n = s.nodes[size_t(n)].parent)
            dynamic = dynamic || s.nodes[size_t(n)].dynamic;
        const scene::Primitive& p = s.primitives[it.primitive];
        const uint64_t tris = p.indices.size() / 3;
        const uint64_t bytes = p.vertices.size() * sizeof(scene::Vertex) + p.indices.size() * sizeof(uint32_t);
        (dynamic ? g.dynamicTriangles : g.staticTriangles) += tris;
        (dynamic ? g.dynamicBytes : g.staticBytes) += bytes;
    }
    return g;
}

void modelTraffic(const gpu::Context& ctx, const render::Renderer& renderer, const SceneGeometry& geometry,
                  uint32_t bounces, Measurement& m) {
    const render::RenderSettings& s = renderer.settings();
    render::FrameSize size;
    size.width = s.width;
    size.height = s.height;
    size.supersample = s.supersample;
    size.traceScale = s.gather.traceScale;
    bench::ModelInputs& in = m.modelInputs;
    in = {};
    in.outputWidth = s.width;
    in.outputHeight = s.height;
    in.internalWidth = size.internalWidth();
    in.internalHeight = size.internalHeight();
    in.traceWidth = size.traceWidth();
    in.traceHeight = size.traceHeight();
    in.shadowMapSize = s.shadowMapSize;
    in.shadowViews = renderer.shadowViewCount();
    in.temporal = s.temporal.enabled;
    in.staticGeometryBytes = geometry.staticBytes;
    in.dynamicGeometryBytes = geometry.dynamicBytes;
    in.bounces = bounces;
    in.bounceRays = renderer.bounceRays();
    in.resolvePasses = render::resolvePasses(s.gather, renderer.gatherRays(), s.cones.coneSet);
    in.backsDark = s.voxelLight.backsDark;
    if (const vxgi::VoxelVolumes* volumes = renderer.volumes()) {
        const auto start = std::chrono::steady_clock::now();
        const vxgi::VoxelCounts counts = vxgi::countVoxels(ctx, *volumes);
        m.detail["voxel_count_ms"] =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        in.voxels = volumes->grid.n;
        in.slots = volumes->slots;
        in.occupiedVoxels = m.occupiedVoxels = counts.occupied;
        in.dynamicVoxels = m.dynamicVoxels = counts.dynamic;
        m.counted = true;
    }
    m.traffic = bench::passTraffic(in);
}

nlohmann::json copyBandwidthJson(const bench::CopyBandwidth& b) {
    return {{"buffer_bytes", b.bufferBytes},
            {"bytes_per_copy", 2 * b.bufferBytes},
            {"repetitions", b.repetitions},
            {"samples_ms", b.samplesMs},
            {"median_ms", b.medianMs},
            {"gbps", b.gbps}};
}

void addEfficiencyJson(const Measurement& m, const std::string& pass, double medianMs, double copyGbps,
                       nlohmann::json& json) {
    const bench::PassTraffic* t = bench::findPass(m.traffic, pass);
    if (!t) return;
    const double gbps = bench::gigabytesPerSecond(t->bytes(), medianMs);
    json["bytes"] = t->bytes();
    json["bytes_read"] = t->readBytes;
    json["bytes_written"] = t->writtenBytes;
    json["gbps"] = gbps;
    json["bandwidth_fraction"] = fraction(gbps, copyGbps);
}

void addTrafficJson(const Measurement& m, double copyGbps, nlohmann::json& json) {
    if (m.traffic.empty()) return;
    if (m.counted) json["voxel_counts"] = {{"occupied", m.occupiedVoxels}, {"dynamic", m.dynamicVoxels}};
    const bench::ModelInputs& in = m.modelInputs;
    json["bytes_model"] = {{"voxels", in.voxels},
                           {"occupied_voxels", in.occupiedVoxels},
                           {"dynamic_voxels", in.dynamicVoxels},
                           {"output", {in.outputWidth, in.outputHeight}},
                           {"internal", {in.internalWidth, in.internalHeight}},
                           {"trace", {in.traceWidth, in.traceHeight}},
                           {"shadow_map_size", in.shadowMapSize},
                           {"shadow_views", in.shadowViews},
                           {"static_geometry_bytes", in.staticGeometryBytes},
                           {"dynamic_geometry_bytes", in.dynamicGeometryBytes},
                           {"slots", in.slots},
                           {"temporal", in.temporal},
                           {"bounces", in.bounces},
                           {"bounce_rays", in.bounceRays}};
    // The whole frame: the modelled bytes of its passes over its time.
    const uint64_t bytes = frameBytes(m);
    const double gbps = bench::gigabytesPerSecond(bytes, summarize(m.frameMs).median);
    json["frame_gpu"]["bytes"] = bytes;
    json["frame_gpu"]["gbps"] = gbps;
    json["frame_gpu"]["bandwidth_fraction"] = fraction(gbps, copyGbps);
}

void printEfficiencyTable(const std::vector<Measurement>& ms, double copyGbps) {
    std::vector<const Measurement*> cols;
    for (const Measurement& m : ms)
        if (m.status == "ok" && !m.traffic.empty()) cols.push_back(&m);
    if (cols.empty()) return;
    std::vector<std::string> rows;
    for (const Measurement* m : cols)
        for (const std::string& name : m->passes.order)
            if (bench::findPass(m->traffic, name) && std::find(rows.begin(), rows.end(), name) == rows.end())
                rows.push_back(name);

    std::printf("\nGB/s of the bytes model at the median time (%% of the copy bandwidth, %s GB/s)\n\n",
                copyGbps > 0.0 ? figure(copyGbps).c_str() : "not measured");
    printColumnsHeader("pass", cols);
    auto row = [&](const std::string& label, auto&& value) {
        std::printf("| %s |", label.c_str());
        for (const Measurement* m : cols) std::printf(" %s |", value(*m).c_str());
        std::printf("\n");
    };
    auto rate = [&](uint64_t bytes, double ms) {
        const double gbps = bench::gigabytesPerSecond(bytes, ms);
        return figure(gbps) + (copyGbps > 0.0 ? " (" + figure(100.0 * gbps / copyGbps) + " %)" : "");
    };
    for (const std::string& name : rows)
        row(name, [&](const Measurement& m) {
            const bench::PassTraffic* t = bench::findPass(m.traffic, name);
            const auto it = m.passes.samples.find(name);
            if (!t || it == m.passes.samples.end()) return std::string("-");
            return rate(t->bytes(), summarize(it->second).median);
        });
    row("**frame (GPU)**", [&](const Measurement& m) { return rate(frameBytes(m), summarize(m.frameMs).median); });
    row("modelled MB per frame", [&](const Measurement& m) { return figure(double(frameBytes(m)) / 1e6); });
    row("occupied / dynamic voxels", [](const Measurement& m) {
        return m.counted ? std::to_string(m.occupiedVoxels) + " / " + std::to_string(m.dynamicVoxels)
                         : std::string("-");
    });
}

}  // namespace dvsgi::app
