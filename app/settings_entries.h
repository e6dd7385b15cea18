// What the two files of the settings table's entries share
// (settings_entries.cpp: output, image, scene and device, voxels, voxel light,
// and the table itself; settings_entries_commands.cpp: cone tracing, temporal
// filtering, animation and the commands' own settings). Internal to them.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "settings_kinds.h"

namespace dvsgi::app::entries {

#define FIELD(expr) [](RenderOptions & o) -> auto& { return o.expr; }

inline constexpr const char* kOutput = "Output";
inline constexpr const char* kImage = "Image";
inline constexpr const char* kSceneDevice = "Scene and device";
inline constexpr const char* kVoxels = "Voxels";
inline constexpr const char* kVoxelLight = "Voxel light";
inline constexpr const char* kCones = "Cone tracing and composition";
inline constexpr const char* kAnimation = "Animation and dynamic objects";
inline constexpr const char* kViewerGroup = "Viewer (dvsgi view)";
inline constexpr const char* kBenchGroup = "Benchmark (dvsgi bench)";
inline constexpr const char* kSoakGroup = "Soak (dvsgi soak)";

inline constexpr Apply kFrame = Apply::NextFrame;
inline constexpr Apply kNew = Apply::NewRenderer;

inline Setting with(Setting s, std::string example, std::string expected = "") {
    s.example = std::move(example);
    if (!expected.empty()) s.expected = std::move(expected);
    return s;
}

// An entry whose default means "not set": `unset` says what happens then.
inline Setting unset(Setting s, std::string meaning) {
    s.unset = std::move(meaning);
    return s;
}

// Output, image, scene and device, voxels, voxel light (settings_entries.cpp).
std::vector<Setting> imageAndVoxels();
// Cone tracing, animation, and the viewer's, the bench's and the soak's own
// settings (settings_entries_commands.cpp).
std::vector<Setting> conesAndCommands();

}  // namespace dvsgi::app::entries
