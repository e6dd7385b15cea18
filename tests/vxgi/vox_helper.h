// GPU voxelization of programmatic scenes for the voxelization tests, and the
// conversions that put the same triangles into the CPU reference's voxel space.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gpu/tracker.h"
#include "gpuscene/scene_gpu.h"
#include "sat.h"
#include "scene/scene.h"
#include "shared/voxel_data.h"
#include "vxgi/volumes.h"
#include "vxgi/voxel_list.h"
#include "vxgi/voxel_storage_io.h"
#include "vxgi/voxelize.h"

namespace dvsgi::test {

// The attribute sums read back per grid voxel: 13 slabs of N^3 floats stacked along z.
struct VoxelReadback : vxgi::DenseAttributes {
    float count(int x, int y, int z) const { return at(x, y, z, shader::CH_COUNT); }
    // Channel sum divided by the fragment count.
    float average(int x, int y, int z, uint32_t channel) const { return at(x, y, z, channel) / count(x, y, z); }
    VoxelSet occupancy() const;  // CH_COUNT > 0
};

VoxelReadback readVoxels(const vxgi::VoxelVolumes& volumes);
// Per grid voxel (x fastest): its slot's extents (shared/voxel_data.h), 0 for an empty voxel.
std::vector<uint32_t> readExtents(const vxgi::VoxelVolumes& volumes);

// Both voxelizers, for tests parametrized over them, and their test names.
inline constexpr vxgi::VoxelizerKind kVoxelizers[] = {vxgi::VoxelizerKind::Geometry, vxgi::VoxelizerKind::Compute};
std::string voxelizerTestName(const ::testing::TestParamInfo<vxgi::VoxelizerKind>& info);

// A scene, its GPU copy, a voxelizer (geometry-shader dilation or compute)
// and volumes for one grid: what the dynamic tests drive frame by frame.
struct VoxelRig {
    // slots: the voxel slot capacity (0 = vxgi::defaultSlotCapacity).
    VoxelRig(const scene::Scene& scene, const vxgi::GridSpec& grid,
             vxgi::VoxelizerKind kind = vxgi::VoxelizerKind::Geometry, uint32_t slots = 0);
    void fullVoxelize();       // clearAll + static + dynamic, as after a load (with the list)
    void dynamicFrame();       // clearDynamic + dynamic, as the Renderer's later frames
    void updateTransforms(const scene::Scene& scene);  // after moving nodes
    VoxelReadback read() const { return readVoxels(volumes); }

    gpuscene::SceneGpu sceneGpu;
    vxgi::Voxelizer voxelizer;
    vxgi::VoxelListPass list;
    vxgi::VoxelVolumes volumes;
    gpu::Tracker tracker;
};

// Voxelization from scratch of every draw (static and dynamic) into a fresh grid.
VoxelReadback voxelizeScene(const scene::Scene& scene, const vxgi::GridSpec& grid,
                            vxgi::VoxelizerKind kind = vxgi::VoxelizerKind::Geometry);

// ---- scene construction ----

using WorldTriangle = std::array<glm::vec3, 3>;

// One node holding the triangles as one primitive, each with its face normal.
int addTriangles(scene::Scene& s, int material, const std::vector<WorldTriangle>& tris,
                 glm::vec3 translation = glm::vec3(0.0f), bool dynamic = false);
// An axis-aligned rectangle [lo, hi] (lo[axis] == hi[axis] is its plane) as
// two triangles with the same diagonal whatever the normal's sign.
int addRect(scene::Scene& s, int material, glm::vec3 lo, glm::vec3 hi, int axis, float normalSign);
// A closed box of 12 triangles with outward normals, centred on its node.
int addBox(scene::Scene& s, int material, glm::vec3 halfExtent, glm::vec3 translation, bool dynamic);

// ---- voxel space ----

// Voxel coordinates as the vertex shader computes them, in float, so the
// reference sees the very same triangle.
glm::dvec3 toVoxel(const glm::vec3& world, const vxgi::GridSpec& grid);
// Every placed triangle of the scene in the grid's voxel coordinates.
std::vector<Triangle> voxelTriangles(const scene::Scene& scene, const vxgi::GridSpec& grid);

// A grid with an exact origin and voxel size (both representable in float).
inline vxgi::GridSpec exactGrid(glm::vec3 origin, float voxelSize, uint32_t n) {
    vxgi::GridSpec g;
    g.origin = origin;
    g.voxelSize = voxelSize;
    g.n = n;
    return g;
}

}  // namespace dvsgi::test
