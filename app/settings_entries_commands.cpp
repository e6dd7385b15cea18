// The settings table's entries after the voxel light, in --help order: cone
// tracing and composition, animation and dynamic objects, and the viewer's,
// the bench's and the soak's own settings (settings_entries.cpp has the rest).
#include "settings_entries.h"

namespace dvsgi::app::entries {

using namespace table;

namespace {

// --dynamic NAME, repeatable.
Setting dynamicNodes() {
    Setting s = base({"dynamic", kAnimation, "NAME", "",
                      "mark the node NAME dynamic; animated nodes are dynamic already. Dynamic "
                      "geometry is re-voxelized every frame",
                      kAll, Apply::Startup},
                     Kind::Special);
    s.repeatable = true;
    s.example = "node";
    s.unset = "none";
    s.parse = [](RenderOptions& o, std::string_view v) {
        o.dynamicNodes.emplace_back(v);
        return true;
    };
    s.text = [](const RenderOptions& o) {
        std::string t;
        for (const std::string& n : o.dynamicNodes) t += (t.empty() ? "" : ",") + n;
        return t;
    };
    s.json = [](const RenderOptions& o) { return nlohmann::json(o.dynamicNodes); };
    return s;
}

// --bench-voxels 128,256.
Setting benchVoxels() {
    Setting s = base({"bench-voxels", kBenchGroup, "LIST", "voxels", "voxel resolutions to measure, e.g. 128,256", kBench,
                      Apply::Startup},
                     Kind::Special);
    s.expected = "a comma-separated list of powers of two in 32..512";
    s.example = "32,64";
    s.parse = [](RenderOptions& o, std::string_view v) {
        std::vector<uint32_t> list;
        std::string_view rest = v;
        while (true) {
            const size_t comma = rest.find(',');
            const std::optional<uint64_t> n = parseUnsigned(rest.substr(0, comma));
            if (!n || *n < 32 || *n > 512 || (*n & (*n - 1)) != 0) return false;
            list.push_back(uint32_t(*n));
            if (comma == std::string_view::npos) break;
            rest = rest.substr(comma + 1);
        }
        o.benchVoxels = list;
        return true;
    };
    s.text = [](const RenderOptions& o) {
        std::string t;
        for (uint32_t n : o.benchVoxels) t += (t.empty() ? "" : ",") + std::to_string(n);
        return t;
    };
    s.json = [](const RenderOptions& o) { return nlohmann::json(o.benchVoxels); };
    return s;
}

}  // namespace

// Cone tracing, animation, and the viewer's and the bench's own settings.
std::vector<Setting> conesAndCommands() {
    return {
        // Cone tracing and composition.
        with(choice({"cones", kCones, "6|16", "",
                     "diffuse cone set: the paper's six 60-degree cones or sixteen equal-solid-angle cones; "
                     "cosine-weighted and normalized so a uniform radiance L gives irradiance pi*L",
                     kAll, kFrame},
                    {{"6", 6u}, {"16", 16u}}, FIELD(settings.cones.coneSet)),
             "16"),
        with(choice({"gather-trace", kCones, "cones|rays", "",
                     "how each pixel gathers its indirect diffuse light: cones = the --cones set through the "
                     "filtered volumes (the paper); rays = --gather-rays cosine rays marched voxel by voxel "
                     "through the radiance volume (a fitted grid's; --clipmap levels and --voxelizer pv trace "
                     "cones); specular keeps its cone",
                     kAll, kFrame},
                    {{"cones", render::GatherTrace::Cones}, {"rays", render::GatherTrace::Rays}}, FIELD(settings.gather.trace)),
             "cones", "cones or rays"),
        with(integer({"gather-rays", kCones, "R", "",
                      "--gather-trace rays: rays per traced pixel, the same every frame; the 3x3 resolve "
                      "(--cone-spin's) averages neighbours' rays, --gather-ray-filter times",
                      kAll, kFrame},
                     1, 1024, FIELD(settings.gather.rays)),
             "8"),
        with(integer({"gather-ray-filter", kCones, "P", "",
                      "--gather-trace rays with --cone-spin on: the 3x3 tent that averages neighbouring pixels' "
                      "rays runs P times, its taps 1, 2, 4, ... trace pixels apart, each weighing how alike the "
                      "surfaces are and how far apart (beyond about 4 voxels less and less; an a-trous filter that "
                      "stays on a surface); 1 = the tent alone",
                      kAll, kFrame},
                     1, 5, FIELD(settings.gather.rayFilterPasses)),
             "2"),
        with(number({"gather-ray-offset", kCones, "V", "voxels",
                     "--gather-trace rays: ray origins move V voxels along the normal (voxels of the pixel's own "
                     "surface are passed however far); the pixels' rays toward emitter patches "
                     "(--emitter-visibility rays) start there too, so an occluder nearer the surface casts no "
                     "area-light shadow",
                     kAll, kFrame},
                    0, 8, FIELD(settings.gather.rayOffsetVoxels)),
             "1.5", "voxels in 0..8"),
        with(number({"cone-step", kCones, "B", "", "step = B * cone diameter (beta)", kAll, kFrame}, 0.05, 4,
                    FIELD(settings.cones.stepFactor)),
             "1", "a step factor beta in 0.05..4"),
        with(number({"cone-min-step", kCones, "S", "voxels", "smallest step", kAll, kFrame}, 0.05, 8,
                    FIELD(settings.cones.minStepVoxels)),
             "1", "a step in voxels in 0.05..8"),
        with(number({"max-distance", kCones, "M", "m", "longest cone (0 = the grid's diagonal)", kAll, kFrame}, 0,
                    1e6, FIELD(settings.cones.maxDistance)),
             "2", "metres >= 0 (0 = the grid's diagonal)"),
        with(number({"cone-offset", kCones, "V", "voxels", "cone origins move V voxels along the normal", kAll,
                     kFrame},
                    0, 16, FIELD(settings.cones.offsetVoxels)),
             "1", "voxels in 0..16"),
        with(number({"cone-clearance", kCones, "K", "",
                     "near a surface, sample mip cells no larger than (height over it - 1 voxel) / K, so a cone "
                     "does not read the surface it leaves (0 = the paper's plain diameter rule)",
                     kAll, kFrame},
                    0, 8, FIELD(settings.cones.clearance)),
             "2", "a number in 0..8 (0 = off)"),
        with(toggle({"cone-spin", kCones, "on|off", "",
                     "turn the six diffuse cones about the normal by a quarter of 72 degrees more in each pixel of "
                     "a 2x2 block and resolve the turns with a 3x3 tent that keeps to the pixel's plane and normal, "
                     "so that neighbours sample 24 directions together (off: the paper's fixed set; no effect with "
                     "--cones 16); "
                     "with --gather-trace rays, the same tent averages neighbouring pixels' rays (off: each "
                     "pixel's own)",
                     kAll, kFrame},
                    FIELD(settings.gather.spin)),
             "off"),
        with(toggle({"specular", kCones, "on|off", "",
                     "one cone along the reflected view direction for glossy materials, tan(half-angle) = "
                     "roughness^2",
                     kAll, kFrame},
                    FIELD(settings.gather.specular)),
             "off"),
        with(number({"min-specular-angle", kCones, "A", "degrees", "half-angle of the narrowest specular cone", kAll,
                     kFrame},
                    0.1, 45, FIELD(settings.gather.minSpecularDegrees)),
             "5", "degrees in 0.1..45"),
        with(number({"ao-lambda", kCones, "L", "", "ambient occlusion falloff f(r) = 1/(1 + L r), r in voxels", kAll,
                     kFrame},
                    0, 1000, FIELD(settings.gather.aoLambda)),
             "1"),
        with(toggle({"ao", kCones, "on|off", "",
                     "multiply the indirect terms by the AO (off: the cones already account for occlusion)", kAll,
                     kFrame},
                    FIELD(settings.applyAO)),
             "on"),
        with(choice({"shadows", kCones, "map|cone", "",
                     "direct-light visibility from shadow maps or from a cone toward each light (paper Table V; "
                     "needs voxels)",
                     kAll, kFrame},
                    {{"map", false}, {"cone", true}}, FIELD(settings.shadowCones.enabled)),
             "cone"),
        with(number({"shadow-aperture", kCones, "D", "degrees", "full angle of the shadow cones", kAll, kFrame}, 0.1,
                    90, FIELD(settings.shadowCones.apertureDegrees)),
             "10", "degrees in 0.1..90"),
        with(number({"trace-scale", kCones, "S", "",
                     "trace cones at S x the resolution and upsample with depth and normal weights", kAll, kNew},
                    0.125, 1, FIELD(settings.gather.traceScale)),
             "0.25", "a scale in 0.125..1"),
        with(toggle({"temporal-indirect", kCones, "on|off", "",
                     "accumulate the indirect diffuse term over frames: last frame's term is reprojected through the "
                     "depth buffer and blended with this frame's, except where the surface there differs "
                     "(disocclusion) or was off screen; dropped on the first frame and when static geometry, lights "
                     "or settings change, so a single frame is unchanged",
                     kAll, kFrame},
                    FIELD(settings.temporal.enabled)),
             "off"),
        with(number({"temporal-alpha", kCones, "A", "",
                     "weight of this frame's indirect term in the blend, the same for every pixel from the "
                     "history's first frame on: an exponential average over about 1/A frames (1 = no "
                     "accumulation)",
                     kAll, kFrame},
                    0.01, 1, FIELD(settings.temporal.minAlpha)),
             "0.25", "a weight in 0.01..1"),

        // Animation and dynamic objects.
        with(integer({"frames", kAnimation, "K", "",
                      "render K frames of the glTF animations, K*time-step seconds, and write the last; a '#' run "
                      "in --out writes every frame",
                      kRender},
                     1, 100000, FIELD(frames)),
             "3"),
        with(number({"time-step", kAnimation, "S", "s", "seconds between frames", kAll, Apply::Viewer}, 0, 3600,
                    FIELD(timeStep)),
             "0.1", "seconds in 0..3600"),
        dynamicNodes(),
        unset(with(text({"add-model", kAnimation, "FILE", "",
                   "add FILE (any supported format) as a dynamic object moving on a circle through the scene, one "
                   "turn per 120 frames (bench: the Stanford bunny unless given; none = no moving object)"},
                  FIELD(addModel)),
             "bunny.ply"), "none"),
        unset(with(text({"camera-path", kAnimation, "FILE.json", "",
                         "drive the camera (--camera) along keyframes of time, position, target or orientation and "
                         "field of view (format: docs/camera-paths.md); render and bench sample it at frame * "
                         "--time-step, the viewer plays it",
                         kRender | kView | kBench},
                        FIELD(cameraPath)),
                   "walk.json"),
              "the scene's camera"),
        unset(with(number({"add-model-size", kAnimation, "M", "m", "the added model's largest extent"}, 1e-4, 1e4,
                          FIELD(addModelSize)),
                   "0.5", "a size in metres in 0.0001..10000"),
              "1/5 of the scene"),

        // dvsgi view.
        with(toggle({"vsync", kViewerGroup, "on|off", "", "FIFO presentation, or the fastest mode available (off)",
                     kView},
                    FIELD(vsync)),
             "off"),
        with(integer({"view-frames", kViewerGroup, "K", "", "close the window after K frames (0 = when closed)", kView},
                     0, 1e9, FIELD(viewFrames)),
             "3"),
        unset(with(text({"screenshot", kViewerGroup, "FILE.exr", "",
                   "on closing, write the last frame as FILE.exr and FILE.png (as the screenshot key does)", kView},
                  FIELD(screenshot), ".exr"),
             "shot.exr"), "none"),

        with(text({"record-path", kViewerGroup, "FILE.json", "",
                   "where the K key writes the camera path it records (a key per press: the camera's pose, field of "
                   "view and time; docs/camera-paths.md)",
                   kView},
                  FIELD(recordPath), ".json"),
             "walk.json"),

        // dvsgi bench.
        with(text({"bench-out", kBenchGroup, "FILE.json", "", "results; a markdown table goes to stdout", kBench},
                  FIELD(benchOut), ".json"),
             "b.json"),
        with(text({"shared", kBenchGroup, "DIR", "", "the shared data folder holding scenes/", kBench}, FIELD(sharedDir)),
             "/data/shared"),
        benchVoxels(),
        with(integer({"bench-frames", kBenchGroup, "K", "",
                      "measured frames per scene and resolution; each re-runs static voxelization. Median, min "
                      "and max per pass",
                      kBench},
                     1, 10000, FIELD(benchFrames)),
             "3"),
        with(integer({"bench-warmup", kBenchGroup, "W", "", "frames rendered before measuring, not recorded", kBench}, 0,
                     1000, FIELD(benchWarmup)),
             "1"),
        with(number({"bench-max-seconds", kBenchGroup, "S", "s",
                     "stop measuring a scene/resolution once it has run S seconds (at least one frame; the JSON "
                     "records the frames measured); 0 = always K frames",
                     kBench},
                    0, 1e6, FIELD(benchMaxSeconds)),
             "5", "seconds in 0..1000000 (0 = no limit)"),
        with(flag({"bench-quick", kBenchGroup, "", "", "Cornell box only, 32^3, 2 frames, 160x90 (a smoke test)", kBench},
                  FIELD(benchQuick)),
             "on"),
        with(flag({"bench-tables", kBenchGroup, "", "",
                   "also measure the variants of the paper's Table III (voxel raycast occlusion) and Table V "
                   "(shadow cones of 1, 5, 10, 25 degrees) for every scene and size (six times the runs)",
                   kBench},
                  FIELD(benchTables)),
             "on"),
        with(flag({"pv-tables", kBenchGroup, "", "",
                   "instead of the frame benchmark: the progressive-voxelization chapter's Table 6.1 (voxelization "
                   "time: conference, dragon, Sponza at 128^3, 256^3 and, where the device can hold it, 512^3) and Table 6.2 (average Hausdorff distance "
                   "after orbits: bunny, dragon, buddha at 64^3-256^3) as markdown; --bench-voxels replaces the "
                   "sizes (docs/pv.md)",
                   kBench},
                  FIELD(pvTables)),
             "on"),
        with(text({"pv-doc", kBenchGroup, "FILE.md", "",
                   "--pv-tables also writes its tables into FILE.md, replacing what lies between the lines "
                   "'<!-- pv-tables: begin -->' and '<!-- pv-tables: end -->' (docs/pv.md has them)",
                   kBench},
                  FIELD(pvDoc), ".md"),
             "docs/pv.md"),

        // dvsgi soak.
        with(integer({"soak-frames", kSoakGroup, "N", "", "frames in all", kSoak}, 1, 100000000, FIELD(soakFrames)),
             "400"),
        with(integer({"soak-every", kSoakGroup, "K", "", "frames between setting changes and memory reports", kSoak},
                     1, 1000000, FIELD(soakEvery)),
             "20"),
        with(text({"soak-out", kSoakGroup, "FILE.json", "", "the report series and the growth", kSoak},
                  FIELD(soakOut), ".json"),
             "s.json"),
        with(number({"soak-max-growth", kSoakGroup, "P", "%",
                     "fail (exit 4) when RSS or device memory grows by more than P percent after the first "
                     "settings cycle",
                     kSoak},
                    0, 1000, FIELD(soakMaxGrowth)),
             "2", "a percentage in 0..1000"),
    };
}

}  // namespace dvsgi::app::entries
