// The one settings table of the dvsgi executable (issue #10, part 2). Each
// entry names a setting once and from it come the command line (app/cli.cpp,
// CLI11), --help (app/cli_help.cpp), the JSON that render and bench write, and
// the viewer's panel (app/view_panel_settings.cpp). Defaults are not stored
// here: they are read through the binding from a default RenderOptions, whose
// renderer part is render::RenderSettings with the library's initialisers.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "options.h"

namespace dvsgi::app {

// Which commands take a setting (bits).
enum CommandMask : uint32_t { kRender = 1, kView = 2, kBench = 4, kSoak = 8, kAll = kRender | kView | kBench | kSoak };

// What a change needs when the program is already running (the viewer).
enum class Apply {
    NextFrame,    // a renderer setting Renderer::applySettings takes from the next frame
    NewRenderer,  // a renderer setting that needs new resources (render::needsNewRenderer)
    Viewer,       // the application's, read every frame (exposure, time step)
    Startup,      // the application's, read once (files, device, scene edits)
};

// How the value is spelled, and which widget the panel draws for it.
enum class Kind {
    Flag,        // no value: given = on
    Toggle,      // on|off
    Integer,     // [lo, hi], optionally a power of two (pow2) and/or 0
    Number,      // real in [lo, hi]
    Choice,      // one of `choices`
    Text,        // a string (file name, device name)
    Special,     // its own syntax (auto|K, a box, NAME=mode, lists); the panel draws it by name
};

struct Setting {
    std::string name;      // the flag without "--", the JSON key, the prefix of library errors
    std::string group;     // --help section and panel header
    Kind kind = Kind::Text;
    std::string metavar;   // what --help shows after the flag ("N", "FILE.exr")
    double lo = 0.0, hi = 0.0;  // Integer and Number
    bool pow2 = false;     // Integer: a power of two in [lo, hi] (or 0 when zeroOk)
    bool zeroOk = false;
    std::vector<std::string> choices;  // Choice (and Toggle: on, off)
    std::string unit;      // "px", "voxels", "m", "degrees", "EV", "s"
    std::string help;
    uint32_t commands = kAll;
    Apply apply = Apply::Startup;
    bool repeatable = false;  // each occurrence adds (NAME=mode, node names)
    std::string expected;  // the parse error's "expected ..." text
    std::string example;   // a valid value other than the default (tests parse it)
    std::string unset;     // what the default means when it is "not set" (empty, or 0 outside the range)

    // The binding. parse returns false for a bad value (the caller names the
    // flag and `expected`); text gives the value as the command line spells it.
    std::function<bool(RenderOptions&, std::string_view)> parse;
    std::function<std::string(const RenderOptions&)> text;
    std::function<nlohmann::json(const RenderOptions&)> json;
    // Integer and Number: the value as a number, for the panel's sliders.
    std::function<double(const RenderOptions&)> number;
    std::function<void(RenderOptions&, double)> setNumber;

    bool takesValue() const { return kind != Kind::Flag; }
    bool renderer() const { return apply == Apply::NextFrame || apply == Apply::NewRenderer; }
    std::string range() const;  // "1..16384", "0 or a power of two in 32..512", "float|half", ""
};

const std::vector<Setting>& settingsTable();
const Setting* findSetting(std::string_view name);

// --help groups in order, with an optional paragraph under the heading.
struct SettingGroup {
    std::string name;
    std::string intro;
};
const std::vector<SettingGroup>& settingGroups();

// Every setting `command` takes (kRender, kView, kBench or kSoak), name -> value.
nlohmann::json settingsJson(const RenderOptions& options, uint32_t command);

// A library message that starts with a setting's name ("voxels: ...") gets
// the flag instead ("--voxels: ..."); anything else is returned unchanged.
std::string withFlagNames(const std::string& message);

}  // namespace dvsgi::app
