#include "render_command.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "gpu/context.h"
#include "image/image_io.h"
#include "json_file.h"
#include "progress.h"
#include "render/renderer.h"
#include "scene/load.h"
#include "settings_table.h"
#include "shared/composite_pass.h"
#include "voxel_dump.h"
#include "vxgi/volumes.h"
#include "vxgi/voxelize.h"

namespace dvsgi::app {

namespace {

std::string pngPathFor(const std::string& exr, const RenderOptions& o) {
    if (o.outPng == "none") return "";
    if (!o.outPng.empty() && o.frames == 1) return o.outPng;
    return std::filesystem::path(exr).replace_extension(".png").string();
}

// "f_###.exr" with frame 7 -> "f_007.exr". No '#': the name itself.
std::string framePath(const std::string& pattern, uint32_t frame) {
    const size_t first = pattern.find('#');
    if (first == std::string::npos) return pattern;
    size_t last = first;
    while (last < pattern.size() && pattern[last] == '#') ++last;
    std::string number = std::to_string(frame);
    if (number.size() < last - first) number.insert(0, last - first - number.size(), '0');
    return pattern.substr(0, first) + number + pattern.substr(last);
}

void markDynamic(scene::Scene& s, const std::vector<std::string>& names) {
    for (const std::string& name : names) {
        bool found = false;
        for (scene::Node& n : s.nodes)
            if (n.name == name) n.dynamic = found = true;
        if (!found) throw std::runtime_error("--dynamic: the scene has no node named '" + name + "'");
    }
}

// Loads `path` and places it as the moving model (placeMovingModel).
void addMovingModel(scene::Scene& s, const std::string& path, float size, bool allowOutside) {
    scene::LoadOptions lo;
    lo.allowOutsideReferences = allowOutside;
    placeMovingModel(s, scene::loadScene(path, lo), size, path);
}

void printTable(const render::FrameStats& stats, const std::vector<render::MemoryItem>& memory) {
    std::printf("%-24s %10s\n", "pass", "GPU ms");
    for (const gpu::TimerResult& r : stats.passes) std::printf("%-24s %10.3f\n", r.name.c_str(), r.ms);
    std::printf("%-24s %10.3f\n", "frame total", stats.gpuMs);
    uint64_t total = 0;
    for (const render::MemoryItem& m : memory) total += m.bytes;
    std::printf("GPU memory: %.1f MiB\n", double(total) / (1024.0 * 1024.0));
}

void printVoxelGrid(const render::Renderer& renderer) {
    const vxgi::VoxelVolumes& v = *renderer.volumes();
    const vxgi::Voxelizer& voxelizer = *renderer.voxelizer();
    const vxgi::GridSpec& g = v.grid;
    const char* how = voxelizer.kind() == vxgi::VoxelizerKind::Compute ? "compute voxelizer (exact)"
                      : voxelizer.kind() == vxgi::VoxelizerKind::Pv    ? "progressive screen-space voxelization"
                      : voxelizer.hardwareConservative()               ? "hardware conservative rasterization"
                                                                       : "geometry-shader conservative rasterization";
    std::printf("voxel grid: %u^3, origin (%.4f, %.4f, %.4f) m, voxel %.5f m, %s, %u voxel slots\n", g.n,
                g.origin.x, g.origin.y, g.origin.z, g.voxelSize, how, v.slots);
    uint64_t total = 0;
    for (const vxgi::VolumeMemory& m : vxgi::volumeMemory(g.n, v.slots, renderer.bounceRays(), renderer.gatherRays())) {
        std::printf("  %-40s %-20s %9.1f MiB\n", m.name.c_str(), m.format.c_str(), double(m.bytes) / 1048576.0);
        total += m.bytes;
    }
    std::printf("  %-61s %9.1f MiB = %.1f bytes per grid voxel\n", "all voxel data", double(total) / 1048576.0,
                renderer.voxelBytesPerGridVoxel());
}

glm::dvec3 meanRgb(const image::ImageRGBA32F& img) {
    glm::dvec3 sum(0.0);
    for (size_t i = 0; i + 3 < img.rgba.size(); i += 4) sum += glm::dvec3(img.rgba[i], img.rgba[i + 1], img.rgba[i + 2]);
    const double n = std::max<double>(1.0, double(img.rgba.size() / 4));
    return sum / n;
}

nlohmann::json metricsJson(const RenderOptions& o, const gpu::Context& ctx, const render::Renderer& renderer,
                           const render::FrameStats& stats, const render::FrameStats& first,
                           const scene::Scene& scene) {
    nlohmann::json j;
    j["scene"] = scene.source;
    j["device"] = ctx.deviceName;
    j["triangles"] = renderer.triangleCount();
    j["lights"] = scene.lights.size();
    j["gpu_ms"] = stats.gpuMs;
    j["emitter_patches"] = renderer.emitterPatchCount();
    // The first frame is the one that converges (--bounces auto); later ones feed back.
    j["bounces"] = {{"first_frame", first.bounces},
                    {"first_frame_change", first.bounceChange},
                    {"converged", first.converged},
                    {"last_frame", stats.bounces}};
    for (const gpu::TimerResult& r : stats.passes) j["passes"].push_back({{"name", r.name}, {"ms", r.ms}});
    for (const render::MemoryItem& m : renderer.memory()) j["memory_bytes"][m.name] = m.bytes;
    if (const vxgi::VoxelVolumes* v = renderer.volumes()) {
        j["voxels"] = {{"n", v->grid.n},
                       {"origin", {v->grid.origin.x, v->grid.origin.y, v->grid.origin.z}},
                       {"voxel_size", v->grid.voxelSize},
                       {"slots", v->slots},
                       {"bytes_per_grid_voxel", renderer.voxelBytesPerGridVoxel()}};
    }
    j["settings"] = settingsJson(o, kRender);
    j["validation_errors"] = ctx.validationErrors();
    return j;
}

// One term of the frame for --aov: a layer name, its channels and the image
// holding them in its first channels.
struct AovTerm {
    const char* name;
    std::vector<std::string> channels;
    image::ImageRGBA32F image;
};

// Every term of the frame. The radiance terms come from re-running the
// composite, so each equals what `--output <term>` writes.
std::vector<AovTerm> readAov(const render::Renderer& renderer) {
    render::Renderer::SurfaceImages surface = renderer.readSurface();
    std::vector<AovTerm> terms;
    terms.push_back({"direct", {"R", "G", "B"}, renderer.readTerm(shader::TERM_DIRECT)});
    terms.push_back({"indirect", {"R", "G", "B"}, renderer.readTerm(shader::TERM_INDIRECT)});
    terms.push_back({"specular", {"R", "G", "B"}, renderer.readTerm(shader::TERM_SPECULAR)});
    terms.push_back({"ao", {"Y"}, renderer.readTerm(shader::TERM_AO)});
    terms.push_back({"albedo", {"R", "G", "B"}, std::move(surface.albedo)});
    terms.push_back({"normal", {"X", "Y", "Z"}, std::move(surface.normal)});
    terms.push_back({"depth", {"Z"}, std::move(surface.depth)});
    return terms;
}

// The terms as named layers of one EXR (channel naming of image::ExrLayer).
void writeAov(const std::string& path, const std::vector<AovTerm>& terms, image::PixelType type) {
    std::vector<image::ExrLayer> layers;
    for (const AovTerm& t : terms) {
        image::ExrLayer l{t.name, t.channels, {}};
        const size_t n = l.channels.size(), pixels = t.image.pixelCount();
        l.pixels.resize(pixels * n);
        for (size_t p = 0; p < pixels; ++p)
            for (size_t c = 0; c < n; ++c) l.pixels[p * n + c] = t.image.rgba[p * 4 + c];
        layers.push_back(std::move(l));
    }
    image::writeExrLayers(path, terms.front().image.width, terms.front().image.height, layers, type);
}

// Where render k of --grid-samples puts the grid, in voxels along each axis
// from the fitted one: none for the first, then the R3 sequence (steps of the
// inverse powers of the plastic number, g^4 = g + 1), which spreads any
// number of points evenly over the cube of offsets.
glm::vec3 gridSampleOffset(uint32_t k) {
    constexpr double g = 1.2207440846057594754;
    const glm::dvec3 step(1.0 / g, 1.0 / (g * g), 1.0 / (g * g * g));
    return glm::vec3(glm::fract(double(k) * step));
}

// --grid-samples moves one fitted grid under one still frame.
void checkGridSamples(const RenderOptions& o) {
    if (o.gridSamples <= 1) return;
    const char* why = nullptr;
    if (o.settings.voxels == 0) why = "--voxels 0 has no grid to move";
    else if (o.frames > 1) why = "it renders one frame, not --frames";
    else if (!o.cameraPath.empty()) why = "it renders one frame, not a --camera-path";
    else if (o.settings.clipmap.levels > 0) why = "--clipmap's grid follows the camera";
    else if (o.settings.voxelizer == vxgi::VoxelizerKind::Pv) why = "--voxelizer pv keeps voxels from frame to frame";
    else if (o.settings.view.mode != render::ViewMode::Final) why = "--view voxels:... draws one grid";
    if (why) throw std::runtime_error(std::string("--grid-samples: ") + why);
}

void addInto(image::ImageRGBA32F& sum, const image::ImageRGBA32F& img) {
    for (size_t i = 0; i < sum.rgba.size(); ++i) sum.rgba[i] += img.rgba[i];
}

// Renders 1..K-1 of --grid-samples, each by a renderer of its own on `fitted`
// moved by gridSampleOffset(k), added to `img` and `aov` (render 0's), which
// then hold the mean. Returns the offsets, render 0's first.
std::vector<glm::vec3> averageGridSamples(gpu::Context& ctx, const scene::Scene& scene, const RenderOptions& o,
                                          const vxgi::GridSpec& fitted, image::ImageRGBA32F& img,
                                          std::vector<AovTerm>& aov) {
    std::vector<glm::vec3> offsets = {gridSampleOffset(0)};
    for (uint32_t k = 1; k < o.gridSamples; ++k) {
        offsets.push_back(gridSampleOffset(k));
        render::RenderSettings s = o.settings;
        s.hasVoxelBox = true;
        s.voxelBoxMin = fitted.origin + offsets.back() * fitted.voxelSize;
        s.voxelBoxMax = s.voxelBoxMin + glm::vec3(float(fitted.n) * fitted.voxelSize);
        render::Renderer r(ctx, scene, s);
        r.renderFrame();
        addInto(img, r.readOutput());
        if (!aov.empty()) {
            const std::vector<AovTerm> more = readAov(r);
            for (size_t t = 0; t < aov.size(); ++t) addInto(aov[t].image, more[t].image);
        }
    }
    const float scale = 1.0f / float(o.gridSamples);
    for (float& v : img.rgba) v *= scale;
    for (AovTerm& t : aov)
        for (float& v : t.image.rgba) v *= scale;
    return offsets;
}


}  // namespace

// Scales `model` to `size` metres (0: 1/5 of the scene) and sends it round a
// circle on the floor of the scene's bounds as a dynamic object.
void placeMovingModel(scene::Scene& s, const scene::Scene& model, float size, const std::string& label) {
    const scene::Bounds sb = scene::worldBounds(s, scene::drawItems(s, scene::worldMatrices(s)));
    const scene::Bounds mb = scene::worldBounds(model, scene::drawItems(model, scene::worldMatrices(model)));
    if (!sb.valid() || !mb.valid()) throw std::runtime_error("--add-model: " + label + " or the scene has no geometry");
    const glm::vec3 se = sb.max - sb.min, me = mb.max - mb.min;
    const float target = size > 0.0f ? size : 0.2f * std::max({se.x, se.y, se.z});
    const float scale = target / std::max({me.x, me.y, me.z, 1e-9f});
    const int fit = scene::appendScene(s, model, "added model");
    // Bottom centre of the model at the mover's origin.
    s.nodes[size_t(fit)].scale = glm::vec3(scale);
    s.nodes[size_t(fit)].translation = -scale * glm::vec3((mb.min.x + mb.max.x) * 0.5f, mb.min.y,
                                                          (mb.min.z + mb.max.z) * 0.5f);
    scene::Node mover;
    mover.name = "added model path";
    mover.children = {fit};
    s.nodes.push_back(mover);
    const int moverIndex = int(s.nodes.size() - 1);
    s.nodes[size_t(fit)].parent = moverIndex;
    s.roots.erase(std::remove(s.roots.begin(), s.roots.end(), fit), s.roots.end());
    s.roots.push_back(moverIndex);
    const glm::vec3 centre((sb.min.x + sb.max.x) * 0.5f, sb.min.y, (sb.min.z + sb.max.z) * 0.5f);
    const float radius = 0.25f * std::min(se.x, se.z);
    scene::addCircularPath(s, moverIndex, centre, radius, 4.0f);
}

scene::Scene loadForOptions(const RenderOptions& o) {
    scene::LoadOptions lo;
    lo.allowOutsideReferences = o.allowOutsideReferences;
    scene::Scene scene = o.scene.empty() ? scene::builtinCornellBox() : scene::loadScene(o.scene, lo);
    markDynamic(scene, o.dynamicNodes);
    if (!o.addModel.empty()) addMovingModel(scene, o.addModel, o.addModelSize, o.allowOutsideReferences);
    return scene;
}

std::optional<scene::CameraPath> cameraPathFor(const RenderOptions& o) {
    if (o.cameraPath.empty()) return std::nullopt;
    return scene::loadCameraPath(o.cameraPath);
}

// A --metrics path whose folder cannot be made fails before anything is
// rendered or written, naming the option and the path.
void checkMetricsPath(const std::string& path) {
    if (path.empty()) return;
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty()) std::filesystem::create_directories(parent, ec);
    if (ec || (!parent.empty() && !std::filesystem::is_directory(parent)))
        throw image::IoError("--metrics: cannot create the folder of " + path + ": " +
                             (ec ? ec.message() : "not a directory"));
}

// --voxel-dump writes the one fitted grid of one render.
void checkVoxelDump(const RenderOptions& o) {
    if (o.voxelDump.empty()) return;
    if (o.settings.voxels == 0) throw std::runtime_error("--voxel-dump: there are no voxels with --voxels 0");
    if (o.settings.clipmap.levels > 0)
        throw std::runtime_error("--voxel-dump: writes the fitted grid's voxels, not --clipmap levels");
    if (o.gridSamples > 1)
        throw std::runtime_error("--voxel-dump: writes one render's voxels, not the --grid-samples mean");
}

int runRender(const RenderOptions& o) {
    checkMetricsPath(o.metricsPath);
    checkGridSamples(o);
    checkVoxelDump(o);
    if (!o.aovExr.empty() && o.settings.view.mode != render::ViewMode::Final)
        throw std::runtime_error("--aov: the terms exist only for the final image, not for --view voxels:...");
    const scene::Scene scene = loadForOptions(o);
    for (const std::string& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    std::optional<scene::CameraPath> path = cameraPathFor(o);

    gpu::ContextOptions co;
    co.validation = o.validate;
    co.deviceName = o.device;
    co.printDevice = !o.quiet;
    gpu::Context ctx(co);

    render::Renderer renderer(ctx, scene, o.settings);
    for (const std::string& w : renderer.warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
    const bool moving = o.frames > 1 || !scene.animations.empty() || path;
    if (path) renderer.setCameraPath(std::move(path));
    if (!o.quiet && renderer.volumes()) {
        printVoxelGrid(renderer);
        const std::vector<const vxgi::VoxelVolumes*> levels = renderer.levelVolumes();
        if (o.settings.clipmap.levels > 0)
            std::printf("voxel clipmap: %zu levels of %u^3 following the camera (the grid above is level 0's, its "
                        "window placed each frame), voxels %.5f m to %.5f m, windows %.3f m to %.3f m wide, "
                        "%.1f MiB of voxel data in all (atlases included)\n",
                        levels.size(), levels[0]->grid.n, levels.front()->grid.voxelSize,
                        levels.back()->grid.voxelSize, levels.front()->grid.voxelSize * float(levels[0]->grid.n),
                        levels.back()->grid.voxelSize * float(levels[0]->grid.n),
                        [&] {
                            // Levels 1.. share one set of dense volumes: counted once.
                            double bytes = 0.0;
                            for (const vxgi::VoxelVolumes* v : levels) bytes += double(v->ownBytes());
                            if (levels.size() > 2) bytes += double(levels[1]->dense()->bytes());
                            if (const vxgi::ClipAtlases* a = renderer.clipAtlases()) bytes += double(a->bytes());
                            return bytes / 1048576.0;
                        }());
    }
    const uint32_t slots = renderer.volumes() ? renderer.volumes()->slots : 0;

    const bool eachFrame = o.outExr.find('#') != std::string::npos;
    render::FrameStats stats, first;
    glm::dvec3 outputMean(0.0);
    std::string lastExr, lastPng;
    std::vector<glm::vec3> gridOffsets;
    FrameProgress progress("", o.frames, !o.quiet);
    for (uint32_t frame = 0; frame < o.frames; ++frame) {
        if (moving) renderer.setTime(float(frame) * o.timeStep);
        stats = renderer.renderFrame();
        progress.done(frame + 1);
        if (frame == 0) {
            first = stats;
            if (stats.bounceChange >= 0.0 && !o.quiet)
                std::printf("voxel bounces: %u, last relative change %.5f%s\n", stats.bounces, stats.bounceChange,
                            stats.converged ? "" : " (not converged)");
            if (stats.bounceChange >= 0.0 && !stats.converged)
                std::fprintf(stderr, "warning: --bounces auto: still changing by %.4f after --max-bounces %u\n",
                             stats.bounceChange, o.settings.voxelLight.maxBounces);
        }
        if (!eachFrame && frame + 1 < o.frames) continue;
        image::ImageRGBA32F img = renderer.readOutput();
        std::vector<AovTerm> aov;
        if (!o.aovExr.empty()) aov = readAov(renderer);
        if (o.gridSamples > 1) {
            gridOffsets = averageGridSamples(ctx, scene, o, renderer.volumes()->grid, img, aov);
            if (!o.quiet)
                std::printf("grid samples: the mean of %u renders, the grid moved by up to a voxel\n", o.gridSamples);
        }
        outputMean = meanRgb(img);
        lastExr = framePath(o.outExr, frame);
        image::ExrOptions exr;
        exr.type = o.exrHalf ? image::PixelType::Half : image::PixelType::Float;
        image::writeExr(lastExr, img, exr);
        if (!aov.empty()) writeAov(framePath(o.aovExr, frame), aov, exr.type);
        lastPng = pngPathFor(lastExr, o);
        if (!lastPng.empty()) image::writePng(lastPng, img, o.exposure);
    }
    if (!o.voxelDump.empty()) writeVoxelDump(o.voxelDump, ctx, *renderer.volumes());
    if (!o.quiet && renderer.volumes() && renderer.volumes()->slots != slots)
        std::printf("voxel slots grew from %u to %u (more occupied voxels): %.1f bytes per grid voxel\n", slots,
                    renderer.volumes()->slots, renderer.voxelBytesPerGridVoxel());
    if (!o.metricsPath.empty()) {
        nlohmann::json j = metricsJson(o, ctx, renderer, stats, first, scene);
        // Mean radiance of the last image written, so scripts can compare runs
        // (for example across voxel resolutions) without reading the EXR.
        j["output_mean_rgb"] = {outputMean.r, outputMean.g, outputMean.b};
        j["output_mean_luminance"] = 0.2126 * outputMean.r + 0.7152 * outputMean.g + 0.0722 * outputMean.b;
        // The timings above are render 0's (the fitted grid).
        for (const glm::vec3& d : gridOffsets) j["grid_sample_offsets"].push_back({d.x, d.y, d.z});
        writeJsonFile(o.metricsPath, j);
    }
    if (!o.quiet) {
        printTable(stats, renderer.memory());
        std::printf("wrote %s%s%s\n", lastExr.c_str(), lastPng.empty() ? "" : " and ", lastPng.c_str());
    }
    if (ctx.validationErrors() > 0) {
        std::fprintf(stderr, "dvsgi: %u Vulkan validation error(s)\n", ctx.validationErrors());
        return 3;
    }
    return 0;
}

}  // namespace dvsgi::app
