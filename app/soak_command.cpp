#include "soak_command.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "shared/composite_pass.h"
#include "device_faults.h"
#include "gpu/context.h"
#include "gpu/resources.h"
#include "image/image_io.h"
#include "progress.h"
#include "render/renderer.h"
#include "json_file.h"
#include "render_command.h"
#include "scene/scene.h"

namespace dvsgi::app {

namespace {

// The settings the soak cycles through, one per --soak-every block. The first
// is the command line itself; the others change what a user changes in the
// viewer's panel, each of which needs a new Renderer.
struct Variant {
    const char* label;
    void (*apply)(RenderOptions&);
};

const Variant kVariants[] = {
    {"command line", [](RenderOptions&) {}},
    {"bounces 1, cones 16, shadows cone, output indirect, ao on",
     [](RenderOptions& o) {
         o.settings.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
         o.settings.voxelLight.bounces = 1;
         o.settings.cones.coneSet = shader::CONE_SET_16;
         o.settings.shadowCones.enabled = true;
         o.settings.outputTerm = shader::TERM_INDIRECT;
         o.settings.applyAO = true;
     }},
    {"bounces 2, cones 6, voxel occlusion raycast, output direct, trace scale 0.5",
     [](RenderOptions& o) {
         o.settings.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
         o.settings.voxelLight.bounces = 2;
         o.settings.cones.coneSet = shader::CONE_SET_6;
         o.settings.voxelLight.occlusion = vxgi::Occlusion::RaycastHard;
         o.settings.outputTerm = shader::TERM_DIRECT;
         o.settings.gather.traceScale = 0.5f;
     }},
    {"bounces auto, cones 16, view voxels:radiance",
     [](RenderOptions& o) {
         o.settings.voxelLight.bounceMode = vxgi::BounceMode::Converge;
         o.settings.cones.coneSet = shader::CONE_SET_16;
         o.settings.view.mode = render::ViewMode::VoxelRadiance;
     }},
};
constexpr uint32_t kVariantCount = uint32_t(std::size(kVariants));

// A unit cube (24 vertices, flat normals), the moving object when no
// --add-model is given, so the soak needs no file.
scene::Scene builtinCube() {
    scene::Scene s;
    s.source = "builtin:cube";
    scene::Material m;
    m.name = "cube";
    m.baseColorFactor = glm::vec4(0.8f, 0.7f, 0.5f, 1.0f);
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 0.4f;
    s.materials.push_back(m);
    scene::Primitive p;
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 n(0.0f), u(0.0f), v(0.0f);
            n[axis] = sign;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = 1.0f;
            if (sign < 0.0f) std::swap(u, v);  // counter-clockwise seen from outside
            const uint32_t base = uint32_t(p.vertices.size());
            for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
                scene::Vertex vert;
                vert.position = 0.5f * (n + c.x * u + c.y * v);
                vert.normal = n;
                vert.uv = 0.5f * (c + glm::vec2(1.0f));
                p.vertices.push_back(vert);
            }
            for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) p.indices.push_back(base + i);
        }
    s.primitives.push_back(p);
    s.meshes.push_back({"cube", {0}});
    scene::Node node;
    node.name = "cube";
    node.mesh = 0;
    s.nodes.push_back(node);
    s.roots = {0};
    return s;
}

uint64_t residentBytes() {
    std::ifstream statm("/proc/self/statm");
    uint64_t size = 0, resident = 0;
    statm >> size >> resident;
    if (!statm) throw std::runtime_error("soak: cannot read /proc/self/statm for the resident set size");
    return resident * uint64_t(sysconf(_SC_PAGESIZE));
}

// Resident bytes of executable anonymous mappings: code a driver compiled at
// run time (lavapipe's LLVM JIT; its code pages are not malloc'd), which
// dvsgi neither allocates nor frees itself.
uint64_t jitCodeBytes() {
    std::ifstream smaps("/proc/self/smaps");
    if (!smaps) throw std::runtime_error("soak: cannot read /proc/self/smaps for the driver's JIT code");
    uint64_t total = 0;
    bool jit = false;
    std::string line;
    while (std::getline(smaps, line)) {
        std::istringstream fields(line);
        std::string range, perms;
        fields >> range >> perms;
        if (range.find('-') != std::string::npos && perms.size() == 4 && !range.empty() &&
            std::isxdigit(static_cast<unsigned char>(range[0]))) {
            // "start-end perms offset dev inode [path]": anonymous when no path follows the inode.
            std::string offset, dev, inode, path;
            fields >> offset >> dev >> inode >> path;
            jit = perms[2] == 'x' && path.empty();
        } else if (jit && line.rfind("Rss:", 0) == 0) {
            total += std::stoull(line.substr(4)) * 1024;  // kB
        }
    }
    return total;
}

struct Report {
    uint32_t frame = 0;    // frames finished
    uint32_t variant = 0;  // kVariants index of the block that just ended
    bool warmup = true;    // within the first cycle of variants
    uint64_t rss = 0;
    uint64_t jitCode = 0;  // part of rss: jitCodeBytes()
    gpu::LiveMemory live;
    int64_t budgetUsage = -1;  // VK_EXT_memory_budget, -1 without it
    double outputMean = 0.0;   // mean of the output's RGB: the scene moved when it changes
    double seconds = 0.0;
};

// The first light's node, moved on a small circle and swung about the
// vertical each frame so the shadow maps, the voxel light and the bounces
// all change (sceneChanged re-uploads lights and shadow views).
struct LightMover {
    int node = -1;
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    float radius = 0.0f;

    void apply(scene::Scene& s, float t) const {
        if (node < 0) return;
        scene::Node& n = s.nodes[size_t(node)];
        const float a = 2.0f * 3.14159265f * t / 3.0f;  // one turn every 3 s
        n.translation = translation + radius * glm::vec3(std::cos(a), 0.0f, std::sin(a));
        n.rotation = glm::angleAxis(0.15f * std::sin(a), glm::vec3(0.0f, 1.0f, 0.0f)) * rotation;
    }
};

LightMover lightMover(const scene::Scene& s) {
    LightMover m;
    for (size_t i = 0; i < s.nodes.size() && m.node < 0; ++i)
        if (s.nodes[i].light >= 0) m.node = int(i);
    if (m.node < 0) return m;
    m.translation = s.nodes[size_t(m.node)].translation;
    m.rotation = s.nodes[size_t(m.node)].rotation;
    const scene::Bounds b = scene::worldBounds(s, scene::drawItems(s, scene::worldMatrices(s)));
    m.radius = b.valid() ? 0.05f * glm::length(b.max - b.min) : 0.1f;
    return m;
}

double meanRgb(const image::ImageRGBA32F& img) {
    double sum = 0.0;
    for (size_t i = 0; i + 3 < img.rgba.size(); i += 4) {
        for (int c = 0; c < 3; ++c) {
            const float v = img.rgba[i + size_t(c)];
            if (!std::isfinite(v)) throw std::runtime_error("soak: the output holds a non-finite value");
            sum += v;
        }
    }
    return sum / std::max<double>(1.0, double(img.rgba.size() / 4) * 3.0);
}

double growthPercent(double from, double to) { return from > 0.0 ? 100.0 * (to - from) / from : 0.0; }

nlohmann::json reportJson(const Report& r) {
    return {{"frame", r.frame},
            {"variant", r.variant},
            {"warmup", r.warmup},
            {"rss_bytes", r.rss},
            {"rss_jit_code_bytes", r.jitCode},
            {"device_bytes", r.live.bytes},
            {"device_allocations", r.live.allocations},
            {"device_budget_usage_bytes", r.budgetUsage < 0 ? nlohmann::json() : nlohmann::json(r.budgetUsage)},
            {"output_mean", r.outputMean},
            {"seconds", r.seconds}};
}


}  // namespace

int runSoak(const RenderOptions& options) {
    const uint32_t every = options.soakEvery, blocks = (options.soakFrames + every - 1) / every;
    if (options.settings.voxels == 0)
        throw std::runtime_error("--voxels 0: the soak cycles voxel settings (cones, bounces); use --voxels 32 or more");
    // Growth compares two reports of the same variant, the later one the last;
    // the earlier must come after the first cycle (warm-up): 2 cycles + 1 block.
    if (blocks < 2 * kVariantCount + 1)
        throw std::runtime_error("--soak-frames " + std::to_string(options.soakFrames) + ": the soak needs at least " +
                                 std::to_string(2 * kVariantCount + 1) + " blocks of --soak-every " +
                                 std::to_string(every) + " frames (" +
                                 std::to_string((2 * kVariantCount + 1) * every) + " frames)");
    if (options.settings.view.mode != render::ViewMode::Final)
        throw std::runtime_error("--view: the soak cycles its own views; leave --view out");

    scene::Scene scene = loadForOptions(options);
    if (options.addModel.empty()) placeMovingModel(scene, builtinCube(), options.addModelSize, "the built-in cube");
    for (const std::string& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    const LightMover light = lightMover(scene);

    gpu::ContextOptions co;
    co.validation = options.validate;
    co.deviceName = options.device;
    co.printDevice = !options.quiet;
    gpu::Context ctx(co);
    if (!options.quiet)
        std::printf("soak: %u frames, settings change every %u (%u variants), device memory from %s\n",
                    options.soakFrames, every, kVariantCount,
                    ctx.features.memoryBudget ? "VK_EXT_memory_budget and dvsgi's allocations"
                                              : "dvsgi's allocations (no VK_EXT_memory_budget)");

    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<render::Renderer> renderer;
    std::vector<Report> reports;
    std::vector<std::string> seenWarnings;
    uint32_t renderersCreated = 0;
    FrameProgress progress("soak", options.soakFrames, !options.quiet);
    for (uint32_t frame = 0; frame < options.soakFrames; ++frame) {
        const uint32_t block = frame / every, variant = block % kVariantCount;
        if (frame % every == 0) {
            // The old renderer goes first, so its memory is back before the
            // new one asks: what a leak keeps shows up in the next report.
            scene::Scene current = renderer ? renderer->scene() : scene;
            renderer.reset();
            RenderOptions o = options;
            kVariants[variant].apply(o);
            renderer = std::make_unique<render::Renderer>(ctx, current, o.settings);
            ++renderersCreated;
            for (const std::string& w : renderer->warnings())
                if (std::find(seenWarnings.begin(), seenWarnings.end(), w) == seenWarnings.end()) {
                    std::fprintf(stderr, "warning: %s\n", w.c_str());
                    seenWarnings.push_back(w);
                }
        }
        const float t = float(frame) * options.timeStep;
        light.apply(renderer->scene(), t);
        renderer->setTime(t);  // the model's path, then sceneChanged() for both
        renderer->renderFrame();
        progress.done(frame + 1);
        if ((frame + 1) % every != 0 && frame + 1 != options.soakFrames) continue;

        Report r;
        r.frame = frame + 1;
        r.variant = variant;
        r.warmup = block < kVariantCount;
        r.outputMean = meanRgb(renderer->readOutput());
        r.rss = residentBytes();
        r.jitCode = jitCodeBytes();
        r.live = gpu::liveDeviceMemory();
        r.budgetUsage = ctx.deviceMemoryUsage();
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        reports.push_back(r);
        if (!options.quiet)
            std::printf("frame %7u  variant %u  RSS %10s  device %10s in %3llu allocations%s%s\n", r.frame, r.variant,
                        formatBytes(double(r.rss)).c_str(), formatBytes(double(r.live.bytes)).c_str(),
                        (unsigned long long)r.live.allocations, r.budgetUsage >= 0 ? ", budget usage " : "",
                        r.budgetUsage >= 0 ? formatBytes(double(r.budgetUsage)).c_str() : "");
        std::fflush(stdout);
    }
    renderer.reset();
    const gpu::LiveMemory leftOver = gpu::liveDeviceMemory();

    const Report& last = reports.back();
    size_t baseIndex = 0;
    while (reports[baseIndex].warmup || reports[baseIndex].variant != last.variant) ++baseIndex;
    const Report& base = reports[baseIndex];
    const double rssGrowth = growthPercent(double(base.rss), double(last.rss));
    // The driver's JIT code is reported but not judged: on lavapipe it grows by
    // about 0.2 MiB per renderer (docs/RELIABILITY.md), which no dvsgi
    // allocation holds.
    const double ownGrowth =
        growthPercent(double(base.rss - base.jitCode), double(last.rss - last.jitCode));
    const double deviceGrowth = growthPercent(double(base.live.bytes), double(last.live.bytes));
    const bool budgetKnown = base.budgetUsage >= 0 && last.budgetUsage >= 0;
    const double budgetGrowth = budgetKnown ? growthPercent(double(base.budgetUsage), double(last.budgetUsage)) : 0.0;
    const double limit = options.soakMaxGrowth;
    const bool grew = ownGrowth > limit || deviceGrowth > limit || budgetGrowth > limit;

    nlohmann::json j;
    j["device"] = ctx.deviceName;
    j["memory_budget_extension"] = ctx.features.memoryBudget;
    j["scene"] = options.scene.empty() ? "builtin:cornell" : options.scene;
    j["moving_model"] = options.addModel.empty() ? "builtin:cube" : options.addModel;
    j["width"] = options.settings.width;
    j["height"] = options.settings.height;
    j["voxels"] = options.settings.voxels;
    j["shadow_map_size"] = options.settings.shadowMapSize;
    j["validation"] = options.validate;
    j["frames"] = options.soakFrames;
    j["every"] = every;
    for (const Variant& v : kVariants) j["variants"].push_back(v.label);
    j["renderers_created"] = renderersCreated;
    j["seconds"] = last.seconds;
    for (const Report& r : reports) j["reports"].push_back(reportJson(r));
    j["baseline"] = reportJson(base);
    j["last"] = reportJson(last);
    j["growth_percent"] = {{"rss", rssGrowth},
                           {"rss_excluding_jit_code", ownGrowth},
                           {"jit_code_bytes", double(last.jitCode) - double(base.jitCode)},
                           {"device", deviceGrowth},
                           {"device_budget_usage", budgetKnown ? nlohmann::json(budgetGrowth) : nlohmann::json()}};
    j["device_bytes_after_last_renderer"] = leftOver.bytes;
    j["max_growth_percent"] = limit;
    j["validation_errors"] = ctx.validationErrors();
    j["passed"] = !grew && ctx.validationErrors() == 0;
    writeJsonFile(options.soakOut, j, "--soak-out");

    if (!options.quiet)
        std::printf("soak: frames %u..%u (variant %u): RSS %s -> %s (%+.2f %%; %+.2f %% without the driver's JIT code, "
                    "which went %s -> %s), device %s -> %s (%+.2f %%); wrote %s\n",
                    base.frame, last.frame, last.variant, formatBytes(double(base.rss)).c_str(),
                    formatBytes(double(last.rss)).c_str(), rssGrowth, ownGrowth,
                    formatBytes(double(base.jitCode)).c_str(), formatBytes(double(last.jitCode)).c_str(),
                    formatBytes(double(base.live.bytes)).c_str(),
                    formatBytes(double(last.live.bytes)).c_str(), deviceGrowth, options.soakOut.c_str());
    if (ctx.validationErrors() > 0) {
        std::fprintf(stderr, "dvsgi: %u Vulkan validation error(s)\n", ctx.validationErrors());
        return 3;
    }
    if (grew) {
        std::fprintf(stderr,
                     "dvsgi: soak: memory grew beyond --soak-max-growth %g %% between frames %u and %u "
                     "(RSS without the driver's JIT code %+.2f %%, device %+.2f %%)\n",
                     limit, base.frame, last.frame, ownGrowth, deviceGrowth);
        return 4;
    }
    return 0;
}

}  // namespace dvsgi::app
