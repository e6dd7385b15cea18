// Command-line options of the dvsgi executable, as plain data. app/cli.cpp parses
// argv into these; nothing else in the program reads argv.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace dvsgi::app {

enum class Command { Render, View, Bench, Soak, Help, Version };

enum class ViewKind { Final, VoxelAlbedo, VoxelNormal, VoxelEmission, VoxelRadiance, VoxelDirectional };

// Everything `dvsgi render` accepts. Defaults are the documented ones in --help.
struct RenderOptions {
    std::string scene;            // empty = built-in Cornell box
    bool allowOutsideReferences = false;  // files a scene names may lie outside its folder
    std::string outExr = "out/render.exr";
    std::string outPng;           // empty = outExr with .png; "none" = no preview
    uint32_t width = 512;
    uint32_t height = 512;
    int camera = 0;               // index among the scene's cameras
    float exposure = 0.0f;        // EV applied to the PNG preview only
    std::string metricsPath;      // empty = no metrics JSON
    std::string device;           // substring of the device name; empty = best
    bool validate = false;        // Khronos validation layer
    uint32_t shadowMapSize = 2048;
    uint32_t supersample = 1;     // k: render k*W x k*H and box-filter to W x H
    bool quiet = false;           // no timing table on stdout
    std::string aovExr;           // multi-layer EXR of every term (--aov); empty = none
    bool exrHalf = false;         // --exr-type half: --out and --aov store HALF samples

    // Voxels (issue #3).
    uint32_t voxels = 128;        // N of the N^3 grid, power of two 32..512; 0 = none
    bool hasVoxelBox = false;     // --voxel-box minx,miny,minz,maxx,maxy,maxz
    float voxelBox[6] = {0, 0, 0, 0, 0, 0};
    bool hardwareConservative = true;  // --conservative auto|gs
    ViewKind view = ViewKind::Final;
    uint32_t viewMip = 0;
    uint32_t viewDirection = 0;   // 0..5 = -X +X -Y +Y -Z +Z

    // Voxel light (issue #4).
    bool bouncesAuto = true;         // --bounces auto: converge (render) / feedback (view, later frames)
    uint32_t bounces = 1;            // --bounces K: exactly K bounces per frame
    float bounceConvergence = 0.005f;  // relative change of voxel radiance that ends converging
    uint32_t maxBounces = 64;        // converging gives up after this many bounces
    bool emitterLights = true;       // --emitters lights|cones
    uint32_t emitterPatches = 64;    // --emitter-patches N
    bool normalWeighted = true;      // eq. 5 (on) or Lambert N.L (off)
    std::string voxelOcclusion = "per-light";  // shadowmap|raycast|soft|none|per-light
    std::vector<std::pair<std::string, std::string>> lightOcclusion;  // NAME=mode
    float softKappa = 0.5f;

    // Cone tracing and composition (issue #5).
    uint32_t cones = 6;              // 6 (paper) or 16
    float coneStep = 0.5f;           // beta
    float coneMinStep = 0.5f;        // voxels
    float maxDistance = 0.0f;        // metres, 0 = grid diagonal
    float coneOffset = 2.5f;         // origin offset along the normal, voxels
    float coneClearance = 3.0f;      // K: sample cells at most (height over the surface - 1 voxel) / K
    float aoLambda = 0.5f;           // f(r) = 1/(1 + lambda r), r in voxels
    bool ao = false;                 // multiply indirect terms by AO in the composite
    bool specular = true;
    float minSpecularAngle = 1.0f;   // degrees, half-angle
    std::string shadows = "map";     // map | cone
    float shadowAperture = 5.0f;     // degrees, full angle of the shadow cone
    float traceScale = 1.0f;
    std::string output = "full";     // full|direct|indirect|specular|ao|shadow

    // Animation and dynamic objects.
    uint32_t frames = 1;          // render frames 0..K-1, write the last (or each: '#' in --out)
    float timeStep = 1.0f / 30.0f;  // seconds between frames
    std::vector<std::string> dynamicNodes;  // node names marked dynamic
    std::string addModel;         // a model that moves on a circle through the scene (dynamic)
    float addModelSize = 0.0f;    // its largest extent in metres; 0 = 1/5 of the scene

    // `dvsgi view` only (app/view_command.cpp); render and bench ignore these.
    uint32_t viewFrames = 0;      // close the window after K frames; 0 = run until closed
    std::string screenshot;       // EXR (+ PNG beside it) of the last frame when the window closes
    bool vsync = true;            // FIFO present mode (on) or IMMEDIATE/MAILBOX (off)

    // `dvsgi bench` only (app/bench_command.cpp); render and view ignore these.
    std::string benchOut = "out/bench.json";
    std::string sharedDir = "../shared";     // holds scenes/ (the benchmark scenes)
    std::vector<uint32_t> benchVoxels = {128, 256};
    uint32_t benchFrames = 10;    // measured frames per (scene, voxel resolution)
    uint32_t benchWarmup = 2;     // frames rendered and discarded before those
    float benchMaxSeconds = 0.0f; // stop measuring a (scene, resolution) after this long; 0 = never
    bool benchQuick = false;      // Cornell box only, 32^3, 2 frames, 160x90
    bool benchTables = false;     // also the variants of the paper's Tables III and V

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
std::string usageText();  // the full --help text

}  // namespace dvsgi::app
