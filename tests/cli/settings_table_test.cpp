// The settings table (app/settings_table.h): its entries are consistent, the
// command line it generates sets the library's structs, --help and the JSON
// name every setting, and its 'next frame' / 'new renderer' column agrees
// with what the renderer itself decides (render::needsNewRenderer).
#include "settings_kinds.h"
#include "settings_table.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

using namespace dvsgi;
using namespace dvsgi::app;

namespace {

ParseResult parse(std::vector<const char*> args) {
    args.insert(args.begin(), "dvsgi");
    return parseCommandLine(int(args.size()), args.data());
}

const std::vector<std::string> kCommands = {"render", "view", "bench"};

uint32_t maskOf(const std::string& command) {
    return command == "render" ? kRender : command == "view" ? kView : kBench;
}

}  // namespace

TEST(CliSettingsTable, NamesUniqueHelpAndGroupsPresent) {
    std::set<std::string> names, groups;
    for (const SettingGroup& g : settingGroups()) groups.insert(g.name);
    for (const Setting& s : settingsTable()) {
        EXPECT_TRUE(names.insert(s.name).second) << "duplicate " << s.name;
        EXPECT_FALSE(s.name.empty());
        EXPECT_EQ(s.name.find_first_of(" =_"), std::string::npos) << s.name;
        EXPECT_FALSE(s.help.empty()) << s.name;
        EXPECT_TRUE(groups.count(s.group)) << s.name << " in unknown group " << s.group;
        EXPECT_NE(s.commands & kAll, 0u) << s.name;
        EXPECT_TRUE(s.parse && s.text && s.json) << s.name;
        if (s.takesValue()) {
            EXPECT_FALSE(s.metavar.empty()) << s.name;
        }
        if (s.kind != Kind::Text && s.kind != Kind::Flag && s.name != "dynamic") {
            EXPECT_FALSE(s.expected.empty()) << s.name;
        }
        if (s.kind == Kind::Integer || s.kind == Kind::Number) {
            EXPECT_LT(s.lo, s.hi) << s.name;
            EXPECT_TRUE(s.number && s.setNumber) << s.name;
        }
    }
    EXPECT_GT(names.size(), 50u);
}

// --help prints each number's range; both ends, as printed, are accepted
// (--bounce-convergence 0.00001 was refused: its float is below the double 1e-5).
TEST(CliSettingsTable, BothEndsOfEveryPrintedRangeAreAccepted) {
    for (const Setting& s : settingsTable()) {
        if ((s.kind != Kind::Integer && s.kind != Kind::Number) || s.hi >= 1e6) continue;
        for (const double end : {s.lo, s.hi}) {
            if (s.pow2 && (uint64_t(end) & (uint64_t(end) - 1)) != 0) continue;
            RenderOptions o;
            const std::string text = table::formatNumber(end);
            EXPECT_TRUE(s.parse(o, text)) << "--" << s.name << " " << text;
        }
    }
}

TEST(CliSettingsTable, EveryDefaultIsInsideItsRange) {
    const RenderOptions defaults;
    for (const Setting& s : settingsTable()) {
        if (!s.unset.empty()) continue;  // a documented "not set" value
        const std::string text = s.text(defaults);
        switch (s.kind) {
            case Kind::Integer:
            case Kind::Number: {
                const double v = s.number(defaults);
                EXPECT_TRUE((s.lo <= v && v <= s.hi) || (s.zeroOk && v == 0.0)) << s.name << " = " << v;
                if (s.pow2 && v != 0.0) {
                    EXPECT_EQ(uint64_t(v) & (uint64_t(v) - 1), 0u) << s.name;
                }
                break;
            }
            case Kind::Toggle:
            case Kind::Choice:
                EXPECT_NE(std::find(s.choices.begin(), s.choices.end(), text), s.choices.end())
                    << s.name << " = " << text;
                break;
            default: break;
        }
        // The default, spelled as the command line spells it, parses back to itself.
        if (s.kind != Kind::Flag && !s.repeatable && !text.empty() && s.kind != Kind::Special) {
            RenderOptions o;
            ASSERT_TRUE(s.parse(o, text)) << s.name << " " << text;
            EXPECT_EQ(s.text(o), text) << s.name;
        }
    }
}

TEST(CliSettingsTable, EveryExampleParsesToAnotherValue) {
    const RenderOptions defaults;
    for (const Setting& s : settingsTable()) {
        RenderOptions o;
        ASSERT_FALSE(s.example.empty()) << s.name;
        ASSERT_TRUE(s.parse(o, s.example)) << s.name << " " << s.example;
        EXPECT_NE(s.json(o), s.json(defaults)) << s.name << ": the example is the default";
        // On the command line too, for every command that takes it.
        for (const std::string& cmd : kCommands) {
            if (!(s.commands & maskOf(cmd))) continue;
            const std::string flag = "--" + s.name;
            const ParseResult r = s.takesValue() ? parse({cmd.c_str(), flag.c_str(), s.example.c_str()})
                                                 : parse({cmd.c_str(), flag.c_str()});
            ASSERT_TRUE(r.error.empty()) << r.error;
            EXPECT_EQ(s.json(r.render), s.json(o)) << cmd << " " << s.name;
            EXPECT_TRUE(r.render.isGiven(s.name)) << s.name;
        }
    }
}

// What the table says about a change (next frame or new renderer) is what
// the renderer does with it.
TEST(CliSettingsTable, ApplyColumnAgreesWithTheRenderer) {
    const RenderOptions defaults;
    int checked = 0;
    for (const Setting& s : settingsTable()) {
        if (!s.renderer()) continue;
        RenderOptions o;
        ASSERT_TRUE(s.parse(o, s.example)) << s.name;
        EXPECT_EQ(render::needsNewRenderer(defaults.settings, o.settings), s.apply == Apply::NewRenderer) << s.name;
        ++checked;
    }
    EXPECT_GT(checked, 30);
}

TEST(CliSettingsTable, CommandLineSetsTheLibraryStructs) {
    const ParseResult r = parse({"render", "--cone-step", "1.5", "--cone-offset=1", "--bounce-step", "0.25",
                                 "--bounces", "3", "--voxel-box", "-1,-2,-3,1,2,3", "--light-occlusion", "sun=soft",
                                 "--light-occlusion", "lamp=none", "--shadows", "cone", "--shadow-aperture", "10",
                                 "--view", "voxels:directional", "--view-direction", "+z", "--voxel-occlusion",
                                 "raycast", "--output", "ao", "--cones", "16", "--conservative", "gs",
                                 "--emitters", "cones", "--min-specular-angle", "2"});
    ASSERT_TRUE(r.error.empty()) << r.error;
    const render::RenderSettings& rs = r.render.settings;
    EXPECT_EQ(rs.cones.stepFactor, 1.5f);
    EXPECT_EQ(rs.cones.offsetVoxels, 1.0f);
    EXPECT_EQ(rs.voxelLight.bounceStepFactor, 0.25f);
    EXPECT_EQ(rs.voxelLight.bounceMode, vxgi::BounceMode::Fixed);
    EXPECT_EQ(rs.voxelLight.bounces, 3u);
    EXPECT_TRUE(rs.hasVoxelBox);
    EXPECT_EQ(rs.voxelBoxMin, glm::vec3(-1, -2, -3));
    EXPECT_EQ(rs.voxelBoxMax, glm::vec3(1, 2, 3));
    ASSERT_EQ(rs.lightOcclusion.size(), 2u);
    EXPECT_EQ(rs.lightOcclusion[0], std::make_pair(std::string("sun"), vxgi::Occlusion::RaycastSoft));
    EXPECT_EQ(rs.lightOcclusion[1], std::make_pair(std::string("lamp"), vxgi::Occlusion::None));
    EXPECT_TRUE(rs.shadowCones.enabled);
    EXPECT_EQ(rs.shadowCones.apertureDegrees, 10.0f);
    EXPECT_EQ(rs.view.mode, render::ViewMode::VoxelDirectional);
    EXPECT_EQ(rs.view.direction, 5u);
    EXPECT_EQ(rs.voxelLight.occlusion, vxgi::Occlusion::RaycastHard);
    EXPECT_EQ(rs.outputTerm, 4u);
    EXPECT_EQ(rs.cones.coneSet, 16u);
    EXPECT_FALSE(rs.hardwareConservative);
    EXPECT_FALSE(rs.emitterLights);
    EXPECT_EQ(rs.gather.minSpecularDegrees, 2.0f);
    // "auto" after a count goes back to converging.
    EXPECT_EQ(parse({"render", "--bounces", "3", "--bounces=auto"}).render.settings.voxelLight.bounceMode,
              vxgi::BounceMode::Converge);
}

TEST(CliSettingsTable, DefaultsAreTheLibrarysOwn) {
    const ParseResult r = parse({"render"});
    ASSERT_TRUE(r.error.empty()) << r.error;
    RenderOptions library;
    library.settings = render::RenderSettings{};
    EXPECT_EQ(settingsJson(r.render, kAll), settingsJson(library, kAll));
    EXPECT_TRUE(r.render.given.empty());
}

// --help with every run of white space as one space, as it reads unwrapped.
std::string flatHelp() {
    std::string flat;
    for (char c : usageText()) {
        const bool space = c == ' ' || c == '\n';
        if (!(space && !flat.empty() && flat.back() == ' ')) flat += space ? ' ' : c;
    }
    return flat;
}

TEST(CliSettingsTable, HelpNamesEveryFlagWithItsRangeAndDefault) {
    const std::string help = flatHelp();
    const RenderOptions defaults;
    // Each entry's text runs to the next entry's heading (the table's order is --help's).
    std::vector<size_t> heads;
    for (const Setting& s : settingsTable()) {
        heads.push_back(help.find(" --" + s.name + (s.metavar.empty() ? "" : " " + s.metavar) + " "));
        ASSERT_NE(heads.back(), std::string::npos) << s.name;
        if (heads.size() > 1) {
            ASSERT_GT(heads.back(), heads[heads.size() - 2]) << s.name;
        }
    }
    heads.push_back(help.size());
    for (size_t i = 0; i < settingsTable().size(); ++i) {
        const Setting& s = settingsTable()[i];
        const std::string entry = help.substr(heads[i], heads[i + 1] - heads[i]);
        const std::string def = !s.unset.empty() ? "default: " + s.unset
                                : s.kind == Kind::Flag ? "default off"
                                                       : "default " + s.text(defaults);
        EXPECT_NE(entry.find(def), std::string::npos) << s.name << ": " << entry;
        EXPECT_NE(entry.find(s.help.substr(0, 20)), std::string::npos) << s.name;
        if (s.kind == Kind::Integer || s.kind == Kind::Number) {
            EXPECT_NE(entry.find(s.range() + (s.unit.empty() || s.unit == "EV" ? "" : " " + s.unit)),
                      std::string::npos)
                << s.name << ": " << entry;
        }
    }
    for (const SettingGroup& g : settingGroups()) EXPECT_NE(help.find(" " + g.name + ": "), std::string::npos);
}

TEST(CliSettingsTable, JsonRecordsEverySettingOfTheCommand) {
    ParseResult r = parse({"bench", "--width", "64", "--bench-voxels", "32,64", "--bounces", "2"});
    ASSERT_TRUE(r.error.empty()) << r.error;
    const nlohmann::json j = settingsJson(r.render, kBench);
    for (const Setting& s : settingsTable()) EXPECT_EQ(j.contains(s.name), bool(s.commands & kBench)) << s.name;
    EXPECT_EQ(j["width"], 64);
    EXPECT_EQ(j["bench-voxels"], nlohmann::json({32, 64}));
    EXPECT_EQ(j["bounces"], 2);
    EXPECT_EQ(j["cones"], 6);
    EXPECT_EQ(j["output"], "full");
    EXPECT_EQ(j["specular"], true);
    EXPECT_EQ(j["voxel-box"], nullptr);
    EXPECT_FALSE(j.contains("out"));
    EXPECT_EQ(settingsJson(RenderOptions{}, kRender)["bounces"], "auto");
    EXPECT_EQ(settingsJson(RenderOptions{}, kRender)["out"], "out/render.exr");
}

TEST(CliSettingsTable, LibraryMessagesGetFlags) {
    EXPECT_EQ(withFlagNames("voxels: 1024^3 needs 3D images"), "--voxels: 1024^3 needs 3D images");
    EXPECT_EQ(withFlagNames("camera: 7 is out of range"), "--camera: 7 is out of range");
    EXPECT_EQ(withFlagNames("light-occlusion: no light named 'x'"), "--light-occlusion: no light named 'x'");
    EXPECT_EQ(withFlagNames("scene.gltf: not found"), "scene.gltf: not found");
    EXPECT_EQ(withFlagNames("no Vulkan device"), "no Vulkan device");
}

TEST(CliSettingsTable, OptionsOfAnotherCommandAreRefused) {
    EXPECT_EQ(parse({"render", "--bench-out", "b.json"}).error,
              "--bench-out: an option of dvsgi bench, not of dvsgi render (see dvsgi --help)");
    EXPECT_EQ(parse({"bench", "--vsync", "off"}).error,
              "--vsync: an option of dvsgi view, not of dvsgi bench (see dvsgi --help)");
    EXPECT_EQ(parse({"view", "--out=a.exr"}).error,
              "--out: an option of dvsgi render, not of dvsgi view (see dvsgi --help)");
    EXPECT_TRUE(parse({"view", "--exposure", "-2", "--vsync", "off"}).error.empty());
}
