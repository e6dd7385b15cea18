// `dvsgi render`: load, render one frame headless, write EXR/PNG/metrics.
#pragma once

#include "options.h"

namespace dvsgi::app {

// Returns the process exit code. Errors are printed as one line on stderr.
int runRender(const RenderOptions& options);

}  // namespace dvsgi::app
