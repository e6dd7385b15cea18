// `dvsgi bench --pv-tables`: the progressive-voxelization chapter's Tables 6.1
// (voxelization time) and 6.2 (average Hausdorff distance after orbits), as
// markdown on stdout and per-frame data in the bench JSON (docs/pv.md).
#pragma once

#include "options.h"

namespace dvsgi::app {

int runPvTables(const RenderOptions& options);

}  // namespace dvsgi::app
