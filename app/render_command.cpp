#include "render_command.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "gpu/context.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/load.h"

namespace dvsgi::app {

namespace {

std::string pngPathFor(const RenderOptions& o) {
    if (o.outPng == "none") return "";
    if (!o.outPng.empty()) return o.outPng;
    return std::filesystem::path(o.outExr).replace_extension(".png").string();
}

void printTable(const render::FrameStats& stats, const std::vector<render::MemoryItem>& memory) {
    std::printf("%-24s %10s\n", "pass", "GPU ms");
    for (const gpu::TimerResult& r : stats.passes) std::printf("%-24s %10.3f\n", r.name.c_str(), r.ms);
    std::printf("%-24s %10.3f\n", "frame total", stats.gpuMs);
    uint64_t total = 0;
    for (const render::MemoryItem& m : memory) total += m.bytes;
    std::printf("GPU memory: %.1f MiB\n", double(total) / (1024.0 * 1024.0));
}

void writeMetrics(const std::string& path, const RenderOptions& o, const gpu::Context& ctx,
                  const render::Renderer& renderer, const render::FrameStats& stats, const scene::Scene& scene) {
    nlohmann::json j;
    j["scene"] = scene.source;
    j["device"] = ctx.deviceName;
    j["width"] = o.width;
    j["height"] = o.height;
    j["supersample"] = o.supersample;
    j["shadow_map_size"] = o.shadowMapSize;
    j["camera"] = o.camera;
    j["triangles"] = renderer.triangleCount();
    j["lights"] = scene.lights.size();
    j["gpu_ms"] = stats.gpuMs;
    for (const gpu::TimerResult& r : stats.passes) j["passes"].push_back({{"name", r.name}, {"ms", r.ms}});
    for (const render::MemoryItem& m : renderer.memory()) j["memory_bytes"][m.name] = m.bytes;
    j["validation_errors"] = ctx.validationErrors();
    std::filesystem::path p(path);
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    std::ofstream f(path);
    if (!f) throw image::IoError(path + ": cannot open for writing");
    f << j.dump(2) << "\n";
    if (!f) throw image::IoError(path + ": write failed");
}

}  // namespace

int runRender(const RenderOptions& o) {
    scene::Scene scene = o.scene.empty() ? scene::builtinCornellBox() : scene::loadScene(o.scene);
    for (const std::string& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());

    gpu::ContextOptions co;
    co.validation = o.validate;
    co.deviceName = o.device;
    co.printDevice = !o.quiet;
    gpu::Context ctx(co);

    render::RenderSettings rs;
    rs.width = o.width;
    rs.height = o.height;
    rs.supersample = o.supersample;
    rs.shadowMapSize = o.shadowMapSize;
    rs.camera = o.camera;
    render::Renderer renderer(ctx, scene, rs);
    for (const std::string& w : renderer.warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());

    const render::FrameStats stats = renderer.renderFrame();
    const image::ImageRGBA32F img = renderer.readOutput();
    image::writeExr(o.outExr, img);
    const std::string png = pngPathFor(o);
    if (!png.empty()) image::writePng(png, img, o.exposure);
    if (!o.metricsPath.empty()) writeMetrics(o.metricsPath, o, ctx, renderer, stats, scene);
    if (!o.quiet) {
        printTable(stats, renderer.memory());
        std::printf("wrote %s%s%s\n", o.outExr.c_str(), png.empty() ? "" : " and ", png.c_str());
    }
    if (ctx.validationErrors() > 0) {
        std::fprintf(stderr, "dvsgi: %u Vulkan validation error(s)\n", ctx.validationErrors());
        return 3;
    }
    return 0;
}

}  // namespace dvsgi::app
