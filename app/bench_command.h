// `dvsgi bench`: time the frame passes over a suite of scenes and voxel
// resolutions (by default the paper's Table II: Cornell box, Sibenik and Crytek
// Sponza with the Stanford bunny moving through them, at 128^3 and 256^3), and
// write the per-pass median/min/max GPU times as JSON plus a markdown table.
// docs/benchmarks.md describes the output.
#pragma once

#include "options.h"

namespace dvsgi::app {

// Without --width/--height (RenderOptions::given) the images are 640x360.
// Returns the process exit code: 0 when at least one measurement succeeded,
// 1 when none did, 3 when the validation layer reported errors.
int runBench(const RenderOptions& options);

}  // namespace dvsgi::app
