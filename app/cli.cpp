#include "options.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <functional>
#include <limits>
#include <string_view>

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

// `dvsgi soak` (app/soak_command.cpp): kept apart from the shared list above.
const std::vector<OptionSpec>& soakOptionSpecs() {
    static const std::vector<OptionSpec> specs = {
        {"--soak-frames", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.soakFrames = uint32_t(parseUnsigned(opt, v, 1, 100000000, "an integer in 1..100000000"));
         }},
        {"--soak-every", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.soakEvery = uint32_t(parseUnsigned(opt, v, 1, 1000000, "an integer in 1..1000000"));
         }},
        {"--soak-out", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             requireExtension(opt, v, ".json", "a .json file name");
             o.soakOut = v;
         }},
        {"--soak-max-growth", true,
         [](RenderOptions& o, std::string_view opt, std::string_view v) {
             o.soakMaxGrowth = parseFloat(opt, v, 0.0f, 1e6f, "a percentage >= 0");
         }},
    };
    return specs;
}

const OptionSpec* findOption(std::string_view name) {
    for (const auto* list : {&optionSpecs(), &soakOptionSpecs()})
        for (const OptionSpec& s : *list)
            if (s.name == name) return &s;
    return nullptr;
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
        const OptionSpec* spec = findOption(name);
        if (!spec)
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
    else if (cmd == "soak") result.command = Command::Soak;
    else {
        result.command = Command::Help;
        if (cmd.starts_with("-"))
            result.error = "expected a command before '" + std::string(cmd) +
                           "': render, view, bench, soak, help or --version (see dvsgi --help)";
        else
            result.error = "unknown command '" + std::string(cmd) +
                           "' (expected render, view, bench, soak, help or --version)";
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

}  // namespace dvsgi::app
