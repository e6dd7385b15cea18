// Settings of the voxel light passes (paper sections VI, VII, IX): how light
// reaches the voxels (inject.h), and how the bounces are iterated (bounce.h).
#pragma once

#include <cstdint>

#include "shared/voxel_data.h"

namespace dvsgi::vxgi {

enum class Occlusion : uint32_t {
    ShadowMap = shader::OCCLUSION_SHADOW_MAP,
    RaycastHard = shader::OCCLUSION_RAYCAST_HARD,
    RaycastSoft = shader::OCCLUSION_RAYCAST_SOFT,
    None = shader::OCCLUSION_NONE,
    PerLight = shader::OCCLUSION_PER_LIGHT,
};

// How the voxel bounces are iterated.
enum class BounceMode {
    Fixed,     // exactly `bounces` bounces every frame (the paper: 1)
    Converge,  // the first frame iterates until the relative change of voxel radiance
               // falls below `convergence` (at most `maxBounces`), later frames feed back
    Feedback,  // one bounce per frame reading the previous frame's filtered radiance
};

// How the voxel bounce gathers each voxel's incoming light.
enum class BounceTrace {
    Cones,  // six cones through the filtered directional volumes (the paper)
    Rays,   // rays marched voxel by voxel through the radiance volume (bounce.h)
};

struct VoxelLightSettings {
    // Paper eq. 5 (W = N^2) reads a plane at 45 degrees to the axes, lit head on, at 71 % of its
    // light (58 % along a diagonal): off by default, Lambert N.L with the averaged normal (eq. 2),
    // exact for a voxel holding one plane at any orientation (docs/quality.md, "Walls at an angle").
    bool normalWeighted = false;
    Occlusion occlusion = Occlusion::PerLight;  // global override of each light's mode
    float softKappa = 0.5f;               // soft raycast: nu += (1 - nu) * kappa / t
    float shadowNormalOffset = 1.5f;      // texels
    bool emissionInRadiance = true;       // the Renderer sets it: false when emitters are lit as area lights
    bool keepSideReflection = false;      // the Renderer sets it: true on feedback frames (shared/inject_pass.h)
    bool keepStaticRadiance = false;      // the Renderer sets it: a feedback frame's rays read last frame's light
    BounceMode bounceMode = BounceMode::Converge;
    uint32_t bounces = 1;                 // Fixed: bounces per frame (0 = direct only)
    float convergence = 0.005f;           // Converge: stop when the light still missing, over the voxels' reflected light, is below this
    uint32_t maxBounces = 64;             // Converge: give up (and say so) after this many
    // The bounce's cones march with the shared settings but this step factor
    // (bounceCones()): beta = 1 costs half of 0.5 and changes the converged
    // indirect light by 1.8 % (docs/quality.md).
    float bounceStepFactor = 1.0f;
    // Rays by default: no light through walls, a closed room keeps all of it
    // (docs/quality.md, "The voxel bounce by rays"). Eight rays score as
    // sixteen on the Cornell box at 128^3 and cost about what the cones do.
    BounceTrace bounceTrace = BounceTrace::Rays;
    uint32_t bounceRays = 8;  // Rays: per voxel (a two-sided voxel's other side: a quarter, at least 4)
    // Feedback frames: weight of this frame's bounced radiance against what
    // the same voxel had after last frame's (1 = no blending). Dropped, so
    // the new value is taken as it is, when lights, static geometry or
    // settings change and for voxels that were not there last frame.
    float temporalAlpha = 1.0f;
    // The directional volumes show a one-sided voxel's light only to rays that
    // meet its front (aniso_filter.comp, seenFront); off: every way, as the
    // paper filters (docs/quality.md, "A voxel seen from behind").
    bool backsDark = true;
    // Edge and corner voxels as their faces (--edge-voxels faces): rays pass
    // beside the part of a voxel its surface does not reach, and an edge
    // voxel is lit and seen per axis face. With Lambert only (normalWeighted
    // off). Off by default: it brings the Cornell box to its reference, but
    // Sponza under the sun comes out 9 % brighter over placements of the grid
    // at 128^3 (docs/quality.md, "--edge-voxels faces").
    bool edgeFaces = false;
};

// Whether edge voxels are lit and shown as their faces with these settings.
inline bool edgeFacesLit(const VoxelLightSettings& s) { return s.edgeFaces && !s.normalWeighted; }

}  // namespace dvsgi::vxgi
