// The settings table's entries, in --help order: output, image, scene and
// device, voxels, voxel light here, the rest in settings_entries_commands.cpp.
// A new setting is one entry plus the code that uses its field; defaults come
// from the bound field's initialiser (render::RenderSettings for the renderer,
// RenderOptions else).
#include "settings_entries.h"

#include "voxel_dump.h"

namespace dvsgi::app {

namespace entries {

using namespace table;

namespace {

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

}  // namespace

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
        unset(with(text({"voxel-dump", kOutput, "FILE.npy", "",
                         std::string("also write every occupied voxel of the fitted grid, after the last frame, as one "
                                     "row of float32 in a NumPy .npy table: ") +
                             kVoxelDumpColumns + " (scripts/voxel-truth.py checks it against a tracer); the grid is read back "
                                                 "whole, about 90 bytes of host memory per grid voxel (1.5 GiB at 256^3)",
                         kRender},
                        FIELD(voxelDump), ".npy"),
                   "voxels.npy"),
              "none"),
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
        with(integer({"texture-anisotropy", kImage, "N", "",
                      "most anisotropic filtering of scene textures (1 = none; the device's limit caps it): "
                      "sharper textures seen at an angle, nearly free on a GPU, about 45 % of the G-buffer's "
                      "time on a CPU device at 8",
                      kAll, kNew},
                     1, 16, FIELD(settings.textureAnisotropy)),
             "1"),
        with(toggle({"shadow-focus", kImage, "on|off", "",
                     "with --clipmap, give each directional light a second shadow view over level 0's window "
                     "around the camera (when that is smaller than the scene's bounding sphere), so a large scene keeps "
                     "fine shadows near the camera",
                     kAll, kNew},
                    FIELD(settings.shadowFocus)),
             "off"),
        with(choice({"output", kImage, "T", "",
                     "write one term of the composition instead of the full image (irradiance: the indirect "
                     "diffuse light before the albedo, E/pi, as a white surface would reflect it)",
                     kAll, kFrame},
                    {{"full", 0u},
                     {"direct", 1u},
                     {"indirect", 2u},
                     {"specular", 3u},
                     {"ao", 4u},
                     {"shadow", 5u},
                     {"irradiance", 6u}},
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
        with(integer({"grid-samples", kVoxels, "K", "",
                      "render K times, the voxel grid moved each time by a fraction of a voxel along its three "
                      "axes (the first render on the grid itself, the rest spread over the voxel by an R3 "
                      "sequence), and write the mean image: where the lattice falls on the scene moves the "
                      "indirect light much less, at K times the cost (docs/quality.md, \"Where the grid falls\"); "
                      "one frame of a fitted grid only (not with --frames above 1, --camera-path, --clipmap, "
                      "--voxelizer pv or --view voxels:...)",
                      kRender, Apply::Startup},
                     1, 64, FIELD(gridSamples)),
             "4"),
        with(integer({"clipmap", kVoxels, "L", "levels",
                      "camera-following voxel clipmap: L levels of N^3 voxels (--voxels), each twice the voxel of "
                      "the one before, centred on the camera; a move voxelizes again only the slabs it exposes "
                      "(toroidal storage) and cones trace across the levels; 0 = one grid fitted to the scene "
                      "(docs/clipmap.md)",
                      kAll, kNew},
                     1, 8, FIELD(settings.clipmap.levels), false, true),
             "4"),
        with(number({"clipmap-voxel", kVoxels, "S", "m",
                     "--clipmap: the voxel edge of the finest level; 0 = the coarsest level holds the whole scene "
                     "from the starting camera (twice the scene's longest side from inside it)",
                     kAll, kNew},
                    0.0, 1000.0, FIELD(settings.clipmap.voxelSize)),
             "0.05", "a length in 0..1000 m"),
        with(choice({"conservative", kVoxels, "auto|gs", "",
                     "conservative rasterization for voxelization: hardware (VK_EXT_conservative_rasterization) "
                     "when the device has it, else geometry-shader dilation; gs = always dilate",
                     kAll, kNew},
                    {{"auto", true}, {"gs", false}}, FIELD(settings.hardwareConservative)),
             "gs", "'auto' (hardware when available) or 'gs'"),
        with(choice({"voxelizer", kVoxels, "geometry|compute|auto|pv", "",
                     "how triangles become voxels: geometry = rasterized with a geometry shader (dilated, "
                     "extras within one voxel), compute = binned in compute shaders with an exact triangle/voxel "
                     "test (needs shaderFloat64), auto = the faster one on this device type, pv = progressive "
                     "screen-space voxelization: kept from frame to frame, filled from the camera's G-buffer and "
                     "cleared where depth buffers see empty space (only what the camera has seen is voxelized; "
                     "docs/pv.md)",
                     kAll, kNew},
                    {{"geometry", vxgi::VoxelizerKind::Geometry},
                     {"compute", vxgi::VoxelizerKind::Compute},
                     {"auto", vxgi::VoxelizerKind::Auto},
                     {"pv", vxgi::VoxelizerKind::Pv}},
                    FIELD(settings.voxelizer)),
             "compute", "geometry, compute, auto or pv"),
        with(integer({"pv-grid", kVoxels, "S", "samples",
                      "--voxelizer pv: injection grid, samples along the G-buffer's longer side (the other in "
                      "proportion); 0 = every pixel",
                      kAll, kFrame},
                     0, 16384, FIELD(settings.pv.grid)),
             "256"),
        with(toggle({"pv-single-pass", kVoxels, "on|off", "",
                    "--voxelizer pv: the chapter's single-pass variant: every grid voxel in a G-buffer's depth band "
                    "takes the sample of the pixel it projects to (instead of each sample adding to its voxel)",
                    kAll, kFrame},
                   FIELD(settings.pv.singlePass)),
             "on"),
        with(integer({"pv-views", kVoxels, "S", "texels",
                      "--voxelizer pv: extra viewpoints: six 90-degree G-buffers of S x S texels around the camera, "
                      "injected like its own, so that what it does not face is voxelized too; 0 = off",
                      kAll, kNew},
                     0, 8192, FIELD(settings.pv.views)),
             "64"),
        with(integer({"pv-rsm", kVoxels, "S", "texels",
                      "--voxelizer pv: reflective shadow maps of S x S texels, one per shadow view, injected like "
                      "the camera's G-buffer so that lit surfaces the camera has not seen are voxelized; 0 = off",
                      kAll, kNew},
                     0, 8192, FIELD(settings.pv.rsm)),
             "128"),
        with(choice({"view", kVoxels, "MODE", "",
                     "final, or voxels:albedo|normal|emission|radiance|directional|age: draw that voxel volume as "
                     "cubes from the camera instead (age: found this frame in orange, kept from earlier frames in "
                     "blue; with the geometric voxelizers, dynamic and static)",
                     kAll, kFrame},
                    {{"final", ViewMode::Final},
                     {"voxels:albedo", ViewMode::VoxelAlbedo},
                     {"voxels:normal", ViewMode::VoxelNormal},
                     {"voxels:emission", ViewMode::VoxelEmission},
                     {"voxels:radiance", ViewMode::VoxelRadiance},
                     {"voxels:directional", ViewMode::VoxelDirectional},
                     {"voxels:age", ViewMode::VoxelAge}},
                    FIELD(settings.view.mode)),
             "voxels:normal", "final or voxels:albedo|normal|emission|radiance|directional|age"),
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
                     "converging stops when the light still missing, estimated from how the change sum|dY| of "
                     "voxel luminance over the voxels' reflected light shrinks per bounce, is below C (a fraction "
                     "of the reflected light)",
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
        with(choice({"bounce-trace", kVoxelLight, "cones|rays", "",
                     "how the voxel bounce gathers each voxel's light: rays = --bounce-rays rays per voxel "
                     "marched voxel by voxel through the radiance volume, so no wall lets light through and a "
                     "closed room keeps all of it (a fitted grid's; --clipmap levels and --voxelizer pv trace cones); "
                     "cones = the paper's six cones through the filtered directional volumes",
                     kAll, kFrame},
                    {{"cones", vxgi::BounceTrace::Cones}, {"rays", vxgi::BounceTrace::Rays}},
                    FIELD(settings.voxelLight.bounceTrace)),
             "cones", "cones or rays"),
        with(integer({"bounce-rays", kVoxelLight, "R", "",
                      "--bounce-trace rays: rays per voxel over its cosine-weighted hemisphere, the same every "
                      "bounce and frame (a two-sided voxel's other side gets R/4, at least 4)",
                      kAll, kFrame},
                     1, 1024, FIELD(settings.voxelLight.bounceRays)),
             "32"),
        with(number({"voxel-temporal-alpha", kVoxelLight, "A", "",
                     "feedback frames (--frames, dvsgi view): the light each voxel reflects moves only a fraction A "
                     "of the way from what it reflected last frame, smoothing the indirect light around a moving "
                     "object (direct light is never delayed); voxels new this frame take the new value, and no "
                     "voxel blends while the light settles after a change of lights, static geometry or settings. "
                     "1 = no blending",
                     kAll, kFrame},
                    0.01, 1, FIELD(settings.voxelLight.temporalAlpha)),
             "0.5", "a weight in 0.01..1"),
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
        with(choice({"emitter-visibility", kVoxelLight, "rays|cones", "",
                     "--emitters lights: how a pixel sees each patch: rays = a ray to the patch's centre through "
                     "this frame's voxels, walked as the gather's rays walk them (a fitted grid's; --clipmap "
                     "levels and --voxelizer pv use cones); cones = a cone as wide as the patch looks through the "
                     "filtered volumes. Voxels always see patches by rays",
                     kAll, kFrame},
                    {{"rays", true}, {"cones", false}}, FIELD(settings.emitterRays)),
             "cones"),
        with(toggle({"normal-weighted", kVoxelLight, "on|off", "",
                     "normal-weighted attenuation at voxels (paper eq. 5: W = N^2, exact only for planes along the "
                     "axes; a plane at 45 degrees lit head on gets 71 % of its light) or plain Lambert N.L with "
                     "the averaged normal (eq. 2: exact for one plane at any orientation)",
                     kAll, kFrame},
                    FIELD(settings.voxelLight.normalWeighted)),
             "on"),
        with(toggle({"voxel-backs-dark", kVoxelLight, "on|off", "",
                     "a one-sided voxel seen from behind shows cones and rays no light but still blocks them (off: "
                     "its light every way, as the paper filters)",
                     kAll, kFrame},
                    FIELD(settings.voxelLight.backsDark)),
             "off"),
        with(choice({"edge-voxels", kVoxelLight, "whole|faces", "",
                     "voxels that hold an edge or a corner: whole = a cube lit with the mean normal (one of axis "
                     "faces: the lesser of that and its faces lit one by one); faces = rays pass beside the part of a voxel its surface does not reach (its "
                     "triangles' boxes; --voxelizer pv: whole voxels), and an edge's faces are lit and shown one "
                     "by one (with --normal-weighted off)",
                     kAll, kFrame},
                    {{"whole", false}, {"faces", true}}, FIELD(settings.voxelLight.edgeFaces)),
             "faces"),
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

}  // namespace entries

using namespace entries;

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
