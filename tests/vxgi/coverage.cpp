#include "coverage.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "shared/voxelize_compute_pass.h"
#include "vxgi/voxelize_compute.h"

namespace dvsgi::test {

glm::dvec3 Rng::unitVector() {
    for (;;) {
        const glm::dvec3 v(range(-1, 1), range(-1, 1), range(-1, 1));
        const double l = glm::length(v);
        if (l > 0.05 && l <= 1.0) return v / l;
    }
}

void Packing::add(const std::vector<LocalTriangle>& local, uint32_t pitch, uint32_t n) {
    const uint32_t perAxis = n / pitch, perGrid = perAxis * perAxis * perAxis;
    for (size_t i = 0; i < local.size(); ++i) {
        if (i % perGrid == 0) {
            // Grids tile a 4 x 4 x k block of world space.
            const uint32_t k = uint32_t(grids.size());
            const glm::vec3 origin(float(n * (k % 4)), float(n * ((k / 4) % 4)), float(n * (k / 16)));
            grids.push_back(exactGrid(origin, 1.0f, n));
        }
        const uint32_t c = uint32_t(i % perGrid);
        const glm::dvec3 cell(double(c % perAxis), double((c / perAxis) % perAxis), double(c / (perAxis * perAxis)));
        const glm::dvec3 base = glm::dvec3(grids.back().origin) + cell * double(pitch);
        WorldTriangle w;
        for (int k = 0; k < 3; ++k) w[size_t(k)] = glm::vec3(base + local[i][size_t(k)]);
        tris.push_back(w);
    }
}

namespace {

std::string describe(const Triangle& t) {
    std::ostringstream o;
    o.precision(9);
    for (int k = 0; k < 3; ++k) o << (k ? " " : "") << "(" << t.v[k].x << ", " << t.v[k].y << ", " << t.v[k].z << ")";
    return o.str();
}

}  // namespace

void expectCoverage(const CoverageReport& r, vxgi::VoxelizerKind kind) {
    if (::testing::Test::IsSkipped()) return;
    EXPECT_EQ(r.misses, 0u);
    EXPECT_EQ(r.farExtras, 0u);
    if (kind == vxgi::VoxelizerKind::Compute) {
        EXPECT_EQ(r.extras, 0u);
    }
    EXPECT_GT(r.reference, 0u);
}

CoverageReport runCoverage(const scene::Scene& s, const std::vector<vxgi::GridSpec>& grids, const std::string& label,
                           vxgi::VoxelizerKind kind) {
    // DVSGI_TEST_HARDWARE_CONSERVATIVE=1 runs the geometry path with
    // VK_EXT_conservative_rasterization instead of the geometry-shader
    // dilation (scripts/gpu-check.sh does, on GPUs that have it).
    const char* hwEnv = std::getenv("DVSGI_TEST_HARDWARE_CONSERVATIVE");
    const bool hardware = kind == vxgi::VoxelizerKind::Geometry && hwEnv && std::string(hwEnv) == "1";
    if (hardware && !context().features.conservativeRaster) {
        [] { GTEST_SKIP() << "DVSGI_TEST_HARDWARE_CONSERVATIVE=1, but " << context().deviceName
                          << " lacks VK_EXT_conservative_rasterization"; }();
        return {};
    }
    gpuscene::SceneGpu sceneGpu(context(), s, float(render::RenderSettings{}.textureAnisotropy));
    vxgi::Voxelizer voxelizer(context(), sceneGpu, hardware, kind);
    CoverageReport total;
    size_t triangles = 0;
    // The compute path runs three times: every triangle split into tiles of
    // one column per lane, then of the CPU's run per lane, then every triangle
    // walked by its own invocation (the device type picks a mix).
    const bool compute = kind == vxgi::VoxelizerKind::Compute;
    struct Run {
        vxgi::ComputeTiling tiling;
        const char* name;
    };
    const std::vector<Run> runs =
        compute ? std::vector<Run>{{{0u, 1u, 1u}, " (all tiled, 1 column per lane, hits sampled at once)"},
                                   {{0u, shader::VOXC_LANE_COLUMNS_CPU, shader::VOXC_PENDING},
                                    " (all tiled, several columns per lane, hits sampled in batches)"},
                                   {{UINT32_MAX, 1u, shader::VOXC_PENDING}, " (none tiled)"}}
                : std::vector<Run>{{{0u, 1u, 1u}, ""}};
    for (size_t g = 0; g < grids.size(); ++g) {
        const vxgi::GridSpec& grid = grids[g];
        const std::vector<Triangle> tris = voxelTriangles(s, grid);
        triangles = tris.size();
        // The compute path's boxes are grown (shared/voxelize_compute_pass.h);
        // its reference is grown alike and must match exactly.
        const double growth = compute ? double(shader::VOXC_BOX_GROWTH) : 0.0;
        const VoxelSet ref = referenceVoxelize(tris, grid.n, growth);
        for (const Run& run : runs) {
            if (compute) voxelizer.setComputeTiling(run.tiling);
            const std::string where = label + run.name + ": grid " + std::to_string(g);
            vxgi::VoxelVolumes volumes(context(), grid);
            gpu::Tracker tracker = volumeTracker(volumes);
            context().submitAndWait([&](VkCommandBuffer cmd) {
                voxelizer.clearAll(cmd, tracker, volumes, nullptr);
                voxelizer.voxelize(cmd, tracker, sceneGpu, volumes, vxgi::VoxelizeMode::Static, nullptr);
            });
            const VoxelSet gpu = readVoxels(volumes).occupancy();
            const CoverageReport r = compareCoverage(ref, gpu);
            for (const glm::ivec3& v : r.missList) {
                std::string culprits;
                for (const Triangle& t : tris)
                    if (triangleBoxOverlap(t, glm::dvec3(v), glm::dvec3(v) + 1.0)) culprits += "\n    " + describe(t);
                ADD_FAILURE() << where << " misses voxel (" << v.x << ", " << v.y << ", " << v.z
                              << "), touched by (voxel coordinates):" << culprits;
            }
            for (const glm::ivec3& v : r.farList) {
                std::string near;
                for (const Triangle& t : tris)
                    if (triangleBoxOverlap(t, glm::dvec3(v) - 2.0, glm::dvec3(v) + 3.0)) near += "\n    " + describe(t);
                ADD_FAILURE() << where << " marks voxel (" << v.x << ", " << v.y << ", " << v.z
                              << "), more than one voxel away from every reference voxel; triangles within 2 voxels:"
                              << near;
            }
            total.reference += r.reference;
            total.gpu += r.gpu;
            total.misses += r.misses;
            total.extras += r.extras;
            total.farExtras += r.farExtras;
        }
    }
    // For the compute path the counts add all three runs.
    std::printf("[%s, %s%s] %zu triangles, %zu grid(s) of %u^3: reference %zu voxels, GPU %zu, misses %zu, "
                "extras %zu (%.1f%% of the reference), extras beyond 1 voxel %zu\n",
                label.c_str(), vxgi::voxelizerName(kind), voxelizer.hardwareConservative() ? " (hardware conservative)" : "", triangles, grids.size(), grids.empty() ? 0u : grids[0].n, total.reference, total.gpu,
                total.misses, total.extras, total.reference ? 100.0 * double(total.extras) / double(total.reference) : 0.0,
                total.farExtras);
    return total;
}

CoverageReport runCoverage(const std::vector<WorldTriangle>& tris, const std::vector<vxgi::GridSpec>& grids,
                           const std::string& label, vxgi::VoxelizerKind kind) {
    scene::Scene s;
    s.source = "test:" + label;
    const int m = addMaterial(s, glm::vec3(0.8f));
    addTriangles(s, m, tris);
    return runCoverage(s, grids, label, kind);
}

}  // namespace dvsgi::test
