// `dvsgi bench`: time the frame passes over a suite of scenes and voxel
// resolutions (by default the paper's Table II: Cornell box, Sibenik and Crytek
// Sponza with the Stanford bunny moving through them, at 128^3 and 256^3), and
// write the per-pass median/min/max GPU times as JSON plus a markdown table.
// docs/benchmarks.md describes the output.
#pragma once

#include "options.h"

namespace dvsgi::app {

// argv is the full command line: it is recorded in the JSON, and tells whether
// --width/--height were given (otherwise the bench uses 640x360).
// Returns the process exit code: 0 when at least one measurement succeeded,
// 1 when none did, 3 when the validation layer reported errors.
int runBench(const RenderOptions& options, int argc, const char* const* argv);

}  // namespace dvsgi::app
