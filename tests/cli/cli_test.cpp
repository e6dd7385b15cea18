#include "options.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <vector>

using namespace dvsgi::app;

namespace {

ParseResult parse(std::initializer_list<const char*> args) {
    std::vector<const char*> argv = {"dvsgi"};
    argv.insert(argv.end(), args.begin(), args.end());
    return parseCommandLine(int(argv.size()), argv.data());
}

// Parses `render <opt> <value>` in both spellings and checks they agree.
ParseResult parseBoth(const char* opt, const char* value) {
    const ParseResult spaced = parse({"render", opt, value});
    const std::string joined = std::string(opt) + "=" + value;
    const ParseResult eq = parse({"render", joined.c_str()});
    EXPECT_EQ(spaced.error, eq.error) << opt << " " << value;
    return spaced;
}

void expectError(std::initializer_list<const char*> args, const std::string& want) {
    const ParseResult r = parse(args);
    EXPECT_EQ(r.error, want);
    EXPECT_EQ(r.error.find('\n'), std::string::npos) << "errors are one line";
}

void expectBadValue(const char* opt, const char* value, const std::string& expected) {
    const std::string want = std::string(opt) + ": expected " + expected + ", got '" + value + "'";
    expectError({"render", opt, value}, want);
    const std::string joined = std::string(opt) + "=" + value;
    expectError({"render", joined.c_str()}, want);
}

}  // namespace

TEST(Cli, NoArgumentsMeansHelp) {
    const char* argv[] = {"dvsgi"};
    const ParseResult r = parseCommandLine(1, argv);
    EXPECT_EQ(r.command, Command::Help);
    EXPECT_TRUE(r.error.empty());
}

TEST(Cli, Defaults) {
    const ParseResult r = parse({"render"});
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.command, Command::Render);
    const RenderOptions& o = r.render;
    EXPECT_EQ(o.scene, "");
    EXPECT_EQ(o.outExr, "out/render.exr");
    EXPECT_EQ(o.outPng, "");
    EXPECT_EQ(o.settings.width, 512u);
    EXPECT_EQ(o.settings.height, 512u);
    EXPECT_EQ(o.settings.camera, 0);
    EXPECT_EQ(o.exposure, 0.0f);
    EXPECT_EQ(o.metricsPath, "");
    EXPECT_EQ(o.device, "");
    EXPECT_FALSE(o.validate);
    EXPECT_EQ(o.settings.shadowMapSize, 2048u);
    EXPECT_EQ(o.settings.supersample, 1u);
    EXPECT_FALSE(o.quiet);
}

TEST(Cli, Commands) {
    EXPECT_EQ(parse({"render"}).command, Command::Render);
    EXPECT_EQ(parse({"view"}).command, Command::View);
    EXPECT_EQ(parse({"bench"}).command, Command::Bench);
    EXPECT_EQ(parse({"help"}).command, Command::Help);
    EXPECT_EQ(parse({"--help"}).command, Command::Help);
    EXPECT_EQ(parse({"-h"}).command, Command::Help);
    EXPECT_EQ(parse({"--version"}).command, Command::Version);
    for (auto* cmd : {"render", "view", "bench", "help", "--help", "-h", "--version"})
        EXPECT_TRUE(parse({cmd}).error.empty()) << cmd;
}

TEST(Cli, EveryCommandTakesTheSharedOptions) {
    for (auto* cmd : {"render", "view", "bench"}) {
        const ParseResult r = parse({cmd, "scene.gltf", "--width", "64", "--quiet"});
        ASSERT_TRUE(r.error.empty()) << r.error;
        EXPECT_EQ(r.render.scene, "scene.gltf");
        EXPECT_EQ(r.render.settings.width, 64u);
        EXPECT_TRUE(r.render.quiet);
    }
}

TEST(Cli, HelpAnywhereWins) {
    for (auto args : {std::initializer_list<const char*>{"render", "--help"},
                      {"render", "scene.gltf", "--width", "abc", "-h"},
                      {"bogus", "--help"},
                      {"render", "--foo", "--help"},
                      {"help", "render"}}) {
        const ParseResult r = parse(args);
        EXPECT_EQ(r.command, Command::Help);
        EXPECT_TRUE(r.error.empty()) << r.error;
    }
}

TEST(Cli, UnknownCommand) {
    expectError({"paint"}, "unknown command 'paint' (expected render, view, bench, soak, help or --version)");
    const ParseResult r = parse({"--width", "5"});
    EXPECT_NE(r.error.find("'--width'"), std::string::npos) << r.error;
}

TEST(Cli, UnknownOption) {
    expectError({"render", "--foo"}, "unknown option '--foo' (see dvsgi --help)");
    expectError({"render", "--foo=3"}, "unknown option '--foo' (see dvsgi --help)");
    expectError({"render", "-x"}, "unknown option '-x' (see dvsgi --help)");
    expectError({"render", "--Width", "3"}, "unknown option '--Width' (see dvsgi --help)");
}

TEST(Cli, ScenePositional) {
    ParseResult r = parse({"render", "scenes/cornell.gltf"});
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.render.scene, "scenes/cornell.gltf");

    r = parse({"render", "--width", "8", "a.gltf", "--height", "4"});
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.render.scene, "a.gltf");
    EXPECT_EQ(r.render.settings.width, 8u);
    EXPECT_EQ(r.render.settings.height, 4u);

    expectError({"render", "a.gltf", "b.gltf"},
                "unexpected argument 'b.gltf' (scene already given as 'a.gltf')");

    r = parse({"render", "--", "-odd-name.gltf"});
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.render.scene, "-odd-name.gltf");
}

TEST(Cli, Out) {
    ParseResult r = parseBoth("--out", "frames/a.exr");
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.render.outExr, "frames/a.exr");
    EXPECT_TRUE(parse({"render", "--out", "A.EXR"}).error.empty());
    expectBadValue("--out", "x.png", "a .exr file name");
    expectBadValue("--out", "dir/.exr", "a .exr file name");
    expectBadValue("--out", "exr", "a .exr file name");
    expectError({"render", "--out"}, "--out: missing value");
    expectError({"render", "--out="}, "--out: missing value");
    expectError({"render", "--out", "--width", "5"}, "--out: missing value");
}

TEST(Cli, Png) {
    ParseResult r = parseBoth("--png", "prev/a.png");
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.render.outPng, "prev/a.png");
    r = parseBoth("--png", "none");
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.render.outPng, "none");
    expectBadValue("--png", "a.exr", "a .png file name or 'none'");
    expectError({"render", "--png"}, "--png: missing value");
}

TEST(Cli, WidthAndHeight) {
    for (auto* opt : {"--width", "--height"}) {
        for (auto [text, value] : {std::pair{"1", 1u}, {"640", 640u}, {"16384", 16384u}}) {
            const ParseResult r = parseBoth(opt, text);
            ASSERT_TRUE(r.error.empty()) << r.error;
            EXPECT_EQ(std::string(opt) == "--width" ? r.render.settings.width : r.render.settings.height, value);
        }
        for (auto* bad : {"abc", "0", "16385", "-5", "12x", "1.5", "+5", " 5", "0x10",
                          "99999999999999999999999"})
            expectBadValue(opt, bad, "an integer in 1..16384");
        expectError({"render", opt}, std::string(opt) + ": missing value");
    }
    expectBadValue("--width", "abc", "an integer in 1..16384");
    EXPECT_EQ(parse({"render", "--width", "abc"}).error,
              "--width: expected an integer in 1..16384, got 'abc'");
}

TEST(Cli, Camera) {
    ParseResult r = parseBoth("--camera", "3");
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.render.settings.camera, 3);
    EXPECT_EQ(parse({"render", "--camera=0"}).render.settings.camera, 0);
    for (auto* bad : {"-1", "one", "2147483648", "1e2"})
        expectBadValue("--camera", bad, "an integer >= 0");
    expectError({"render", "--camera"}, "--camera: missing value");
}

TEST(Cli, Exposure) {
    for (auto [text, value] : {std::pair{"0", 0.0f}, {"1.5", 1.5f}, {"-2", -2.0f}, {"+3", 3.0f},
                               {"20", 20.0f}, {"-20", -20.0f}, {"1e1", 10.0f}}) {
        const ParseResult r = parseBoth("--exposure", text);
        ASSERT_TRUE(r.error.empty()) << text << ": " << r.error;
        EXPECT_EQ(r.render.exposure, value) << text;
    }
    for (auto* bad : {"bright", "20.5", "-21", "nan", "inf", "1.5ev", "++1", "."})
        expectBadValue("--exposure", bad, "a number in -20..20 (EV)");
    expectError({"render", "--exposure"}, "--exposure: missing value");
}

TEST(Cli, MetricsAndDevice) {
    ParseResult r = parseBoth("--metrics", "out/m.json");
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.render.metricsPath, "out/m.json");
    r = parseBoth("--device", "NVIDIA H100");
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.render.device, "NVIDIA H100");
    r = parse({"render", "--device=llvmpipe"});
    EXPECT_EQ(r.render.device, "llvmpipe");
    expectError({"render", "--metrics"}, "--metrics: missing value");
    expectError({"render", "--device"}, "--device: missing value");
    expectError({"render", "--device="}, "--device: missing value");
}

TEST(Cli, Flags) {
    ParseResult r = parse({"render", "--validate", "--quiet"});
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_TRUE(r.render.validate);
    EXPECT_TRUE(r.render.quiet);
    expectError({"render", "--quiet=yes"}, "--quiet: takes no value, got 'yes'");
    expectError({"render", "--validate=1"}, "--validate: takes no value, got '1'");
    // A flag never swallows the next argument.
    r = parse({"render", "--quiet", "scene.gltf"});
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.render.scene, "scene.gltf");
}

TEST(Cli, ShadowMap) {
    for (auto [text, value] : {std::pair{"256", 256u}, {"1024", 1024u}, {"8192", 8192u}}) {
        const ParseResult r = parseBoth("--shadow-map", text);
        ASSERT_TRUE(r.error.empty()) << r.error;
        EXPECT_EQ(r.render.settings.shadowMapSize, value);
    }
    for (auto* bad : {"1000", "128", "16384", "0", "big", "-1024"})
        expectBadValue("--shadow-map", bad, "a power of two in 256..8192");
    expectError({"render", "--shadow-map"}, "--shadow-map: missing value");
}

TEST(Cli, Supersample) {
    for (auto [text, value] : {std::pair{"1", 1u}, {"4", 4u}, {"8", 8u}}) {
        const ParseResult r = parseBoth("--supersample", text);
        ASSERT_TRUE(r.error.empty()) << r.error;
        EXPECT_EQ(r.render.settings.supersample, value);
    }
    for (auto* bad : {"0", "9", "2.0", "x"})
        expectBadValue("--supersample", bad, "an integer in 1..8");
    expectError({"render", "--supersample"}, "--supersample: missing value");
}

TEST(Cli, EverythingTogether) {
    const ParseResult r = parse({"render", "s.gltf", "--out=o/f.exr", "--png", "none", "--width",
                                 "320", "--height=200", "--camera", "1", "--exposure=-1.5",
                                 "--metrics", "m.json", "--device", "lavapipe", "--validate",
                                 "--shadow-map=4096", "--supersample", "2", "--quiet"});
    ASSERT_TRUE(r.error.empty()) << r.error;
    const RenderOptions& o = r.render;
    EXPECT_EQ(o.scene, "s.gltf");
    EXPECT_EQ(o.outExr, "o/f.exr");
    EXPECT_EQ(o.outPng, "none");
    EXPECT_EQ(o.settings.width, 320u);
    EXPECT_EQ(o.settings.height, 200u);
    EXPECT_EQ(o.settings.camera, 1);
    EXPECT_EQ(o.exposure, -1.5f);
    EXPECT_EQ(o.metricsPath, "m.json");
    EXPECT_EQ(o.device, "lavapipe");
    EXPECT_TRUE(o.validate);
    EXPECT_EQ(o.settings.shadowMapSize, 4096u);
    EXPECT_EQ(o.settings.supersample, 2u);
    EXPECT_TRUE(o.quiet);
}

TEST(Cli, LaterOptionWins) {
    const ParseResult r = parse({"render", "--width", "10", "--width=20"});
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.render.settings.width, 20u);
}

TEST(Cli, UsageDocumentsEveryOption) {
    const std::string u = usageText();
    for (auto* s : {"render", "view", "bench", "--version", "--out", "--png", "--width",
                    "--height", "--camera", "--exposure", "--metrics", "--device", "--validate",
                    "--shadow-map", "--supersample", "--quiet", "--help", "out/render.exr",
                    "512", "2048", "W.m^-2.sr^-1", "PNG preview only", "256..8192", "1..8",
                    "1..16384", "-20..20", "box-average"})
        EXPECT_NE(u.find(s), std::string::npos) << "usage lacks '" << s << "'";
}

TEST(Cli, ConeClearance) {
    EXPECT_EQ(parse({"render"}).render.settings.cones.clearance, 3.0f);
    for (auto [text, value] : {std::pair{"0", 0.0f}, {"2", 2.0f}, {"3.5", 3.5f}, {"8", 8.0f}}) {
        const ParseResult r = parseBoth("--cone-clearance", text);
        ASSERT_TRUE(r.error.empty()) << text << ": " << r.error;
        EXPECT_EQ(r.render.settings.cones.clearance, value) << text;
    }
    for (auto* bad : {"-1", "9", "wide", "nan"})
        expectBadValue("--cone-clearance", bad, "a number in 0..8 (0 = off)");
    EXPECT_NE(usageText().find("--cone-clearance"), std::string::npos);
}

TEST(Cli, Soak) {
    const ParseResult d = parse({"soak"});
    ASSERT_TRUE(d.error.empty()) << d.error;
    EXPECT_EQ(d.command, Command::Soak);
    EXPECT_EQ(d.render.soakFrames, 10000u);
    EXPECT_EQ(d.render.soakEvery, 100u);
    EXPECT_EQ(d.render.soakOut, "out/soak.json");
    EXPECT_EQ(d.render.soakMaxGrowth, 1.0f);
    const ParseResult r = parse({"soak", "--soak-frames", "200", "--soak-every=20", "--soak-out", "x/s.json",
                                 "--soak-max-growth", "0.5", "--voxels", "32"});
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.render.soakFrames, 200u);
    EXPECT_EQ(r.render.soakEvery, 20u);
    EXPECT_EQ(r.render.soakOut, "x/s.json");
    EXPECT_EQ(r.render.soakMaxGrowth, 0.5f);
    EXPECT_EQ(r.render.settings.voxels, 32u);
    expectError({"soak", "--soak-frames", "0"}, "--soak-frames: expected an integer >= 1, got '0'");
    expectError({"soak", "--soak-every", "-3"}, "--soak-every: expected an integer >= 1, got '-3'");
    expectError({"soak", "--soak-out", "soak.txt"}, "--soak-out: expected a .json file name, got 'soak.txt'");
    expectError({"soak", "--soak-max-growth", "nan"},
                "--soak-max-growth: expected a percentage in 0..1000, got 'nan'");
    expectError({"render", "--soak-frames", "5"},
                "--soak-frames: an option of dvsgi soak, not of dvsgi render (see dvsgi --help)");
    const std::string u = usageText();
    for (auto* s : {"dvsgi soak", "--soak-frames", "--soak-every", "--soak-out", "--soak-max-growth"})
        EXPECT_NE(u.find(s), std::string::npos) << "usage lacks '" << s << "'";
}
