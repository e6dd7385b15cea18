// The settings table's entries, in --help order. A new setting is one entry
// here plus the code that uses its field; defaults come from the bound field's
// initialiser (render::RenderSettings for the renderer, RenderOptions else).
#include "settings_kinds.h"

namespace dvsgi::app {

namespace {

using namespace table;

#define FIELD(expr) [](RenderOptions & o) -> auto& { return o.expr; }

const char* const kOutput = "Output";
const char* const kImage = "Image";
const char* const kSceneDevice = "Scene and device";
const char* const kVoxels = "Voxels";
const char* const kVoxelLight = "Voxel light";
const char* const kCones = "Cone tracing and composition";
const char* const kAnimation = "Animation and dynamic objects";
const char* const kViewerGroup = "Viewer (dvsgi view)";
const char* const kBenchGroup = "Benchmark (dvsgi bench)";
const char* const kSoakGroup = "Soak (dvsgi soak)";

constexpr Apply kFrame = Apply::NextFrame;
constexpr Apply kNew = Apply::NewRenderer;

Setting with(Setting s, std::string example, std::string expected = "") {
    s.example = std::move(example);
    if (!expected.empty()) s.expected = std::move(expected);
    return s;
}

// An entry whose default means "not set": `unset` says what happens then.
Setting unset(Setting s, std::string meaning) {
    s.unset = std::move(meaning);
    return s;
}

// --voxel-box X0,Y0,Z0,X1,Y1,Z1 (unset: the grid on the scene's bounds).
Setting voxelBox() {
    Setting s = base({"voxel-box", kVoxels, "X0,Y0,Z0,X1,Y1,Z1", "m",
                      "put the grid on this box instead of the scene's bounds", kAll, kNew},
                     Kind::Special);
    s.expected = "six numbers minx,miny,minz,maxx,maxy,maxz with min < max";
    s.example = "-1,-1,-1,1,1,1";
    s.parse = [](RenderOptions& o, std::string_view v) {
        float box[6];
        std::string_view rest = v;
        for (int i = 0; i < 6; ++i) {
            const size_t comma = rest.find(',');
            if ((comma == std::string_view::npos) != (i == 5)) return false;
            const std::optional<float> f = parseFloat(rest.substr(0, comma));
            if (!f || *f < -1e6f || *f > 1e6f) return false;
            box[i] = *f;
            rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
        }
        for (int i = 0; i < 3; ++i)
            if (!(box[i] < box[i + 3])) return false;
        o.settings.hasVoxelBox = true;
        o.settings.voxelBoxMin = glm::vec3(box[0], box[1], box[2]);
        o.settings.voxelBoxMax = glm::vec3(box[3], box[4], box[5]);
        return true;
    };
    s.json = [](const RenderOptions& o) {
        const render::RenderSettings& r = o.settings;
        if (!r.hasVoxelBox) return nlohmann::json(nullptr);
        return nlohmann::json({r.voxelBoxMin.x, r.voxelBoxMin.y, r.voxelBoxMin.z, r.voxelBoxMax.x, r.voxelBoxMax.y,
                               r.voxelBoxMax.z});
    };
    s.text = [](const RenderOptions& o) {
        if (!o.settings.hasVoxelBox) return std::string("scene bounds");
        const glm::vec3 lo = o.settings.voxelBoxMin, hi = o.settings.voxelBoxMax;
        std::string t;
        for (float v : {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z}) t += (t.empty() ? "" : ",") + formatNumber(v);
        return t;
    };
    return s;
}


// --bounces auto|K: converge (a render; the viewer feeds back) or exactly K.
Setting bounces() {
    Setting s = base({"bounces", kVoxelLight, "auto|K", "",
                      "voxel bounces by cone tracing. auto: a single render repeats the bounce until the voxel "
                      "radiance has converged (--bounce-convergence); later frames (--frames, dvsgi view) add one "
                      "bounce per frame from the previous frame's light (feedback). K: exactly K bounces every "
                      "frame (the paper: 1; 0 = direct light only)",
                      kAll, kFrame},
                     Kind::Special);
    s.lo = 0;
    s.hi = 64;
    s.expected = "'auto' or an integer in 0..64";
    s.example = "1";
    s.parse = [](RenderOptions& o, std::string_view v) {
        vxgi::VoxelLightSettings& l = o.settings.voxelLight;
        if (v == "auto") {
            l.bounceMode = vxgi::BounceMode::Converge;
            return true;
        }
        const std::optional<uint64_t> n = parseUnsigned(v);
        if (!n || *n > 64) return false;
        l.bounceMode = vxgi::BounceMode::Fixed;
        l.bounces = uint32_t(*n);
        return true;
    };
    s.text = [](const RenderOptions& o) {
        const vxgi::VoxelLightSettings& l = o.settings.voxelLight;
        return l.bounceMode == vxgi::BounceMode::Fixed ? std::to_string(l.bounces) : std::string("auto");
    };
    s.json = [text = s.text](const RenderOptions& o) {
        const std::string t = text(o);
        return t == "auto" ? nlohmann::json(t) : nlohmann::json(o.settings.voxelLight.bounces);
    };
    return s;
}

const std::vector<std::pair<std::string, vxgi::Occlusion>> kOcclusionModes = {
    {"shadowmap", vxgi::Occlusion::ShadowMap},
    {"raycast", vxgi::Occlusion::RaycastHard},
    {"soft", vxgi::Occlusion::RaycastSoft},
    {"none", vxgi::Occlusion::None},
};

std::string occlusionName(vxgi::Occlusion m) {
    for (const auto& [name, mode] : kOcclusionModes)
        if (mode == m) return name;
    return "per-light";
}

// --light-occlusion NAME=mode, repeatable.
Setting lightOcclusion() {
    Setting s = base({"light-occlusion", kVoxelLight, "NAME=M", "",
                      "the voxel occlusion mode of the light NAME; lights not named use shadow maps",
                      kAll, kFrame},
                     Kind::Special);
    s.repeatable = true;
    s.expected = "NAME=shadowmap|raycast|soft|none";
    s.example = "light=raycast";
    s.unset = "none";
    s.parse = [](RenderOptions& o, std::string_view v) {
        const size_t eq = v.rfind('=');
        if (eq == std::string_view::npos || eq == 0) return false;
        for (const auto& [name, mode] : kOcclusionModes)
            if (v.substr(eq + 1) == name) {
                o.settings.lightOcclusion.emplace_back(std::string(v.substr(0, eq)), mode);
                return true;
            }
        return false;
    };
    s.text = [](const RenderOptions& o) {
        std::string t;
        for (const auto& [light, mode] : o.settings.lightOcclusion)
            t += (t.empty() ? "" : ",") + light + "=" + occlusionName(mode);
        return t;
    };
    s.json = [](const RenderOptions& o) {
        nlohmann::json j = nlohmann::json::object();
        for (const auto& [light, mode] : o.settings.lightOcclusion) j[light] = occlusionName(mode);
        return j;
    };
    return s;
}

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

// Output, image, scene and device, voxels, voxel light.
std::vector<Setting> imageAndVoxels() {
    using render::ViewMode;
    const uint32_t kRV = kRender | kView;
    return {
        // Output.
        with(text({"out", kOutput, "FILE.exr", "",
                   "output frame: OpenEXR R,G,B, linear radiance in W.m^-2.sr^-1 averaged over each pixel's area; "
                   "no exposure, tone mapping or gamma. A '#' run (f_###.exr) writes every frame with its number; "
                   "missing folders are created",
                   kRender},
                  FIELD(outExr), ".exr"),
             "frames/a.exr"),
        with(choice({"exr-type", kOutput, "float|half", "",
                     "sample type of --out and --aov (half keeps 11 significant bits; above 65504 becomes infinite)",
                     kRender},
                    {{"float", false}, {"half", true}}, FIELD(exrHalf)),
             "half"),
        unset(with(text({"aov", kOutput, "FILE.exr", "",
                   "also write one multi-layer EXR of the frame's terms at the output size: direct, indirect, "
                   "specular (R,G,B radiance), ao (Y), albedo (R,G,B), normal (X,Y,Z world), depth (Z, metres along "
                   "the view axis; inf = no geometry); a '#' run is replaced as in --out",
                   kRender},
                  FIELD(aovExr), ".exr"),
             "aov.exr"), "none"),
        unset(with(text({"png", kOutput, "FILE.png|none", "", "8-bit sRGB preview; 'none' writes no preview",
                         kRender},
                        FIELD(outPng), ".png", "none"),
                   "none"),
              "the --out name with .png"),
        unset(with(text({"metrics", kOutput, "FILE.json", "",
                   "write timings, memory, the voxel grid and every setting as JSON", kRender},
                  FIELD(metricsPath)),
             "m.json"), "none"),
        with(number({"exposure", kOutput, "EV", "EV",
                     "exposure in stops for the PNG preview only: preview = sRGB(clamp(radiance * 2^EV, 0, 1)); "
                     "the EXR is never scaled",
                     kRV, Apply::Viewer},
                    -20, 20, FIELD(exposure)),
             "1.5", "a number in -20..20 (EV)"),
        with(flag({"quiet", kOutput, "", "", "do not print the device, grid and timing table on stdout", kAll},
                  FIELD(quiet)),
             "on"),

        // Image.
        with(integer({"width", kImage, "N", "px", "image width in pixels", kAll, kNew}, 1, 16384,
                     FIELD(settings.width)),
             "640"),
        with(integer({"height", kImage, "N", "px", "image height in pixels", kAll, kNew}, 1, 16384,
                     FIELD(settings.height)),
             "360"),
        with(integer({"supersample", kImage, "K", "", "render at K*width x K*height and box-average each KxK block, "
                      "giving pixel-area averages (1 = no supersampling)", kAll, kNew},
                     1, 8, FIELD(settings.supersample)),
             "2"),
        with(integer({"camera", kImage, "N", "", "index among the scene's camera nodes (0 = first)", kAll, kNew}, 0,
                     2147483647, FIELD(settings.camera)),
             "1"),
        with(integer({"shadow-map", kImage, "N", "texels", "shadow map resolution per side", kAll, kNew}, 256, 8192,
                     FIELD(settings.shadowMapSize), true),
             "1024"),
        with(choice({"output", kImage, "T", "", "write one term of the composition instead of the full image",
                     kAll, kFrame},
                    {{"full", 0u}, {"direct", 1u}, {"indirect", 2u}, {"specular", 3u}, {"ao", 4u}, {"shadow", 5u}},
                    FIELD(settings.outputTerm)),
             "indirect"),

        // Scene and device.
        with(flag({"allow-outside-references", kSceneDevice, "", "",
                   "let a scene name buffers, images, MTL files or textures outside its own folder (refused "
                   "by default)"},
                  FIELD(allowOutsideReferences)),
             "on"),
        unset(with(text({"device", kSceneDevice, "NAME", "",
                         "use the first Vulkan device whose name contains NAME (any case)"},
                        FIELD(device)),
                   "llvmpipe"),
              "the best device: discrete > integrated > CPU"),
        with(flag({"validate", kSceneDevice, "", "",
                   "enable the Khronos validation layer; exit code 3 if it reports errors"},
                  FIELD(validate)),
             "on"),

        // Voxels.
        with(integer({"voxels", kVoxels, "N", "voxels",
                      "voxel grid of N^3 on the scene's bounds; 0 = no voxel passes (direct light only)", kAll, kNew},
                     32, 512, FIELD(settings.voxels), true, true),
             "64"),
        voxelBox(),
        with(choice({"conservative", kVoxels, "auto|gs", "",
                     "conservative rasterization for voxelization: hardware (VK_EXT_conservative_rasterization) "
                     "when the device has it, else geometry-shader dilation; gs = always dilate",
                     kAll, kNew},
                    {{"auto", true}, {"gs", false}}, FIELD(settings.hardwareConservative)),
             "gs", "'auto' (hardware when available) or 'gs'"),
        with(choice({"voxelizer", kVoxels, "geometry|compute|auto", "",
                     "how triangles become voxels: geometry = rasterized with a geometry shader (dilated, "
                     "extras within one voxel), compute = binned in compute shaders with an exact triangle/voxel "
                     "test (needs shaderFloat64), auto = the faster one on this device type",
                     kAll, kNew},
                    {{"geometry", vxgi::VoxelizerKind::Geometry},
                     {"compute", vxgi::VoxelizerKind::Compute},
                     {"auto", vxgi::VoxelizerKind::Auto}},
                    FIELD(settings.voxelizer)),
             "compute", "geometry, compute or auto"),
        with(choice({"view", kVoxels, "MODE", "",
                     "final, or voxels:albedo|normal|emission|radiance|directional: draw that voxel volume as cubes "
                     "from the camera instead",
                     kAll, kFrame},
                    {{"final", ViewMode::Final},
                     {"voxels:albedo", ViewMode::VoxelAlbedo},
                     {"voxels:normal", ViewMode::VoxelNormal},
                     {"voxels:emission", ViewMode::VoxelEmission},
                     {"voxels:radiance", ViewMode::VoxelRadiance},
                     {"voxels:directional", ViewMode::VoxelDirectional}},
                    FIELD(settings.view.mode)),
             "voxels:normal", "final or voxels:albedo|normal|emission|radiance|directional"),
        with(integer({"view-mip", kVoxels, "M", "", "mip level for --view voxels:directional", kAll, kFrame}, 0, 16,
                     FIELD(settings.view.mip)),
             "1"),
        with(choice({"view-direction", kVoxels, "D", "", "which directional volume --view voxels:directional draws",
                     kAll, kFrame},
                    {{"-x", 0u}, {"+x", 1u}, {"-y", 2u}, {"+y", 3u}, {"-z", 4u}, {"+z", 5u}},
                    FIELD(settings.view.direction)),
             "+y", "one of -x +x -y +y -z +z"),

        // Voxel light.
        bounces(),
        with(number({"bounce-convergence", kVoxelLight, "C", "",
                     "converging stops when the light still missing, estimated from how the change sum|dY|/sum Y "
                     "of voxel luminance shrinks per bounce, is below C, or when the change is down to the RGBA16F "
                     "rounding noise (5e-4)",
                     kAll, kFrame},
                    1e-5, 0.5, FIELD(settings.voxelLight.convergence)),
             "0.01", "a relative change in 0.00001..0.5"),
        with(integer({"max-bounces", kVoxelLight, "M", "",
                      "converging stops after M bounces even if not converged, and says so", kAll, kFrame},
                     1, 1000, FIELD(settings.voxelLight.maxBounces)),
             "16"),
        with(number({"bounce-step", kVoxelLight, "B", "",
                     "step factor beta of the voxel bounce's cones (the pixels' cones use --cone-step)", kAll, kFrame},
                    0.05, 4, FIELD(settings.voxelLight.bounceStepFactor)),
             "0.5", "a step factor beta in 0.05..4"),
        with(choice({"emitters", kVoxelLight, "lights|cones", "",
                     "emissive surfaces lit as area lights (their triangles become --emitter-patches patches, "
                     "evaluated at voxels and pixels with voxel visibility) or only gathered by the cones (the "
                     "paper; small emitters are under-sampled). Emissive textures always use the cones",
                     kAll, kNew},
                    {{"lights", true}, {"cones", false}}, FIELD(settings.emitterLights)),
             "cones"),
        with(integer({"emitter-patches", kVoxelLight, "N", "", "area-light patches for all emitters", kAll, kNew}, 1,
                     1024, FIELD(settings.emitterPatches)),
             "16"),
        with(toggle({"normal-weighted", kVoxelLight, "on|off", "",
                     "normal-weighted attenuation at voxels (paper eq. 5) or plain Lambert N.L with the averaged "
                     "normal (eq. 2)",
                     kAll, kFrame},
                    FIELD(settings.voxelLight.normalWeighted)),
             "off"),
        with(choice({"voxel-occlusion", kVoxelLight, "M", "",
                     "occlusion of lights at voxels for all lights: shadowmap, raycast (hard), soft (raycast, "
                     "nu += (1-nu) kappa / t), none; per-light: each light's own mode (shadowmap unless "
                     "--light-occlusion sets it)",
                     kAll, kFrame},
                    {{"shadowmap", vxgi::Occlusion::ShadowMap},
                     {"raycast", vxgi::Occlusion::RaycastHard},
                     {"soft", vxgi::Occlusion::RaycastSoft},
                     {"none", vxgi::Occlusion::None},
                     {"per-light", vxgi::Occlusion::PerLight}},
                    FIELD(settings.voxelLight.occlusion)),
             "raycast"),
        lightOcclusion(),
        with(number({"soft-kappa", kVoxelLight, "K", "", "kappa of soft raycast shadows, t in voxels", kAll, kFrame},
                    0, 100, FIELD(settings.voxelLight.softKappa)),
             "1"),
    };
}

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
             "0.5", "a scale in 0.125..1"),

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

}  // namespace

const std::vector<Setting>& settingsTable() {
    static const std::vector<Setting> table = [] {
        std::vector<Setting> t = imageAndVoxels();
        for (Setting& s : conesAndCommands()) t.push_back(std::move(s));
        return t;
    }();
    return table;
}

const std::vector<SettingGroup>& settingGroups() {
    static const std::vector<SettingGroup> groups = {
        {kOutput, ""},
        {kImage, ""},
        {kSceneDevice, ""},
        {kVoxels, ""},
        {kVoxelLight, ""},
        {kCones, ""},
        {kAnimation, ""},
        {kViewerGroup,
         "Keys: WASD move, Q/E down/up, right mouse drag looks, scroll changes the speed, 1-9 pick a scene camera, "
         "V toggles vsync, P takes a screenshot, K records a camera-path key, Esc closes; arrows and PageUp/PageDown move a light or dynamic "
         "object (Tab picks which). The window shows the frame as the PNG preview encodes it (--exposure "
         "applies); the panel changes every setting marked 'next frame' without rebuilding the renderer."},
        {kBenchGroup,
         "Without SCENE: the paper's Table II suite, Cornell box, Sibenik and Crytek Sponza from the shared "
         "folder, each with the Stanford bunny as the moving dynamic object (--add-model replaces the bunny). "
         "Images are 640x360 unless --width/--height are given (docs/benchmarks.md)."},
        {kSoakGroup,
         "A moving model (--add-model, else a built-in cube) and a moving first light; every --soak-every frames "
         "the settings change (bounces, cone set, shadows, output term, voxel view), which builds a new renderer, "
         "and host RSS and device memory are reported (docs/RELIABILITY.md). Needs --voxels >= 32."},
    };
    return groups;
}

}  // namespace dvsgi::app
