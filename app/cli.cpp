#include "options.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <functional>
#include <limits>
#include <string_view>

#ifndef DVSGI_VERSION
#define DVSGI_VERSION "unknown"
#endif

namespace dvsgi::app {

namespace {

// Thrown inside the parser only; parseCommandLine turns it into ParseResult::error.
struct ParseError {
    std::string message;
};

[[noreturn]] void reject(std::string message) { throw ParseError{std::move(message)}; }

[[noreturn]] void badValue(std::string_view opt, std::string_view expected, std::string_view got) {
    reject(std::string(opt) + ": expected " + std::string(expected) + ", got '" +
           std::string(got) + "'");
}

// Digits only: from_chars alone would accept a leading '-' for signed types
// and we want "+5", " 5", "5x", "0x10" all rejected.
uint64_t parseUnsigned(std::string_view opt, std::string_view text, uint64_t lo, uint64_t hi,
                       std::string_view expected) {
    const bool digits = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
        return c >= '0' && c <= '9';
    });
    uint64_t v = 0;
    if (!digits) badValue(opt, expected, text);
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || v < lo || v > hi)
        badValue(opt, expected, text);
    return v;
}

float parseFloat(std::string_view opt, std::string_view text, float lo, float hi,
                 std::string_view expected) {
    std::string_view t = text;
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);  // "+1" EV reads naturally
    // from_chars would take "inf"/"nan"; the range test below rejects them, but
    // demand a digit so words like "infinity" fail for the obvious reason.
    const bool hasDigit = std::any_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
    float v = 0.0f;
    if (t.empty() || !hasDigit || t.front() == '+') badValue(opt, expected, text);
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size() || !std::isfinite(v) || v < lo || v > hi)
        badValue(opt, expected, text);
    return v;
}

bool parseOnOff(std::string_view opt, std::string_view v) {
    if (v != "on" && v != "off") badValue(opt, "on or off", v);
    return v == "on";
}

bool endsWithNoCase(std::string_view s, std::string_view suffix) {
    if (s.size() < suffix.size()) return false;
    return std::equal(suffix.begin(), suffix.end(), s.end() - suffix.size(), [](char a, char b) {
        return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
    });
}

// A file name with the given extension and a non-empty stem.
void requireExtension(std::string_view opt, std::string_view text, std::string_view ext,
                      std::string_view expected) {
    const size_t slash = text.find_last_of('/');
    const std::string_view base = slash == std::string_view::npos ? text : text.substr(slash + 1);
    if (!endsWithNoCase(base, ext) || base.size() == ext.size()) badValue(opt, expected, text);
}

struct OptionSpec {
    std::string_view name;
    bool takesValue;
    std::function<void(RenderOptions&, std::string_view opt, std::string_view value)> apply;
};

const std::vector<OptionSpec>& optionSpecs() {
    static const std::vector<OptionSpec> specs = {
        {"--out", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             requireExtension(opt, v, ".exr", "a .exr file name");
             o.outExr = v;
         }},
        {"--aov", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             requireExtension(opt, v, ".exr", "a .exr file name");
             o.aovExr = v;
         }},
        {"--exr-type", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             if (v != "float" && v != "half") badValue(opt, "float or half", v);
             o.exrHalf = v == "half";
         }},
        {"--png", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             if (v != "none") requireExtension(opt, v, ".png", "a .png file name or 'none'");
             o.outPng = v;
         }},
        {"--width", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.width = uint32_t(parseUnsigned(opt, v, 1, 16384, "an integer in 1..16384"));
         }},
        {"--height", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.height = uint32_t(parseUnsigned(opt, v, 1, 16384, "an integer in 1..16384"));
         }},
        {"--camera", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.camera = int(parseUnsigned(opt, v, 0, uint64_t(std::numeric_limits<int>::max()),
                                          "an integer >= 0"));
         }},
        {"--exposure", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.exposure = parseFloat(opt, v, -20.0f, 20.0f, "a number in -20..20 (EV)");
         }},
        {"--metrics", true,
         [](RenderOptions& o, std::string_view, std::string_view v) { o.metricsPath = v; }},
        {"--allow-outside-references", false,
         [](RenderOptions& o, std::string_view, std::string_view) { o.allowOutsideReferences = true; }},
        {"--device", true,
         [](RenderOptions& o, std::string_view, std::string_view v) { o.device = v; }},
        {"--validate", false,
         [](RenderOptions& o, std::string_view, std::string_view) { o.validate = true; }},
        {"--shadow-map", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             const char* expected = "a power of two in 256..8192";
             const uint64_t n = parseUnsigned(opt, v, 256, 8192, expected);
             if ((n & (n - 1)) != 0) badValue(opt, expected, v);
             o.shadowMapSize = uint32_t(n);
         }},
        {"--supersample", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.supersample = uint32_t(parseUnsigned(opt, v, 1, 8, "an integer in 1..8"));
         }},
        {"--quiet", false,
         [](RenderOptions& o, std::string_view, std::string_view) { o.quiet = true; }},
        {"--voxels", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             const char* expected = "0 or a power of two in 32..512";
             const uint64_t n = parseUnsigned(opt, v, 0, 512, expected);
             if (n != 0 && (n < 32 || (n & (n - 1)) != 0)) badValue(opt, expected, v);
             o.voxels = uint32_t(n);
         }},
        {"--voxel-box", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             const char* expected = "six numbers minx,miny,minz,maxx,maxy,maxz with min < max";
             std::string_view rest = v;
             for (int i = 0; i < 6; ++i) {
                 const size_t comma = rest.find(',');
                 if ((comma == std::string_view::npos) != (i == 5)) badValue(opt, expected, v);
                 o.voxelBox[i] = parseFloat(opt, rest.substr(0, comma), -1e6f, 1e6f, expected);
                 rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
             }
             for (int i = 0; i < 3; ++i)
                 if (!(o.voxelBox[i] < o.voxelBox[i + 3])) badValue(opt, expected, v);
             o.hasVoxelBox = true;
         }},
        {"--conservative", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             if (v != "auto" && v != "gs") badValue(opt, "'auto' (hardware when available) or 'gs'", v);
             o.hardwareConservative = v == "auto";
         }},
        {"--view", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             static const std::pair<std::string_view, ViewKind> kinds[] = {
                 {"final", ViewKind::Final},
                 {"voxels:albedo", ViewKind::VoxelAlbedo},
                 {"voxels:normal", ViewKind::VoxelNormal},
                 {"voxels:emission", ViewKind::VoxelEmission},
                 {"voxels:radiance", ViewKind::VoxelRadiance},
                 {"voxels:directional", ViewKind::VoxelDirectional}};
             for (const auto& [name, kind] : kinds)
                 if (v == name) {
                     o.view = kind;
                     return;
                 }
             badValue(opt, "final or voxels:albedo|normal|emission|radiance|directional", v);
         }},
        {"--view-mip", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.viewMip = uint32_t(parseUnsigned(opt, v, 0, 16, "an integer in 0..16"));
         }},
        {"--view-direction", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             static const std::string_view names[] = {"-x", "+x", "-y", "+y", "-z", "+z"};
             for (uint32_t i = 0; i < 6; ++i)
                 if (v == names[i]) {
                     o.viewDirection = i;
                     return;
                 }
             badValue(opt, "one of -x +x -y +y -z +z", v);
         }},
        {"--bounces", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.bouncesAuto = v == "auto";
             if (!o.bouncesAuto) o.bounces = uint32_t(parseUnsigned(opt, v, 0, 64, "'auto' or an integer in 0..64"));
         }},
        {"--bounce-convergence", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.bounceConvergence = parseFloat(opt, v, 1e-5f, 0.5f, "a relative change in 0.00001..0.5");
         }},
        {"--emitters", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             if (v != "lights" && v != "cones") badValue(opt, "lights or cones", v);
             o.emitterLights = v == "lights";
         }},
        {"--emitter-patches", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.emitterPatches = uint32_t(parseUnsigned(opt, v, 1, 1024, "an integer in 1..1024"));
         }},
        {"--max-bounces", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.maxBounces = uint32_t(parseUnsigned(opt, v, 1, 1000, "an integer in 1..1000"));
         }},
        {"--normal-weighted", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.normalWeighted = parseOnOff(opt, v);
         }},
        {"--voxel-occlusion", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             if (v != "shadowmap" && v != "raycast" && v != "soft" && v != "none" && v != "per-light")
                 badValue(opt, "shadowmap, raycast, soft, none or per-light", v);
             o.voxelOcclusion = v;
         }},
        {"--light-occlusion", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             const size_t eq = v.rfind('=');
             const char* expected = "NAME=shadowmap|raycast|soft|none";
             if (eq == std::string_view::npos || eq == 0) badValue(opt, expected, v);
             const std::string_view mode = v.substr(eq + 1);
             if (mode != "shadowmap" && mode != "raycast" && mode != "soft" && mode != "none")
                 badValue(opt, expected, v);
             o.lightOcclusion.emplace_back(std::string(v.substr(0, eq)), std::string(mode));
         }},
        {"--soft-kappa", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.softKappa = parseFloat(opt, v, 0.0f, 100.0f, "a number in 0..100");
         }},
        {"--cones", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             if (v != "6" && v != "16") badValue(opt, "6 or 16", v);
             o.cones = v == "6" ? 6 : 16;
         }},
        {"--cone-step", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.coneStep = parseFloat(opt, v, 0.05f, 4.0f, "a step factor beta in 0.05..4");
         }},
        {"--cone-min-step", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.coneMinStep = parseFloat(opt, v, 0.05f, 8.0f, "a step in voxels in 0.05..8");
         }},
        {"--max-distance", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.maxDistance = parseFloat(opt, v, 0.0f, 1e6f, "metres >= 0 (0 = the grid's diagonal)");
         }},
        {"--cone-offset", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.coneOffset = parseFloat(opt, v, 0.0f, 16.0f, "voxels in 0..16");
         }},
        {"--cone-clearance", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.coneClearance = parseFloat(opt, v, 0.0f, 8.0f, "a number in 0..8 (0 = off)");
         }},
        {"--ao-lambda", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.aoLambda = parseFloat(opt, v, 0.0f, 1000.0f, "a number in 0..1000");
         }},
        {"--ao", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.ao = parseOnOff(opt, v);
         }},
        {"--specular", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.specular = parseOnOff(opt, v);
         }},
        {"--shadows", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             if (v != "map" && v != "cone") badValue(opt, "map or cone", v);
             o.shadows = v;
         }},
        {"--shadow-aperture", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.shadowAperture = parseFloat(opt, v, 0.1f, 90.0f, "degrees in 0.1..90");
         }},
        {"--trace-scale", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.traceScale = parseFloat(opt, v, 0.125f, 1.0f, "a scale in 0.125..1");
         }},
        {"--output", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             if (v != "full" && v != "direct" && v != "indirect" && v != "specular" && v != "ao" && v != "shadow")
                 badValue(opt, "full, direct, indirect, specular, ao or shadow", v);
             o.output = v;
         }},
        {"--frames", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.frames = uint32_t(parseUnsigned(opt, v, 1, 100000, "an integer in 1..100000"));
         }},
        {"--time-step", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.timeStep = parseFloat(opt, v, 0.0f, 3600.0f, "seconds in 0..3600");
         }},
        {"--dynamic", true,
         [](RenderOptions& o, std::string_view, std::string_view v) { o.dynamicNodes.emplace_back(v); }},
        {"--add-model", true,
         [](RenderOptions& o, std::string_view, std::string_view v) { o.addModel = v; }},
        {"--add-model-size", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.addModelSize = parseFloat(opt, v, 1e-4f, 1e4f, "a size in metres in 0.0001..10000");
         }},
        {"--view-frames", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.viewFrames = uint32_t(parseUnsigned(opt, v, 0, 1000000000, "an integer >= 0"));
         }},
        {"--screenshot", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             requireExtension(opt, v, ".exr", "a .exr file name");
             o.screenshot = v;
         }},
        {"--vsync", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) { o.vsync = parseOnOff(opt, v); }},
        {"--bench-out", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             requireExtension(opt, v, ".json", "a .json file name");
             o.benchOut = v;
         }},
        {"--shared", true,
         [](RenderOptions& o, std::string_view, std::string_view v) { o.sharedDir = v; }},
        {"--bench-voxels", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             const char* expected = "a comma-separated list of powers of two in 32..512";
             std::vector<uint32_t> list;
             std::string_view rest = v;
             while (true) {
                 const size_t comma = rest.find(',');
                 const std::string_view item = rest.substr(0, comma);
                 const uint64_t n = parseUnsigned(opt, item, 32, 512, expected);
                 if ((n & (n - 1)) != 0) badValue(opt, expected, v);
                 list.push_back(uint32_t(n));
                 if (comma == std::string_view::npos) break;
                 rest = rest.substr(comma + 1);
             }
             o.benchVoxels = list;
         }},
        {"--bench-frames", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.benchFrames = uint32_t(parseUnsigned(opt, v, 1, 10000, "an integer in 1..10000"));
         }},
        {"--bench-warmup", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.benchWarmup = uint32_t(parseUnsigned(opt, v, 0, 1000, "an integer in 0..1000"));
         }},
        {"--bench-max-seconds", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.benchMaxSeconds = parseFloat(opt, v, 0.0f, 1e6f, "seconds in 0..1000000 (0 = no limit)");
         }},
        {"--bench-quick", false,
         [](RenderOptions& o, std::string_view, std::string_view) { o.benchQuick = true; }},
        {"--bench-tables", false,
         [](RenderOptions& o, std::string_view, std::string_view) { o.benchTables = true; }},
    };
    return specs;
}

bool isHelp(std::string_view a) { return a == "--help" || a == "-h"; }

void parseRenderArgs(const std::vector<std::string_view>& args, RenderOptions& o) {
    bool haveScene = false;
    bool optionsEnded = false;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string_view arg = args[i];
        if (optionsEnded || arg.empty() || arg[0] != '-' || arg == "-") {
            if (haveScene)
                reject("unexpected argument '" + std::string(arg) + "' (scene already given as '" +
                       o.scene + "')");
            o.scene = arg;
            haveScene = true;
            continue;
        }
        if (arg == "--") {
            optionsEnded = true;
            continue;
        }
        const size_t eq = arg.find('=');
        const std::string_view name = arg.substr(0, eq);
        const auto& specs = optionSpecs();
        const auto spec = std::find_if(specs.begin(), specs.end(),
                                       [&](const OptionSpec& s) { return s.name == name; });
        if (spec == specs.end())
            reject("unknown option '" + std::string(name) + "' (see dvsgi --help)");

        std::string_view value;
        if (!spec->takesValue) {
            if (eq != std::string_view::npos)
                reject(std::string(name) + ": takes no value, got '" + std::string(arg.substr(eq + 1)) + "'");
        } else if (eq != std::string_view::npos) {
            value = arg.substr(eq + 1);
            if (value.empty()) reject(std::string(name) + ": missing value");
        } else {
            // A following long option means the value was forgotten; single-dash
            // words are allowed through so "--exposure -2" works.
            if (i + 1 >= args.size() || args[i + 1].empty() || args[i + 1].starts_with("--"))
                reject(std::string(name) + ": missing value");
            value = args[++i];
        }
        spec->apply(o, name, value);
    }
}

}  // namespace

ParseResult parseCommandLine(int argc, const char* const* argv) {
    ParseResult result;
    std::vector<std::string_view> args;
    for (int i = 1; i < argc; ++i) args.emplace_back(argv[i] ? argv[i] : "");

    if (args.empty()) {
        result.command = Command::Help;
        return result;
    }
    // Asking for help wins over any other problem on the line.
    const auto helpEnd = std::find(args.begin(), args.end(), std::string_view("--"));
    if (std::any_of(args.begin(), helpEnd, isHelp) || args[0] == "help") {
        result.command = Command::Help;
        return result;
    }
    if (args[0] == "--version") {
        result.command = Command::Version;
        return result;
    }

    const std::string_view cmd = args[0];
    if (cmd == "render") result.command = Command::Render;
    else if (cmd == "view") result.command = Command::View;
    else if (cmd == "bench") result.command = Command::Bench;
    else {
        result.command = Command::Help;
        if (cmd.starts_with("-"))
            result.error = "expected a command before '" + std::string(cmd) +
                           "': render, view, bench, help or --version (see dvsgi --help)";
        else
            result.error = "unknown command '" + std::string(cmd) +
                           "' (expected render, view, bench, help or --version)";
        return result;
    }

    try {
        parseRenderArgs({args.begin() + 1, args.end()}, result.render);
    } catch (const ParseError& e) {
        result.error = e.message;
        result.render = RenderOptions{};
    }
    return result;
}

std::string usageText() {
    return "dvsgi " DVSGI_VERSION
           " - voxel global illumination renderer (Vulkan)\n"
           "\n"
           "Usage:\n"
           "  dvsgi render [SCENE] [options]   render one frame to an EXR (and a PNG preview)\n"
           "  dvsgi view   [SCENE] [options]   interactive window (same options)\n"
           "  dvsgi bench  [SCENE] [options]   time the frame passes (same options)\n"
           "  dvsgi help | --help | -h         this text\n"
           "  dvsgi --version                  print the version\n"
           "\n"
           "SCENE is a glTF 2.0 (.gltf/.glb), OBJ (+MTL) or PLY file; without one the built-in\n"
           "Cornell box is used.\n"
           "Options take their value as '--opt VALUE' or '--opt=VALUE'; '--' ends the options.\n"
           "\n"
           "Options:\n"
           "  --out FILE.exr       output frame (default out/render.exr). OpenEXR, float32 R,G,B:\n"
           "                       linear radiance in W.m^-2.sr^-1 averaged over each pixel's area;\n"
           "                       no exposure, tone mapping or gamma. Missing directories are created.\n"
           "  --exr-type float|half  sample type of --out and --aov (default float; half keeps\n"
           "                       11 significant bits, values above 65504 become infinite)\n"
           "  --aov FILE.exr       also write one multi-layer EXR of the frame's terms at the\n"
           "                       output size: direct, indirect, specular (R,G,B radiance),\n"
           "                       ao (Y), albedo (R,G,B base colour), normal (X,Y,Z world),\n"
           "                       depth (Z, metres along the view axis; inf = no geometry);\n"
           "                       a '#' run is replaced by the frame number as in --out\n"
           "  --png FILE.png|none  8-bit sRGB preview (default: the --out name with .png);\n"
           "                       'none' writes no preview\n"
           "  --width N            image width in pixels, 1..16384 (default 512)\n"
           "  --height N           image height in pixels, 1..16384 (default 512)\n"
           "  --camera N           index among the scene's camera nodes, >= 0 (default 0 = first)\n"
           "  --exposure EV        exposure in stops applied to the PNG preview only:\n"
           "                       preview = sRGB(clamp(radiance * 2^EV, 0, 1)); -20..20 (default 0).\n"
           "                       The EXR is never scaled.\n"
           "  --metrics FILE.json  write timings and frame statistics as JSON (default: none)\n"
           "  --allow-outside-references  let a scene name buffers, images, MTL files or textures\n"
           "                       outside its own folder (refused by default)\n"
           "  --device NAME        use the first Vulkan device whose name contains NAME\n"
           "                       (default: the best available device)\n"
           "  --validate           enable the Khronos validation layer (default off)\n"
           "  --shadow-map N       shadow map resolution in texels per side, a power of two\n"
           "                       in 256..8192 (default 2048)\n"
           "  --supersample K      render at K*width x K*height and box-average each KxK block,\n"
           "                       giving pixel-area averages; 1..8 (default 1 = no supersampling)\n"
           "  --quiet              do not print the timing table on stdout (default: print it)\n"
           "\n"
           "Voxels:\n"
           "  --voxels N           voxel grid of N^3, N a power of two in 32..512 (default 128);\n"
           "                       0 = no voxel passes. The grid is a cube on the scene's bounds\n"
           "  --voxel-box X0,Y0,Z0,X1,Y1,Z1  put the grid on this box (metres) instead\n"
           "  --conservative auto|gs  conservative rasterization for voxelization: hardware\n"
           "                       (VK_EXT_conservative_rasterization) when the device has it,\n"
           "                       else geometry-shader dilation (default auto); gs = always dilate\n"
           "  --view MODE          final (default) or voxels:albedo|normal|emission|radiance|directional:\n"
           "                       draw that voxel volume as cubes from the camera instead\n"
           "  --view-mip M         mip level for voxels:directional (default 0)\n"
           "  --view-direction D   -x +x -y +y -z +z: which directional volume (default -x)\n"
           "\n"
           "Voxel light:\n"
           "  --bounces auto|K     voxel bounces by cone tracing. auto (default): a single render\n"
           "                       repeats the bounce until the voxel radiance changes by less\n"
           "                       than --bounce-convergence (all bounces, converged); later frames\n"
           "                       (--frames, dvsgi view) add one bounce per frame from the previous\n"
           "                       frame's light (feedback). K: exactly K bounces every frame, 0..64\n"
           "                       (the paper: 1; 0 = direct light only)\n"
           "  --bounce-convergence C  converging stops when the light still missing, estimated\n"
           "                       from how the change sum|dY|/sum Y of voxel luminance shrinks per\n"
           "                       bounce, is below C (default 0.005), or when the change is down\n"
           "                       to the RGBA16F rounding noise (5e-4)\n"
           "  --max-bounces M      converging stops after M bounces even if not converged, and\n"
           "                       says so (default 64)\n"
           "  --emitters lights|cones  emissive surfaces lit as area lights (default lights: their\n"
           "                       triangles become --emitter-patches patches, evaluated at voxels\n"
           "                       and pixels with voxel visibility) or only gathered by the cones\n"
           "                       (the paper; small emitters are under-sampled). Emissive textures\n"
           "                       always use the cones\n"
           "  --emitter-patches N  area-light patches for all emitters, 1..1024 (default 64)\n"
           "  --normal-weighted on|off  normal-weighted attenuation (paper eq. 5, default on)\n"
           "                       or plain Lambert N.L with the averaged normal (eq. 2)\n"
           "  --voxel-occlusion M  occlusion of lights at voxels for all lights: shadowmap,\n"
           "                       raycast (hard), soft (raycast, nu += (1-nu) kappa / t), none;\n"
           "                       default per-light (each light's own mode, shadowmap unless set)\n"
           "  --light-occlusion NAME=M  the mode of one light (repeatable)\n"
           "  --soft-kappa K       kappa of soft raycast shadows, t in voxels (default 0.5)\n"
           "\n"
           "Cone tracing and composition:\n"
           "  --cones 6|16         diffuse cone set: the paper's six 60-degree cones (default)\n"
           "                       or sixteen equal-solid-angle cones; cosine-weighted and\n"
           "                       normalized so a uniform radiance L gives irradiance pi*L\n"
           "  --cone-step B        step = B * cone diameter (beta, default 0.5)\n"
           "  --cone-min-step S    smallest step in voxels (default 0.5)\n"
           "  --max-distance M     longest cone in metres (default 0 = the grid's diagonal)\n"
           "  --cone-offset V      cone origins move V voxels along the normal (default 2.5)\n"
           "  --cone-clearance K   near a surface, sample mip cells no larger than (height\n"
           "                       over it - 1 voxel) / K, so a cone does not read the surface\n"
           "                       it leaves (default 3; 0 = the paper's plain diameter rule)\n"
           "  --specular on|off    one cone along the reflected view direction for glossy\n"
           "                       materials, tan(half-angle) = roughness^2 (default on)\n"
           "  --ao-lambda L        ambient occlusion falloff f(r) = 1/(1 + L r), r in voxels\n"
           "                       (default 0.5)\n"
           "  --ao on|off          multiply the indirect terms by the AO (default off: the\n"
           "                       cones already account for occlusion)\n"
           "  --shadows map|cone   direct-light visibility from shadow maps (default) or from\n"
           "                       a cone toward each light (paper Table V)\n"
           "  --shadow-aperture D  full angle of the shadow cones in degrees (default 5)\n"
           "  --trace-scale S      trace cones at S x the resolution and upsample with depth\n"
           "                       and normal weights (0.125..1, default 1)\n"
           "  --output T           full (default), direct, indirect, specular, ao or shadow:\n"
           "                       write one term of the composition\n"
           "\n"
           "Animation and dynamic objects:\n"
           "  --frames K           render K frames of the glTF animations, K*time-step seconds,\n"
           "                       and write the last; a '#' run in --out (e.g. f_###.exr)\n"
           "                       writes every frame with its number (default 1)\n"
           "  --time-step S        seconds between frames (default 1/30)\n"
           "  --dynamic NAME       mark the node NAME dynamic (repeatable); animated nodes are\n"
           "                       dynamic already. Dynamic geometry is re-voxelized every frame\n"
           "  --add-model FILE     add FILE (any supported format) as a dynamic object moving on\n"
           "                       a circle through the scene, one turn per 120 frames\n"
           "  --add-model-size M   its largest extent in metres (default: 1/5 of the scene)\n"
           "  --help, -h           this text\n"
           "\n"
           "Viewer (dvsgi view; needs a display):\n"
           "  Keys: WASD move, Q/E down/up, right mouse drag looks, scroll changes the speed,\n"
           "  1-9 pick a scene camera, V toggles vsync, P takes a screenshot, Esc closes;\n"
           "  arrows and PageUp/PageDown move a light or dynamic object (Tab picks which).\n"
           "  The window shows the frame as the PNG preview encodes it (--exposure applies).\n"
           "  --vsync on|off       FIFO presentation (default on) or the fastest mode available\n"
           "  --view-frames K      close the window after K frames (default 0 = when closed)\n"
           "  --screenshot FILE.exr  on closing, write the last frame as FILE.exr and FILE.png\n"
           "                       (the same code as the screenshot key)\n"
           "\n"
           "Benchmark (dvsgi bench; see docs/benchmarks.md):\n"
           "  Without SCENE: the paper's Table II suite, Cornell box, Sibenik and Crytek Sponza\n"
           "  from the shared folder, each with the Stanford bunny as the moving dynamic object\n"
           "  (--add-model replaces the bunny). Images are 640x360 unless --width/--height are given.\n"
           "  --bench-out FILE.json  results (default out/bench.json); a markdown table goes to stdout\n"
           "  --shared DIR         the shared data folder holding scenes/ (default ../shared)\n"
           "  --bench-voxels LIST  voxel resolutions, e.g. 128,256 (default 128,256)\n"
           "  --bench-frames K     measured frames per scene and resolution (default 10); each\n"
           "                       re-runs static voxelization. Median, min and max per pass\n"
           "  --bench-warmup W     frames rendered before measuring, not recorded (default 2)\n"
           "  --bench-max-seconds S  stop measuring a scene/resolution once it has run S seconds\n"
           "                       (at least one frame; the JSON records the frames measured)\n"
           "                       (default 0 = always K frames)\n"
           "  --bench-quick        Cornell box only, 32^3, 2 frames, 160x90 (a smoke test)\n"
           "  --bench-tables       also measure the variants of the paper's Table III (voxel\n"
           "                       raycast occlusion) and Table V (shadow cones of 1, 5, 10, 25\n"
           "                       degrees) for every scene and size (six times the runs)\n"
           "\n"
           "Exit status: 0 on success, 2 for a bad command line, another non-zero value\n"
           "for any other failure.\n";
}

}  // namespace dvsgi::app
