// Turns a GPU failure into the one stderr line the user sees: for an
// allocation that failed, the setting that sized it (--voxels, --shadow-map,
// --width/--height/--supersample, the scene), what it needed and what the
// device offers. docs/RELIABILITY.md, "Device faults".
#pragma once

#include <string>

#include "gpu/check.h"
#include "options.h"

namespace dvsgi::app {

std::string describeGpuError(const gpu::GpuError& error, const RenderOptions& options);

// 1.2 GiB, 832 MiB, 64 KiB: sizes in messages and reports.
std::string formatBytes(double bytes);

}  // namespace dvsgi::app
