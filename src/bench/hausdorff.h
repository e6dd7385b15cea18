// The voxelization accuracy figure of the progressive-voxelization chapter
// (seed 004, Table 6.2): the average Hausdorff distance between a mesh and the
// centres of its occupied voxels, on the CPU from dense surface samples.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace dvsgi::bench {

// `count` points on the scene's triangles (placed by their nodes), spread in
// proportion to area; deterministic (a fixed low-discrepancy sequence per
// triangle), so runs compare.
std::vector<glm::dvec3> surfaceSamples(const scene::Scene& scene, size_t count);

struct Hausdorff {
    double surfaceToVoxels = 0.0;  // mean over the samples of the distance to the nearest voxel centre
    double voxelsToSurface = 0.0;  // mean over the voxel centres of the distance to the nearest sample
    double average() const { return 0.5 * (surfaceToVoxels + voxelsToSurface); }
};

// Both one-sided mean distances (metres), by nearest-point searches in k-d
// trees. Either set empty: infinite distances.
Hausdorff averageHausdorff(const std::vector<glm::dvec3>& surface, const std::vector<glm::dvec3>& voxelCentres);

}  // namespace dvsgi::bench
