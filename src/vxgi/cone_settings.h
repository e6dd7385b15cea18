// How a cone marches through the filtered voxel volumes: one description for
// the per-pixel gather, the voxel bounce and the shadow cones, and its one GPU
// form (shader::ConeParams) built in one place.
#pragma once

#include <cstdint>

#include "shared/voxel_data.h"
#include "vxgi/volumes.h"

namespace dvsgi::vxgi {

struct ConeSettings {
    uint32_t coneSet = shader::CONE_SET_6;  // diffuse aperture set: the paper's 6 or 16 cones
    float stepFactor = 0.5f;       // beta: step = beta * cone diameter
    float minStepVoxels = 0.5f;    // floor of the step
    float maxDistance = 0.0f;      // metres; 0 = the grid's diagonal
    float offsetVoxels = 2.5f;     // origin lifted along the normal: clears the 2-voxel directional
                                   // cells' trilinear footprint at a pixel
    float firstSampleVoxels = 1.0f;
    float clearance = shader::CONE_CLEARANCE_DEFAULT;  // K of traceConeAO (0 = plain diameter rule)
};

// The bounce traces N^3 voxels' cones, so it takes the shared settings with its
// own step factor, the six-cone set, and an origin two voxels off the voxel's
// centre: the nearest point outside the two-voxel directional cell that holds
// the voxel, whichever of its two voxels that is (one voxel left the origin in
// its own wall's cell, and grazing cones lit the wall with itself: an open box
// carried 5.7 % more light per bounce than its view factors, converged +15 %).
ConeSettings bounceCones(const ConeSettings& shared, float bounceStepFactor);

// The GPU form: the maximum distance resolved to metres on `grid`.
shader::ConeParams gpuCone(const ConeSettings& c, const GridSpec& grid);

}  // namespace dvsgi::vxgi
