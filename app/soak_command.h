// `dvsgi soak`: many frames with a moving model, a moving light and settings
// that change every --soak-every frames (each change builds a new renderer),
// reporting host RSS and device memory; fails when either grows.
// docs/RELIABILITY.md, "Soak".
#pragma once

#include "options.h"

namespace dvsgi::app {

// Returns the process exit code: 0, 3 for validation errors, 4 for growth
// beyond --soak-max-growth. Other errors throw (one line in main).
int runSoak(const RenderOptions& options);

}  // namespace dvsgi::app
