// Command-line options of the dvsgi executable, as plain data. app/cli.cpp
// parses argv into these through the settings table (app/settings_table.h);
// nothing else in the program reads argv.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "render/renderer.h"

namespace dvsgi::app {

enum class Command { Render, View, Bench, Soak, Help, Version };

// Everything `dvsgi render`, `view` and `bench` accept. The renderer's settings
// are the library's own struct, so their defaults are its member initialisers;
// the rest are the application's, with their defaults here.
struct RenderOptions {
    std::string scene;            // empty = built-in Cornell box
    render::RenderSettings settings;

    bool allowOutsideReferences = false;  // files a scene names may lie outside its folder
    std::string outExr = "out/render.exr";
    std::string outPng;           // empty = outExr with .png; "none" = no preview
    float exposure = 0.0f;        // EV applied to the PNG preview (and the viewer) only
    std::string metricsPath;      // empty = no metrics JSON
    std::string device;           // substring of the device name; empty = best
    bool validate = false;        // Khronos validation layer
    bool quiet = false;           // no timing table on stdout
    std::string aovExr;           // multi-layer EXR of every term (--aov); empty = none
    std::string voxelDump;        // .npy table of the fitted grid's voxels (--voxel-dump); empty = none
    bool exrHalf = false;         // --exr-type half: --out and --aov store HALF samples
    uint32_t gridSamples = 1;     // renders on sub-voxel shifts of the grid, averaged (--grid-samples)

    // Animation and dynamic objects.
    uint32_t frames = 1;          // render frames 0..K-1, write the last (or each: '#' in --out)
    float timeStep = 1.0f / 30.0f;  // seconds between frames
    std::vector<std::string> dynamicNodes;  // node names marked dynamic
    std::string cameraPath;       // keyframes that drive the camera (scene/camera_path.h)
    std::string recordPath = "out/camera_path.json";  // dvsgi view: where K writes the recorded path
    std::string addModel;         // a model that moves on a circle through the scene (dynamic)
    float addModelSize = 0.0f;    // its largest extent in metres; 0 = 1/5 of the scene

    // `dvsgi view` only.
    uint32_t viewFrames = 0;      // close the window after K frames; 0 = run until closed
    std::string screenshot;       // EXR (+ PNG beside it) of the last frame when the window closes
    bool vsync = true;            // FIFO present mode (on) or IMMEDIATE/MAILBOX (off)

    // `dvsgi bench` only.
    std::string benchOut = "out/bench.json";
    std::string sharedDir = "../shared";     // holds scenes/ (the benchmark scenes)
    std::vector<uint32_t> benchVoxels = {128, 256};
    uint32_t benchFrames = 10;    // measured frames per (scene, voxel resolution)
    uint32_t benchWarmup = 2;     // frames rendered and discarded before those
    float benchMaxSeconds = 0.0f; // stop measuring a (scene, resolution) after this long; 0 = never
    bool benchQuick = false;      // Cornell box only, 32^3, 2 frames, 160x90
    bool benchTables = false;     // also the variants of the paper's Tables III and V
    bool pvTables = false;        // instead: the progressive-voxelization chapter's Tables 6.1 and 6.2
    std::string pvDoc;            // --pv-tables also writes them into this markdown file, between its markers

    // What the command line said, for commands whose defaults depend on it
    // (the bench's image size) and for the record (the bench JSON).
    std::vector<std::string> given;  // setting names that appeared on the command line
    std::string commandLine;         // argv, shell-quoted where needed
    bool isGiven(std::string_view name) const {
        return std::find(given.begin(), given.end(), name) != given.end();
    }

    // `dvsgi soak` only (app/soak_command.cpp); the other commands ignore these.
    uint32_t soakFrames = 10000;        // frames rendered in all
    uint32_t soakEvery = 100;           // settings change and a memory report every K frames
    std::string soakOut = "out/soak.json";
    float soakMaxGrowth = 1.0f;         // percent of RSS or device memory; more fails the run
};

struct ParseResult {
    Command command = Command::Help;
    RenderOptions render;
    std::string error;  // non-empty: one line naming the option, exit code 2
};

ParseResult parseCommandLine(int argc, const char* const* argv);
std::string usageText();  // the full --help text, generated from the settings table

}  // namespace dvsgi::app
