#include "bench_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <thread>

#include <nlohmann/json.hpp>
#include <vulkan/vulkan.h>

#include "bench/bandwidth_copy.h"
#include "bench_efficiency.h"
#include "bench_measurement.h"
#include "gpu/context.h"
#include "image/image_io.h"
#include "progress.h"
#include "render/renderer.h"
#include "bench_flicker.h"
#include "bench_pv.h"
#include "json_file.h"
#include "render_command.h"
#include "scene/load.h"
#include "settings_table.h"
#include "vxgi/volumes.h"
#include "vxgi/voxelize.h"

namespace dvsgi::app {

namespace {

// The largest magnitude among `values` (0 for none).
double largestAbs(const std::vector<double>& values) {
    double largest = 0.0;
    for (double v : values) largest = std::max(largest, std::abs(v));
    return largest;
}

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct BenchScene {
    std::string name;  // short label: table column and JSON "scene"
    std::string path;
};

nlohmann::json summaryJson(const Summary& s, const std::vector<double>& samples) {
    return {{"median_ms", s.median}, {"min_ms", s.min}, {"max_ms", s.max}, {"mean_ms", s.mean}, {"samples_ms", samples}};
}

std::string utcNow() {
    const std::time_t t = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
}

std::string hostCpu() {
    std::ifstream f("/proc/cpuinfo");
    std::string line;
    while (std::getline(f, line))
        if (line.starts_with("model name")) {
            const size_t colon = line.find(':');
            if (colon != std::string::npos) {
                size_t b = line.find_first_not_of(" \t", colon + 1);
                return b == std::string::npos ? "" : line.substr(b);
            }
        }
    return "";
}

const char* deviceTypeName(VkPhysicalDeviceType t) {
    switch (t) {
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
        default: return "other";
    }
}

std::string versionString(uint32_t v) {
    return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
           std::to_string(VK_API_VERSION_PATCH(v));
}

nlohmann::json deviceJson(const gpu::Context& ctx) {
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 props2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props2.pNext = &driver;
    vkGetPhysicalDeviceProperties2(ctx.physical, &props2);
    uint64_t deviceLocal = 0;
    for (uint32_t i = 0; i < ctx.memory.memoryHeapCount; ++i)
        if (ctx.memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            deviceLocal = std::max<uint64_t>(deviceLocal, ctx.memory.memoryHeaps[i].size);
    return {{"name", ctx.deviceName},
            {"type", deviceTypeName(ctx.properties.deviceType)},
            {"vendor_id", ctx.properties.vendorID},
            {"device_id", ctx.properties.deviceID},
            {"api_version", versionString(ctx.properties.apiVersion)},
            {"driver_name", std::string(driver.driverName)},
            {"driver_info", std::string(driver.driverInfo)},
            {"driver_version", ctx.properties.driverVersion},
            {"device_local_heap_bytes", deviceLocal},
            {"conservative_rasterization", ctx.features.conservativeRaster}};
}

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Renders warm-up frames, then `frames` measured frames, each with static
// voxelization forced so every frame reports "voxelize static". Throws on any
// failure (e.g. out of device memory); the caller records it.
void measure(const gpu::Context& ctx, const scene::Scene& scene, const SceneGeometry& geometry, const RenderOptions& o,
             uint32_t warmup, uint32_t frames, double maxSeconds, Measurement& m,
             std::vector<std::string>& seenWarnings) {
    const auto setupStart = Clock::now();
    render::Renderer renderer(ctx, scene, o.settings);
    if (std::optional<scene::CameraPath> path = cameraPathFor(o)) renderer.setCameraPath(std::move(path));
    const double setupMs = msSince(setupStart);
    for (const std::string& w : renderer.warnings())
        if (std::find(seenWarnings.begin(), seenWarnings.end(), w) == seenWarnings.end()) {
            std::fprintf(stderr, "warning: %s\n", w.c_str());
            seenWarnings.push_back(w);
        }

    const auto warmStart = Clock::now();
    FrameProgress progress(m.scene + " " + std::to_string(o.settings.voxels) + "^3", warmup + frames, !o.quiet);
    uint32_t frame = 0;
    for (; frame < warmup; ++frame) {
        renderer.setTime(float(frame) * o.timeStep);
        const auto frameStart = Clock::now();
        const render::FrameStats stats = renderer.renderFrame();
        progress.done(frame + 1);
        // With --bounces auto the first frame converges the bounces and the
        // measured frames then add one bounce each from the previous frame.
        if (frame == 0 && stats.bounceChange >= 0.0)
            m.detail["converge"] = {{"bounces", stats.bounces},
                                    {"last_change", stats.bounceChange},
                                    {"converged", stats.converged},
                                    {"gpu_ms", stats.gpuMs},
                                    {"wall_ms", msSince(frameStart)}};
    }
    const double warmupMs = msSince(warmStart);

    // With a camera path every measured frame is reported, with its flicker
    // figure against the frame before (the last warm-up frame for the first).
    const bool perFrame = !o.cameraPath.empty();
    std::optional<render::TemporalFrame> previous;
    if (perFrame && warmup > 0) previous = render::captureIndirect(renderer);
    const auto measureStart = Clock::now();
    uint32_t bounces = 0;
    for (uint32_t i = 0; i < frames; ++i, ++frame) {
        // --bench-max-seconds: stop early (after at least one frame) on slow devices.
        if (i > 0 && maxSeconds > 0.0 && msSince(measureStart) > maxSeconds * 1000.0) break;
        renderer.setTime(float(frame) * o.timeStep);
        // Static voxelization, timed in a submission of its own, then an
        // ordinary frame (dynamic voxels cleared and re-voxelized).
        for (const gpu::TimerResult& r : renderer.revoxelizeStatic()) m.passes.add(r.name, r.ms);
        const auto start = Clock::now();
        const render::FrameStats stats = renderer.renderFrame();
        progress.done(frame + 1);
        m.wallMs.push_back(msSince(start));
        m.frameMs.push_back(stats.gpuMs);
        for (const gpu::TimerResult& r : stats.passes) m.passes.add(r.name, r.ms);
        bounces = stats.bounces;
        // Of the scene's triangles_renderer, what the raster passes drew after culling.
        m.detail["triangles_drawn"] = {{"gbuffer", stats.gbufferTriangles}, {"shadow_maps", stats.shadowTriangles}};
        if (perFrame) recordFrameFlicker(renderer, frame, float(frame) * o.timeStep, stats, previous, m);
    }
    m.frames = uint32_t(m.frameMs.size());
    modelTraffic(ctx, renderer, geometry, bounces, m);
    m.detail["frames_requested"] = frames;

    nlohmann::json memory = nlohmann::json::object();
    m.memoryBytes = 0;
    for (const render::MemoryItem& item : renderer.memory()) {
        memory[item.name] = item.bytes;
        m.memoryBytes += item.bytes;
    }
    m.detail["memory_bytes"] = memory;
    m.detail["renderer_setup_ms"] = setupMs;
    m.detail["warmup_frames"] = warmup;
    m.detail["warmup_ms"] = warmupMs;
    m.detail["triangles_renderer"] = renderer.triangleCount();
    if (const vxgi::VoxelVolumes* v = renderer.volumes()) {
        m.detail["voxel_grid"] = {
            {"n", v->grid.n},
            {"origin", {v->grid.origin.x, v->grid.origin.y, v->grid.origin.z}},
            {"voxel_size", v->grid.voxelSize},
            {"bytes_per_grid_voxel", renderer.voxelBytesPerGridVoxel()},
            {"voxel_slots", v->slots},
            {"voxelizer", renderer.voxelizer() ? vxgi::voxelizerName(renderer.voxelizer()->kind()) : "none"},
            {"conservative", renderer.voxelizer() && renderer.voxelizer()->hardwareConservative() ? "hardware"
                                                                                                  : "geometry-shader"}};
    }
}

nlohmann::json measurementJson(const Measurement& m, double copyGbps) {
    nlohmann::json j = {{"scene", m.scene}, {"file", m.file}, {"voxels", m.voxels}, {"status", m.status}};
    if (!m.variant.empty()) j["variant"] = m.variant;
    if (!m.error.empty()) j["error"] = m.error;
    if (m.status != "ok") return j;
    j["frames"] = m.frames;
    j["triangles"] = {{"static", m.staticTriangles},
                      {"dynamic", m.dynamicTriangles},
                      {"total", m.staticTriangles + m.dynamicTriangles}};
    j["gpu_memory_bytes"] = m.memoryBytes;
    for (const auto& [key, value] : m.detail.items()) j[key] = value;
    nlohmann::json passes = nlohmann::json::array();
    for (const std::string& name : m.passes.order) {
        const std::vector<double>& s = m.passes.samples.at(name);
        nlohmann::json p = summaryJson(summarize(s), s);
        p["name"] = name;
        p["count"] = s.size();  // < frames: the pass did not run in every frame
        addEfficiencyJson(m, name, summarize(s).median, copyGbps, p);
        passes.push_back(p);
    }
    j["passes"] = passes;
    j["frame_gpu"] = summaryJson(summarize(m.frameMs), m.frameMs);
    j["frame_wall"] = summaryJson(summarize(m.wallMs), m.wallMs);
    addTrafficJson(m, copyGbps, j);
    if (!m.flickerMean.empty())
        j["flicker"] = {
            {"mean_relative_change", summaryJson(summarize(m.flickerMean), m.flickerMean)},
            {"p99_relative_change", summaryJson(summarize(m.flickerP99), m.flickerP99)},
            {"irradiance",
             {{"mean_relative_change", summaryJson(summarize(m.flickerIrradianceMean), m.flickerIrradianceMean)},
              {"p99_relative_change", summaryJson(summarize(m.flickerIrradianceP99), m.flickerIrradianceP99)}}}};
    if (!m.scrollJumps.empty())
        j["flicker"]["scroll_luminance_jump"] = {{"largest_abs", largestAbs(m.scrollJumps)}, {"samples", m.scrollJumps}};
    return j;
}

std::string cell(const std::vector<double>& samples) {
    const Summary s = summarize(samples);
    char buf[64];
    if (samples.size() == 1)
        std::snprintf(buf, sizeof buf, "%.2f", s.median);
    else
        std::snprintf(buf, sizeof buf, "%.2f (%.2f-%.2f)", s.median, s.min, s.max);
    return buf;
}

// Fractions as percentages: median (min-max) over the frames.
std::string percentCell(const std::vector<double>& samples) {
    const Summary s = summarize(samples);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.2f %% (%.2f-%.2f)", 100.0 * s.median, 100.0 * s.min, 100.0 * s.max);
    return buf;
}

// Rows = passes (the union, in first-seen order), columns = measurements, like
// the paper's Table II. Cells: median (min-max) GPU ms.
void printTable(const std::vector<Measurement>& ms, const std::string& title) {
    std::vector<const Measurement*> cols;
    for (const Measurement& m : ms)
        if (m.status != "skipped") cols.push_back(&m);
    if (cols.empty()) return;
    std::vector<std::string> rows;
    for (const Measurement* m : cols)
        for (const std::string& name : m->passes.order)
            if (std::find(rows.begin(), rows.end(), name) == rows.end()) rows.push_back(name);

    std::printf("\n%s\n\n", title.c_str());
    printColumnsHeader("GPU ms: median (min-max)", cols);
    auto row = [&](const std::string& label, auto&& value) {
        std::printf("| %s |", label.c_str());
        for (const Measurement* m : cols) {
            if (m->status != "ok") {
                std::printf(" failed |");
                continue;
            }
            std::printf(" %s |", value(*m).c_str());
        }
        std::printf("\n");
    };
    for (const std::string& name : rows)
        row(name, [&](const Measurement& m) {
            const auto it = m.passes.samples.find(name);
            return it == m.passes.samples.end() ? std::string("-") : cell(it->second);
        });
    // The paper's Table IV from the same frames: the final gather with direct
    // light only, with indirect light only, with both, and the dynamic update.
    auto sumOf = [](const Measurement& m, std::initializer_list<const char*> names) {
        double sum = 0.0;
        for (const char* n : names) {
            const auto it = m.passes.samples.find(n);
            if (it != m.passes.samples.end()) sum += summarize(it->second).median;
        }
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.2f", sum);
        return std::string(buf);
    };
    row("Table IV: direct (gbuffer + direct lighting + composite)",
        [&](const Measurement& m) { return sumOf(m, {"gbuffer", "direct lighting", "composite"}); });
    row("Table IV: indirect (cone tracing + upsample)",
        [&](const Measurement& m) { return sumOf(m, {"cone tracing", "upsample"}); });
    row("Table IV: both", [&](const Measurement& m) {
        return sumOf(m, {"gbuffer", "direct lighting", "cone tracing", "upsample", "composite"});
    });
    row("Table IV/VI: dynamic update (clear + voxelize dynamic + voxel light + filtering + bounce)",
        [&](const Measurement& m) {
            return sumOf(m, {"clear dynamic voxels", "voxelize dynamic", "voxel direct light", "voxel filtering",
                             "voxel bounce", "voxel filtering (bounce)"});
        });
    row("**frame (GPU)**", [](const Measurement& m) { return cell(m.frameMs); });
    row("frame (wall)", [](const Measurement& m) { return cell(m.wallMs); });
    row("frames measured", [](const Measurement& m) { return std::to_string(m.frames); });
    if (std::any_of(cols.begin(), cols.end(), [](const Measurement* m) { return !m->flickerMean.empty(); })) {
        row("flicker: mean relative change of the indirect term, frame to frame", [](const Measurement& m) {
            return m.flickerMean.empty() ? std::string("-") : percentCell(m.flickerMean);
        });
        row("flicker: 99th percentile of the relative change", [](const Measurement& m) {
            return m.flickerP99.empty() ? std::string("-") : percentCell(m.flickerP99);
        });
        row("flicker of the irradiance (before the albedo): mean", [](const Measurement& m) {
            return m.flickerIrradianceMean.empty() ? std::string("-") : percentCell(m.flickerIrradianceMean);
        });
        row("flicker of the irradiance: 99th percentile", [](const Measurement& m) {
            return m.flickerIrradianceP99.empty() ? std::string("-") : percentCell(m.flickerIrradianceP99);
        });
        row("largest mean indirect luminance jump at a clipmap scroll", [](const Measurement& m) {
            if (m.scrollJumps.empty()) return std::string("-");
            char buf[48];
            std::snprintf(buf, sizeof buf, "%.2f %% (%zu scrolls)", 100.0 * largestAbs(m.scrollJumps),
                          m.scrollJumps.size());
            return std::string(buf);
        });
    }
    row("triangles static / dynamic", [](const Measurement& m) {
        return std::to_string(m.staticTriangles) + " / " + std::to_string(m.dynamicTriangles);
    });
    row("GPU memory (MiB)", [](const Measurement& m) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.1f", double(m.memoryBytes) / 1048576.0);
        return std::string(buf);
    });
    row("voxel data, bytes per grid voxel (all volumes, mips and the list)", [](const Measurement& m) {
        char buf[32];
        if (!m.detail.contains("voxel_grid")) return std::string("-");
        std::snprintf(buf, sizeof buf, "%.1f", m.detail["voxel_grid"]["bytes_per_grid_voxel"].get<double>());
        return std::string(buf);
    });
    for (const Measurement* m : cols)
        if (m->status == "failed") std::printf("\n%s %u^3 failed: %s\n", m->scene.c_str(), m->voxels, m->error.c_str());
}


}  // namespace

int runBench(const RenderOptions& options) {
    if (options.pvTables) return runPvTables(options);
    RenderOptions o = options;
    if (!o.isGiven("width")) o.settings.width = 640;
    if (!o.isGiven("height")) o.settings.height = 360;
    if (o.benchQuick) {
        o.benchVoxels = {32};
        o.benchFrames = 2;
        o.benchWarmup = 1;
        o.settings.width = 160;
        o.settings.height = 90;
    }
    const std::vector<uint32_t>& resolutions = o.benchVoxels;
    const uint32_t frames = o.benchFrames, warmup = o.benchWarmup;
    cameraPathFor(o);  // a bad --camera-path fails now, not in every measurement

    const fs::path shared(o.sharedDir);
    const fs::path scenes = shared / "scenes";
    std::vector<BenchScene> suite;
    if (!o.scene.empty())
        suite.push_back({fs::path(o.scene).stem().string(), o.scene});
    else {
        suite.push_back({"cornell", (scenes / "cornell-box/cornell-lights.gltf").string()});
        if (!o.benchQuick) {
            suite.push_back({"sibenik", (scenes / "sibenik/sibenik-point.gltf").string()});
            suite.push_back({"sponza", (scenes / "crytek-sponza/sponza-sun.gltf").string()});
        }
    }
    // The moving dynamic object: --add-model, else the Stanford bunny.
    // "none": static scenes only (what the flicker figure of a camera path wants).
    std::string dynamicModel = o.addModel.empty() ? (scenes / "stanford-bunny/bun_zipper.ply").string()
                               : o.addModel == "none" ? std::string()
                                                      : o.addModel;
    if (!dynamicModel.empty() && !fs::exists(dynamicModel)) {
        std::fprintf(stderr, "warning: dynamic object %s not found; benchmarking without one\n", dynamicModel.c_str());
        dynamicModel.clear();
    }

    gpu::ContextOptions co;
    co.validation = o.validate;
    co.deviceName = o.device;
    gpu::Context ctx(co);

    nlohmann::json out;
    out["tool"] = "dvsgi bench";
    out["date"] = utcNow();
    out["command_line"] = o.commandLine;
    out["device"] = deviceJson(ctx);
    const char* lpThreads = std::getenv("LP_NUM_THREADS");
    out["host"] = {{"cpu", hostCpu()},
                   {"hardware_threads", std::thread::hardware_concurrency()},
                   {"LP_NUM_THREADS", lpThreads ? lpThreads : ""}};
    // Every setting the bench takes, as it ran (the bench's own image size and
    // --bench-quick applied), and what the bench adds.
    out["settings"] = settingsJson(o, kBench);
    out["dynamic_model"] = dynamicModel.empty() ? nlohmann::json(nullptr) : nlohmann::json(dynamicModel);
    out["static_voxelization"] = "timed in its own submission before every measured frame (Renderer::revoxelizeStatic)";

    std::fprintf(stderr, "dvsgi bench: %s, %ux%u, %u warm-up + %u measured frame(s) per measurement\n",
                 ctx.deviceName.c_str(), o.settings.width, o.settings.height, warmup, frames);
    // Once per run, before any measurement: the yardstick of the efficiency table.
    double copyGbps = 0.0;
    try {
        const bench::CopyBandwidth copy = bench::measureCopyBandwidth(ctx, bench::copyBandwidthBytes(ctx), 5);
        copyGbps = copy.gbps;
        out["device"]["copy_bandwidth_gbps"] = copy.gbps;
        out["device"]["copy_bandwidth"] = copyBandwidthJson(copy);
        std::fprintf(stderr, "copy bandwidth: %.2f GB/s (%llu MiB buffer read and written, median of %u: %.3f ms)\n",
                     copy.gbps, (unsigned long long)(copy.bufferBytes >> 20), copy.repetitions, copy.medianMs);
    } catch (const std::exception& e) {
        out["device"]["copy_bandwidth_gbps"] = nullptr;
        out["device"]["copy_bandwidth"] = {{"error", e.what()}};
        std::fprintf(stderr, "warning: copy bandwidth not measured: %s\n", e.what());
    }

    std::vector<Measurement> results;
    auto writeResults = [&] {
        nlohmann::json list = nlohmann::json::array();
        for (const Measurement& m : results) list.push_back(measurementJson(m, copyGbps));
        out["measurements"] = list;
        out["validation_errors"] = ctx.validationErrors();
        writeJsonFile(o.benchOut, out);
    };
    out["complete"] = false;
    std::vector<std::string> seenWarnings;
    struct Variant {
        std::string name;
        std::function<void(RenderOptions&)> apply;
    };
    std::vector<Variant> variants = {{"", [](RenderOptions&) {}}};
    if (o.benchTables) {
        variants.push_back({"raycast occlusion", [](RenderOptions& r) { r.settings.voxelLight.occlusion = vxgi::Occlusion::RaycastHard; }});
        for (float a : {1.0f, 5.0f, 10.0f, 25.0f})
            variants.push_back({"shadow cone " + std::to_string(int(a)) + " deg", [a](RenderOptions& r) {
                                    r.settings.shadowCones.enabled = true;
                                    r.settings.shadowCones.apertureDegrees = a;
                                }});
    }
    const size_t total = suite.size() * resolutions.size() * variants.size();
    size_t index = 0, ok = 0;
    uint32_t validationBefore = ctx.validationErrors();
    for (const BenchScene& bs : suite) {
        // Load once per scene; a missing or unreadable scene skips all its measurements.
        std::string skipReason;
        scene::Scene scene;
        double loadMs = 0.0;
        if (!fs::exists(bs.path)) {
            skipReason = bs.path + ": file not found";
        } else {
            RenderOptions so = o;
            so.scene = bs.path;
            so.addModel = dynamicModel;
            try {
                const auto start = Clock::now();
                scene = loadForOptions(so);
                loadMs = msSince(start);
                for (const std::string& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
            } catch (const std::exception& e) {
                skipReason = e.what();
            }
        }
        if (!skipReason.empty()) std::fprintf(stderr, "warning: skipping %s: %s\n", bs.name.c_str(), skipReason.c_str());

        const SceneGeometry geometry = skipReason.empty() ? sceneGeometry(scene) : SceneGeometry{};

        for (uint32_t n : resolutions)
        for (const Variant& variant : variants) {
            ++index;
            Measurement m;
            m.scene = bs.name;
            m.file = bs.path;
            m.voxels = n;
            m.variant = variant.name;
            const std::string label = bs.name + (variant.name.empty() ? "" : " (" + variant.name + ")");
            if (!skipReason.empty()) {
                std::fprintf(stderr, "[%zu/%zu] %s %u^3 skipped\n", index, total, label.c_str(), n);
                m.status = "skipped";
                m.error = skipReason;
                results.push_back(std::move(m));
                continue;
            }
            std::fprintf(stderr, "[%zu/%zu] %s %u^3 ...\n", index, total, label.c_str(), n);
            std::fflush(stderr);
            RenderOptions mo = o;
            mo.settings.voxels = n;
            variant.apply(mo);
            m.staticTriangles = geometry.staticTriangles;
            m.dynamicTriangles = geometry.dynamicTriangles;
            const auto start = Clock::now();
            try {
                measure(ctx, scene, geometry, mo, warmup, frames, o.benchMaxSeconds, m, seenWarnings);
                m.status = "ok";
                m.detail["scene_load_ms"] = loadMs;
                ++ok;
                const auto vs = m.passes.samples.find("voxelize static");
                std::fprintf(stderr, "[%zu/%zu] %s %u^3 done in %.1f s: voxelize static %.2f ms, frame %.2f ms (GPU medians)\n",
                             index, total, label.c_str(), n, msSince(start) / 1000.0,
                             vs == m.passes.samples.end() ? 0.0 : summarize(vs->second).median,
                             summarize(m.frameMs).median);
            } catch (const std::exception& e) {
                m.status = "failed";
                m.error = e.what();
                m.passes = {};
                m.frameMs.clear();
                m.wallMs.clear();
                std::fprintf(stderr, "[%zu/%zu] %s %u^3 failed: %s\n", index, total, label.c_str(), n, e.what());
            }
            const uint32_t validationNow = ctx.validationErrors();
            m.detail["validation_errors"] = validationNow - validationBefore;
            validationBefore = validationNow;
            results.push_back(std::move(m));
            writeResults();  // after every measurement, so an interrupted run keeps what it measured
        }
    }
    out["complete"] = true;
    writeResults();

    if (!o.quiet) {
        char copy[64] = "copy bandwidth not measured";
        if (copyGbps > 0.0) std::snprintf(copy, sizeof copy, "copy bandwidth %.2f GB/s", copyGbps);
        printTable(results, "dvsgi bench, " + ctx.deviceName + ", " + std::to_string(o.settings.width) + "x" +
                                std::to_string(o.settings.height) + ", " + out["date"].get<std::string>() + ", " +
                                copy);
        printEfficiencyTable(results, copyGbps);
        std::printf("\nwrote %s\n", o.benchOut.c_str());
    }
    if (ctx.validationErrors() > 0) {
        std::fprintf(stderr, "dvsgi: %u Vulkan validation error(s)\n", ctx.validationErrors());
        return 3;
    }
    if (ok == 0) {
        std::fprintf(stderr, "dvsgi: bench: no measurement succeeded\n");
        return 1;
    }
    return 0;
}

}  // namespace dvsgi::app
