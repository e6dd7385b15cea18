// Emissive surfaces as area lights. Cones that leave a surface rarely hit a
// small bright emitter, so its light is under-sampled however many bounces
// follow; instead the emissive triangles become patches that the voxel light
// and the per-pixel lighting evaluate like lights (irradiance with both
// cosines and a disk-shaped near field, visibility through the voxels).
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"
#include "shared/scene_data.h"

namespace dvsgi::render {

struct EmitterPatches {
    std::vector<shader::GpuLight> lights;  // LIGHT_AREA records
    bool complete = true;  // false: an emissive texture, which patches cannot carry (cones gather it instead)
};

// Patches of every emissive triangle of the scene's draw items: triangles are
// split along their longest edge until there are about `maxPatches`, or
// clustered on a grid when there are more triangles than that.
EmitterPatches emitterPatches(const scene::Scene& scene, const std::vector<scene::DrawItem>& items,
                              uint32_t maxPatches);

}  // namespace dvsgi::render
