// Coverage of whole scenes: the built-in Cornell box on a fitted grid, and
// generated meshes placed with rotations, against the CPU reference of every
// placed triangle.
#include <cmath>
#include <cstdio>
#include <map>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include "coverage.h"
#include "gpu_fixture.h"
#include "scene/load.h"

namespace dvsgi::test {
namespace {

class SceneCoverage : public GpuTest, public ::testing::WithParamInterface<vxgi::VoxelizerKind> {};

TEST_P(SceneCoverage, CornellBox64) {
    const scene::Scene s = scene::builtinCornellBox();
    const auto items = scene::drawItems(s, scene::worldMatrices(s));
    const vxgi::GridSpec grid = vxgi::fitGrid(scene::worldBounds(s, items), 64);
    // fitGrid puts the box's lower walls 0.05 of a voxel off voxel centres
    // (kFitLatticeOffset), which keeps the plane halfway along the longest
    // axis off a voxel face; a plane elsewhere may still lie within float
    // rounding of one, where the GPU's depth slack may mark the layers on both
    // sides while the reference, exact on the rounded coordinates, marks one.
    // expectCoverage allows such extras within one voxel.
    glm::dvec3 lo(1e30), hi(-1e30);
    for (const Triangle& t : voxelTriangles(s, grid))
        for (const glm::dvec3& v : t.v) lo = glm::min(lo, v), hi = glm::max(hi, v);
    std::printf("Cornell box spans voxel coordinates (%.7f, %.7f, %.7f) - (%.7f, %.7f, %.7f)\n", lo.x, lo.y, lo.z,
                hi.x, hi.y, hi.z);
    expectCoverage(runCoverage(s, {grid}, "Cornell box, N=64", GetParam()), GetParam());
}

// Smooth-shaded meshes as one primitive each (icosphere: gpu_fixture.h).
scene::Primitive torus(double major, double minor, uint32_t segments, uint32_t sides) {
    scene::Primitive p;
    for (uint32_t i = 0; i < segments; ++i)
        for (uint32_t j = 0; j < sides; ++j) {
            const double u = 2.0 * glm::pi<double>() * i / segments, w = 2.0 * glm::pi<double>() * j / sides;
            const glm::dvec3 n(std::cos(u) * std::cos(w), std::sin(w), std::sin(u) * std::cos(w));
            const glm::dvec3 c(std::cos(u) * major, 0.0, std::sin(u) * major);
            scene::Vertex vert;
            vert.position = glm::vec3(c + n * minor);
            vert.normal = glm::vec3(n);
            p.vertices.push_back(vert);
        }
    for (uint32_t i = 0; i < segments; ++i)
        for (uint32_t j = 0; j < sides; ++j) {
            const uint32_t a = i * sides + j, b = ((i + 1) % segments) * sides + j;
            const uint32_t c = ((i + 1) % segments) * sides + (j + 1) % sides, d = i * sides + (j + 1) % sides;
            p.indices.insert(p.indices.end(), {a, b, c, a, c, d});
        }
    return p;
}

TEST_P(SceneCoverage, IcosphereAndTorus32) {
    // Grid [-2, 2]^3 with voxels of 1/8: both exact in float.
    const vxgi::GridSpec grid = vxgi::gridForBox(glm::vec3(-2.0f), glm::vec3(2.0f), 32);
    ASSERT_EQ(grid.voxelSize, 0.125f);
    ASSERT_EQ(grid.origin, glm::vec3(-2.0f));
    scene::Scene s;
    const int m = addMaterial(s, glm::vec3(0.7f));
    // 320 triangles, radius 0.9 m = 7.2 voxels.
    addMeshNode(s, icosphere(2), m, glm::vec3(-0.83f, 0.71f, 0.05f),
                glm::angleAxis(0.4f, glm::normalize(glm::vec3(1, 2, 3))), glm::vec3(0.9f));
    // 576 triangles, tube radius 2.4 voxels, tilted.
    addMeshNode(s, torus(0.9, 0.3, 32, 9), m, glm::vec3(0.6f, -0.55f, 0.1f),
                glm::angleAxis(1.1f, glm::normalize(glm::vec3(-1, 0.5f, 0.2f))), glm::vec3(1.0f));
    expectCoverage(runCoverage(s, {grid}, "icosphere and torus, N=32", GetParam()), GetParam());
}

INSTANTIATE_TEST_SUITE_P(Voxelizers, SceneCoverage, ::testing::ValuesIn(kVoxelizers), voxelizerTestName);

}  // namespace
}  // namespace dvsgi::test
