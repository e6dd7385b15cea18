#include "bench_pv.h"

#include <algorithm>
#include <cstdarg>
#include <iterator>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "bench/hausdorff.h"
#include "json_file.h"
#include "gpu/context.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "render_command.h"
#include "shared/voxel_data.h"
#include "vxgi/voxel_storage_io.h"

namespace dvsgi::app {

namespace {

namespace fs = std::filesystem;

double median(std::vector<double> v) {
    if (v.empty()) return -1.0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

double passesMs(const std::vector<gpu::TimerResult>& passes, const std::vector<std::string>& names) {
    double ms = 0.0;
    for (const gpu::TimerResult& r : passes)
        if (names.empty() || std::find(names.begin(), names.end(), r.name) != names.end()) ms += r.ms;
    return ms;
}

// Voxel passes only: the image is a cheap voxel view, no bounces, no history.
render::RenderSettings voxelOnly(const RenderOptions& o, uint32_t n, vxgi::VoxelizerKind kind) {
    render::RenderSettings s = o.settings;
    s.voxels = n;
    s.voxelizer = kind;
    s.view.mode = render::ViewMode::VoxelAlbedo;
    s.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    s.voxelLight.bounces = 0;
    s.temporal.enabled = false;
    return s;
}

// Table 6.1: static voxelization (clear included) of the geometric voxelizers,
// timed in its own submission, against pv's passes in a frame of a fixed
// camera (after two warm-up frames), and the G-buffer the frame renders.
nlohmann::json timeVoxelizers(const gpu::Context& ctx, const scene::Scene& scene, const RenderOptions& o, uint32_t n,
                              int reps) {
    nlohmann::json row;
    for (vxgi::VoxelizerKind kind : {vxgi::VoxelizerKind::Geometry, vxgi::VoxelizerKind::Compute}) {
        render::Renderer r(ctx, scene, voxelOnly(o, n, kind));
        r.renderFrame();
        std::vector<double> ms;
        for (int i = 0; i < reps; ++i) ms.push_back(passesMs(r.revoxelizeStatic(), {}));
        row[vxgi::voxelizerName(kind)] = median(ms);
        row["triangles"] = r.triangleCount();
    }
    render::Renderer r(ctx, scene, voxelOnly(o, n, vxgi::VoxelizerKind::Pv));
    for (int i = 0; i < 2; ++i) r.renderFrame();
    std::vector<double> pv, gbuffer;
    for (int i = 0; i < reps; ++i) {
        const render::FrameStats st = r.renderFrame();
        pv.push_back(passesMs(st.passes, {"pv rsm", "pv cleanup", "pv inject", "pv inject rsm"}));
        gbuffer.push_back(passesMs(st.passes, {"gbuffer"}));
    }
    row["pv"] = median(pv);
    row["gbuffer"] = median(gbuffer);
    return row;
}

std::vector<glm::dvec3> voxelCentres(const gpu::Context& ctx, const vxgi::VoxelVolumes& v) {
    const std::vector<uint32_t> index = vxgi::readVoxelIndex(ctx, v);
    const uint32_t n = v.grid.n;
    std::vector<glm::dvec3> out;
    for (size_t i = 0; i < index.size(); ++i)
        if (shader::indexSlot(index[i]) != 0)
            out.push_back(glm::dvec3(v.grid.origin) +
                          (glm::dvec3(double(i % n), double(i / n % n), double(i / (size_t(n) * n))) + 0.5) *
                              double(v.grid.voxelSize));
    return out;
}

// Once around each principal axis through the scene's centre, `perAxis`
// views per orbit, at 2.5 bounding radii.
scene::CameraPath orbits(const scene::Scene& s, int perAxis) {
    const scene::Bounds b = scene::worldBounds(s, scene::drawItems(s, scene::worldMatrices(s)));
    const glm::vec3 centre = 0.5f * (b.min + b.max);
    const float radius = 0.5f * glm::length(b.max - b.min);
    scene::CameraPath path;
    path.catmullRom = false;
    path.source = "pv orbits";
    for (int axis = 0; axis < 3; ++axis)
        for (int k = 0; k < perAxis; ++k) {
            const float a = 2.0f * glm::pi<float>() * float(k) / float(perAxis);
            const float c = std::cos(a), si = std::sin(a);
            // Around X: the yz plane; around Y: zx; around Z: xy.
            const glm::vec3 dir = axis == 0 ? glm::vec3(0, si, c) : axis == 1 ? glm::vec3(si, 0, c) : glm::vec3(c, si, 0);
            glm::vec3 up(0.0f);
            up[axis] = 1.0f;
            scene::CameraKey key;
            key.time = float(axis * perAxis + k);
            key.position = centre + 2.5f * radius * dir;
            key.orientation = glm::quatLookAt(-dir, up);
            key.yfov = 2.0f * std::atan(1.1f / 2.5f);
            path.keys.push_back(key);
        }
    return path;
}

// Table 6.2: average Hausdorff distance (% of the bounding-box diagonal) of
// pv after the orbits, per frame, against the exact geometric voxelizer's.
nlohmann::json measureAccuracy(const gpu::Context& ctx, const scene::Scene& scene, const RenderOptions& o, uint32_t n,
                               int perAxis, size_t samples) {
    const scene::Bounds b = scene::worldBounds(scene, scene::drawItems(scene, scene::worldMatrices(scene)));
    const double diagonal = glm::length(glm::dvec3(b.max - b.min));
    const std::vector<glm::dvec3> surface = bench::surfaceSamples(scene, samples);
    render::Renderer exact(ctx, scene, voxelOnly(o, n, vxgi::VoxelizerKind::Compute));
    exact.renderFrame();
    const std::vector<glm::dvec3> reference = voxelCentres(ctx, *exact.volumes());
    const double exactDistance = 100.0 * bench::averageHausdorff(surface, reference).average() / diagonal;

    render::Renderer pv(ctx, scene, voxelOnly(o, n, vxgi::VoxelizerKind::Pv));
    const scene::CameraPath path = orbits(scene, perAxis);
    pv.setCameraPath(path);
    nlohmann::json perFrame = nlohmann::json::array();
    std::vector<glm::dvec3> centres;
    for (const scene::CameraKey& key : path.keys) {
        pv.setTime(key.time);
        pv.renderFrame();
        centres = voxelCentres(ctx, *pv.volumes());
        perFrame.push_back(100.0 * bench::averageHausdorff(surface, centres).average() / diagonal);
    }
    // Of the exact voxelizer's voxels, how many pv holds at the end.
    std::vector<uint8_t> mask(size_t(n) * n * n, 0);
    const vxgi::GridSpec& g = pv.volumes()->grid;
    auto at = [&](const glm::dvec3& c) {
        const glm::ivec3 v = glm::ivec3(glm::floor((c - glm::dvec3(g.origin)) / double(g.voxelSize)));
        return (size_t(v.z) * n + size_t(v.y)) * n + size_t(v.x);
    };
    for (const glm::dvec3& c : centres) mask[at(c)] = 1;
    size_t found = 0;
    for (const glm::dvec3& c : reference) found += mask[at(c)];
    return {{"pv", perFrame.back()},
            {"geometric", exactDistance},
            {"pv_per_frame", perFrame},
            {"pv_voxels", centres.size()},
            {"geometric_voxels", reference.size()},
            {"geometric_found_percent", reference.empty() ? 0.0 : 100.0 * double(found) / double(reference.size())}};
}

// Everything the tables print goes to stdout and, for --pv-doc, into this.
std::string g_markdown;

void emit(const char* format, ...) __attribute__((format(printf, 1, 2)));
void emit(const char* format, ...) {
    char line[2048];
    va_list args;
    va_start(args, format);
    std::vsnprintf(line, sizeof line, format, args);
    va_end(args);
    std::fputs(line, stdout);
    std::fflush(stdout);
    g_markdown += line;
}

constexpr const char* kDocBegin = "<!-- pv-tables: begin -->";
constexpr const char* kDocEnd = "<!-- pv-tables: end -->";

// The text of `file` and where its markers lie; throws naming the file.
std::string readDoc(const std::string& file, size_t& begin, size_t& end) {
    std::ifstream in(file);
    if (!in) throw image::IoError("--pv-doc: " + file + ": cannot open");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    begin = text.find(kDocBegin);
    end = text.find(kDocEnd);
    if (begin == std::string::npos || end == std::string::npos || end < begin)
        throw image::IoError("--pv-doc: " + file + " lacks the lines '" + kDocBegin + "' and '" + kDocEnd + "'");
    return text;
}

// Replaces the lines between the markers of `file` with the tables.
void writeIntoDoc(const std::string& file, const std::string& tables) {
    size_t begin = 0, end = 0;
    const std::string text = readDoc(file, begin, end);
    const size_t from = text.find('\n', begin);
    const std::string out = text.substr(0, from + 1) + "\n" + tables + "\n" + text.substr(end);
    std::ofstream f(file);
    if (!(f << out)) throw image::IoError("--pv-doc: " + file + ": write failed");
}

}  // namespace

int runPvTables(const RenderOptions& options) {
    RenderOptions o = options;
    if (!o.pvDoc.empty()) {
        size_t begin = 0, end = 0;
        readDoc(o.pvDoc, begin, end);  // a bad file fails now, not after the measurements
    }
    if (!o.isGiven("width")) o.settings.width = 512;
    if (!o.isGiven("height")) o.settings.height = 512;
    const fs::path scenes = fs::path(o.sharedDir) / "scenes";
    struct Model {
        std::string name;
        fs::path file;
    };
    const std::vector<Model> timed = {{"conference", scenes / "conference-room-geometry-only/conference.obj"},
                                      {"dragon", scenes / "stanford-dragon/dragon.obj"},
                                      {"sponza", scenes / "crytek-sponza/sponza-sun.gltf"}};
    const std::vector<Model> measured = {{"bunny", scenes / "stanford-bunny/bun_zipper.ply"},
                                         {"dragon", scenes / "stanford-dragon/dragon.obj"},
                                         {"buddha", scenes / "stanford-buddha/buddha.obj"}};
    // 512^3 where the device can hold it (lavapipe's 128 MiB storage-buffer
    // range cannot take its slot index): a row that says why otherwise.
    const std::vector<uint32_t> timedSizes =
        o.isGiven("bench-voxels") ? o.benchVoxels : std::vector<uint32_t>{128, 256, 512};
    const std::vector<uint32_t> measuredSizes =
        o.isGiven("bench-voxels") ? o.benchVoxels : std::vector<uint32_t>{64, 128, 256};
    constexpr int kReps = 3, kPerAxis = 12;
    constexpr size_t kSamples = 200000;

    gpu::ContextOptions co;
    co.validation = o.validate;
    co.deviceName = o.device;
    gpu::Context ctx(co);
    nlohmann::json out;
    out["tool"] = "dvsgi bench --pv-tables";
    out["device"] = ctx.deviceName;
    out["image"] = {o.settings.width, o.settings.height};
    out["command_line"] = o.commandLine;
    size_t measuredRows = 0;
    // A model that is missing (a GPU bundle carries only some) gets rows that
    // say so instead of stopping the run.
    auto load = [&](const fs::path& file, std::string& missing) {
        missing.clear();
        if (!fs::exists(file)) {
            missing = file.string() + ": file not found";
            std::fprintf(stderr, "warning: --pv-tables: %s\n", missing.c_str());
            return scene::Scene{};
        }
        RenderOptions so = o;
        so.scene = file.string();
        so.addModel.clear();
        return loadForOptions(so);
    };
    std::string missing;

    emit("Table 6.1 (%s, %ux%u): voxelization, ms (geometric: static voxelization with its clear, "
                "median of %d; pv: its passes in a frame, and the G-buffer the frame renders)\n\n",
                ctx.deviceName.c_str(), o.settings.width, o.settings.height, kReps);
    emit("| scene | voxels | triangles | geometry | compute | pv | pv + G-buffer | pv / geometry |\n");
    emit("|---|---|---|---|---|---|---|---|\n");
    for (const Model& m : timed) {
        const scene::Scene s = load(m.file, missing);
        for (uint32_t n : timedSizes) {
            std::fprintf(stderr, "timing %s at %u^3 ...\n", m.name.c_str(), n);
            nlohmann::json row;
            try {
                if (!missing.empty()) throw std::runtime_error(missing);
                row = timeVoxelizers(ctx, s, o, n, kReps);
            } catch (const std::exception& e) {
                emit("| %s | %u³ | – | not measured: %s |||||\n", m.name.c_str(), n, e.what());
                out["table_6_1"].push_back({{"scene", m.name}, {"voxels", n}, {"error", e.what()}});
                continue;
            }
            ++measuredRows;
            row["scene"] = m.name;
            row["voxels"] = n;
            const double geometry = row["geometry"], compute = row["compute"], pv = row["pv"], gb = row["gbuffer"];
            emit("| %s | %u³ | %llu | %.1f | %.1f | %.2f | %.1f | %.1f %% |\n", m.name.c_str(), n,
                        (unsigned long long)row["triangles"].get<uint64_t>(), geometry, compute, pv, pv + gb,
                        100.0 * pv / geometry);
            std::fflush(stdout);
            out["table_6_1"].push_back(row);
        }
    }
    emit("\nTable 6.2 (%s, %ux%u): average Hausdorff distance, %% of the bounding-box diagonal, after "
                "orbiting once around each principal axis (%d views per orbit; %zu surface samples)\n\n",
                ctx.deviceName.c_str(), o.settings.width, o.settings.height, kPerAxis, kSamples);
    emit("| model | voxels | pv | geometric (exact) | pv / geometric | geometric voxels pv holds |\n");
    emit("|---|---|---|---|---|---|\n");
    for (const Model& m : measured) {
        const scene::Scene s = load(m.file, missing);
        for (uint32_t n : measuredSizes) {
            std::fprintf(stderr, "orbiting %s at %u^3 ...\n", m.name.c_str(), n);
            nlohmann::json row;
            try {
                if (!missing.empty()) throw std::runtime_error(missing);
                row = measureAccuracy(ctx, s, o, n, kPerAxis, kSamples);
            } catch (const std::exception& e) {
                emit("| %s | %u³ | not measured: %s ||||\n", m.name.c_str(), n, e.what());
                out["table_6_2"].push_back({{"model", m.name}, {"voxels", n}, {"error", e.what()}});
                continue;
            }
            ++measuredRows;
            row["model"] = m.name;
            row["voxels"] = n;
            const double pv = row["pv"], geometric = row["geometric"], found = row["geometric_found_percent"];
            emit("| %s | %u³ | %.3f | %.3f | %.2f | %.2f %% |\n", m.name.c_str(), n, pv, geometric,
                        pv / geometric, found);
            std::fflush(stdout);
            out["table_6_2"].push_back(row);
        }
    }
    out["validation_errors"] = ctx.validationErrors();
    writeJsonFile(o.benchOut, out);
    std::printf("\nwrote %s\n", o.benchOut.c_str());
    if (!o.pvDoc.empty()) {
        writeIntoDoc(o.pvDoc, g_markdown);
        std::printf("wrote the tables into %s\n", o.pvDoc.c_str());
    }
    if (ctx.validationErrors() > 0) {
        std::fprintf(stderr, "dvsgi: %u Vulkan validation error(s)\n", ctx.validationErrors());
        return 3;
    }
    if (measuredRows == 0) {
        std::fprintf(stderr, "dvsgi: bench --pv-tables: no measurement succeeded\n");
        return 1;
    }
    return 0;
}

}  // namespace dvsgi::app
