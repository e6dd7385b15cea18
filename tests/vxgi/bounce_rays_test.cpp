// The voxel bounce's rays (--bounce-trace rays, shaders/lib/voxel_rays.glsl)
// against the same rays marched on the CPU: an open box of emissive walls
// (32^3), its radiance read back before the bounce, and for every inner wall
// voxel the rays the shader casts (same directions, same start, same rule for
// the voxel's own surface) walked voxel by voxel through that radiance. What
// one bounce adds to each voxel must be albedo times their mean. With
// --edge-voxels faces the same, the rays passing beside the part of the box's
// edge voxels its walls do not reach and seeing those voxels' faces. And with
// a thin slab inside the box, its top emitting: the rays see the side of the
// slab's voxels they meet and pass beside its ends. And against a closed
// form: a floor under an emitting square gets its view factor from where its
// voxels' rays start.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "gpu_fixture.h"
#include "light_helpers.h"
#include "shared/bounce_pass.h"
#include "shared/voxel_data.h"
#include "ray_march.h"
#include "vox_helper.h"
#include "vxgi/voxel_light_settings.h"
#include "vxgi/voxel_storage_io.h"

namespace dvsgi::test {
namespace {

constexpr uint32_t kN = 32;
constexpr float kHalf = 0.71875f;  // walls in the middle of voxel layers 4 and 27 of [-1, 1]^3
constexpr int kLow = 4, kHigh = 27, kInnerLo = 6, kInnerHi = 25;
constexpr float kRho = 0.5f, kL = 1.0f;
constexpr uint32_t kRays = 16;

// The inward normal of a voxel in exactly one wall layer (the box's faces; the
// top is open), or zero for voxels in none or in two (edges: their normal is
// diagonal, so no ray counts them as its own surface).
glm::vec3 wallNormal(glm::ivec3 c) {
    glm::vec3 n(0.0f);
    int walls = 0;
    for (int a = 0; a < 3; ++a) {
        if (c[a] == kLow) n[a] = 1.0f, ++walls;
        if (c[a] == kHigh && a != 1) n[a] = -1.0f, ++walls;
    }
    return walls == 1 ? n : glm::vec3(0.0f);
}

// voxelRaysCosine's mean over its rays: R2 directions shifted per voxel,
// cosine-distributed about n, from just past the voxel's face.
float cpuRays(const Rgba16Volume& radiance, const VoxelReadback& attributes, glm::ivec3 v, glm::vec3 n,
              const EdgeModel* edges = nullptr) {
    const uint32_t seed = shader::raySeed(v);
    const glm::vec3 origin = shader::voxelRayOrigin(glm::vec3(v) + 0.5f, n);
    // The voxel's own surface: its wall's layer, by the walls' own normals.
    const auto own = [&](glm::ivec3 c) {
        return std::fabs(glm::dot(glm::vec3(c - v), n)) < 1.5f && glm::dot(wallNormal(c), n) > 0.8f;
    };
    const auto normalAt = [&](glm::ivec3 c) { return rayNormalOf(attributes, c); };
    double sum = 0.0;
    for (uint32_t i = 0; i < kRays; ++i)
        sum += marchRay(radiance, origin, cosineRay(n, seed, i), own, normalAt, RayStart::Voxel, true, nullptr, edges).r;
    return float(sum / kRays);
}

// What the rays read besides the radiance: the attributes, and with
// --edge-voxels faces the extents and the side light (the faces' light).
struct RayInputs {
    VoxelReadback attributes;
    std::vector<uint32_t> extents;
    std::vector<glm::uvec4> sides;
};

Rgba16Volume radianceAfter(const scene::Scene& s, uint32_t bounces, RayInputs* inputs = nullptr,
                           bool edgeFaces = false, uint32_t rays = kRays) {
    render::RenderSettings rs = unitBoxGridSettings(kN, 256);
    rs.voxelLight.bounceTrace = vxgi::BounceTrace::Rays;
    rs.voxelLight.bounceRays = rays;
    rs.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    rs.voxelLight.bounces = bounces;
    rs.voxelLight.edgeFaces = edgeFaces;
    rs.voxelizer = vxgi::VoxelizerKind::Compute;  // the extents' voxelizer
    render::Renderer r(context(), s, rs);
    r.renderFrame();
    if (inputs) {
        inputs->attributes = readVoxels(*r.volumes());
        inputs->extents = readExtents(*r.volumes());
        inputs->sides = vxgi::readSideLight(context(), *r.volumes());
    }
    return readRgba16(r.volumes()->radiance);
}

class BounceRays : public GpuTest {};

// One voxel bounce against the CPU march, summed over the inner wall voxels
// but the opening's: what the GPU's bounce added to each (after - before)
// and kRho times the CPU's mean over the same rays.
struct WallSums {
    double gpu = 0.0, cpu = 0.0, worst = 0.0;
    int count = 0;
    double ratio() const { return gpu / cpu; }
};
WallSums compareWalls(const Rgba16Volume& before, const Rgba16Volume& after, const VoxelReadback& attributes,
                      const EdgeModel& model) {
    WallSums w;
    forEachWallVoxel(kLow, kHigh, kInnerLo, kInnerHi, [&](glm::ivec3 v) {
        if (v.y == kHigh) return;  // the opening
        const float gpu = after.at(v.x, v.y, v.z).r - before.at(v.x, v.y, v.z).r;
        const float cpu = kRho * cpuRays(before, attributes, v, wallNormal(v), &model);
        w.gpu += gpu;
        w.cpu += cpu;
        w.worst = std::max(w.worst, double(std::fabs(gpu - cpu)));
        ++w.count;
    });
    return w;
}

TEST_F(BounceRays, MatchTheSameRaysMarchedOnTheCpu) {
    scene::Scene s;
    addInwardBox(s, addMaterial(s, glm::vec3(kRho), glm::vec3(kL)), glm::vec3(0.0f), kHalf, true);
    addTopDownCamera(s, 0.0f, 1.0f);
    RayInputs in;
    const Rgba16Volume before = radianceAfter(s, 0, &in), after = radianceAfter(s, 1);
    const WallSums w = compareWalls(before, after, in.attributes, edgeModel(in.attributes, in.extents, in.sides, false));
    std::printf("  %d wall voxels: reflected light GPU %.5f, CPU %.5f (%+.3f%%); worst voxel off by %.4f\n", w.count,
                w.gpu / w.count, w.cpu / w.count, 100.0 * (w.ratio() - 1.0), w.worst);
    ASSERT_GT(w.count, 1000);
    EXPECT_NEAR(w.ratio(), 1.0, 0.002);
    EXPECT_LT(w.worst, 0.02);
}

TEST_F(BounceRays, EdgeFacesMatchTheSameRaysMarchedOnTheCpu) {
    scene::Scene s;
    addInwardBox(s, addMaterial(s, glm::vec3(kRho), glm::vec3(kL)), glm::vec3(0.0f), kHalf, true);
    addTopDownCamera(s, 0.0f, 1.0f);
    RayInputs in;
    const Rgba16Volume before = radianceAfter(s, 0, &in, true), after = radianceAfter(s, 1, nullptr, true);
    const EdgeModel edges = edgeModel(in.attributes, in.extents, in.sides);
    int faceVoxels = 0, partial = 0;
    for (int z = 0; z < int(kN); ++z)
        for (int y = 0; y < int(kN); ++y)
            for (int x = 0; x < int(kN); ++x) {
                if (in.attributes.count(x, y, z) <= 0.0f) continue;
                faceVoxels += showsFaces(in.attributes, glm::ivec3(x, y, z));
                const uint32_t e = in.extents[voxelIndex(kN, x, y, z)];
                partial += e != 0u && e != shader::VOXEL_EXTENT_ALL;
            }
    const WallSums w = compareWalls(before, after, in.attributes, edges);
    std::printf("  %d voxels show faces, %d reached in part; %d wall voxels: reflected light GPU %.5f, CPU %.5f "
                "(%+.3f%%); worst voxel off by %.4f\n",
                faceVoxels, partial, w.count, w.gpu / w.count, w.cpu / w.count, 100.0 * (w.ratio() - 1.0), w.worst);
    ASSERT_GT(faceVoxels, 100) << "the box's edges";
    ASSERT_GT(partial, 1000) << "its walls lie in the middle of their voxels";
    EXPECT_NEAR(w.ratio(), 1.0, 0.002);
    EXPECT_LT(w.worst, 0.02);
}

// A slab thinner than a voxel across the box, lying in the middle of voxel
// layer 16 and ending inside voxels 11 and 20 along x and 8 and 23 along z;
// its top emits kSlabL. Its voxels hold its two sides: rays that meet them
// see the side they meet, and rays that run past its ends, beside it, go on.
TEST_F(BounceRays, ThinSlabMatchesTheSameRaysMarchedOnTheCpu) {
    constexpr float kSlabL = 4.0f;
    scene::Scene s;
    addInwardBox(s, addMaterial(s, glm::vec3(kRho), glm::vec3(kL)), glm::vec3(0.0f), kHalf, true);
    const glm::vec3 lo(-0.3f, 0.0f, -0.45f), hi(0.3f, 0.0f, 0.45f);
    addRect(s, addMaterial(s, glm::vec3(kRho), glm::vec3(kSlabL)), glm::vec3(lo.x, 0.04f, lo.z),
            glm::vec3(hi.x, 0.04f, hi.z), 1, 1.0f);
    addRect(s, addMaterial(s, glm::vec3(kRho)), glm::vec3(lo.x, 0.02f, lo.z), glm::vec3(hi.x, 0.02f, hi.z), 1, -1.0f);
    addTopDownCamera(s, 0.0f, 1.0f);
    RayInputs in;
    const Rgba16Volume before = radianceAfter(s, 0, &in), after = radianceAfter(s, 1);
    EdgeModel model = edgeModel(in.attributes, in.extents, in.sides, false);
    int slabVoxels = 0;
    for (int z = 0; z < int(kN); ++z)
        for (int x = 0; x < int(kN); ++x) slabVoxels += thinWallAxis(before.at(x, 16, z).a) == 1;
    const WallSums w = compareWalls(before, after, in.attributes, model);
    model.thinWallEnds = false;
    const WallSums whole = compareWalls(before, after, in.attributes, model);
    std::printf("  %d voxels of the slab two-sided across y; %d wall voxels: reflected light GPU %.5f, CPU %.5f "
                "(%+.3f%%), CPU with the slab's ends whole %.5f (%+.3f%%); worst voxel off by %.4f\n",
                slabVoxels, w.count, w.gpu / w.count, w.cpu / w.count, 100.0 * (w.ratio() - 1.0),
                whole.cpu / w.count, 100.0 * (whole.cpu / w.cpu - 1.0), w.worst);
    ASSERT_GT(slabVoxels, 100) << "the slab's voxels hold its two sides";
    EXPECT_NEAR(w.ratio(), 1.0, 0.002);
    EXPECT_LT(w.worst, 0.02);
    // The rule matters here: the slab's ends taken whole show the rays that
    // run past them under the slab its emitting top.
    EXPECT_GT(whole.cpu / w.cpu, 1.01);
}


// The view factor from a point to a parallel rectangle whose corner lies
// straight above it, a by b, at height h.
double cornerViewFactor(double a, double b, double h) {
    const double x = a / h, y = b / h, sx = std::sqrt(1.0 + x * x), sy = std::sqrt(1.0 + y * y);
    return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2.0 * glm::pi<double>());
}

// A closed black box with a grey floor and, in the middle of its ceiling, an
// emitting square whose edges run through voxel centres (voxels 10.5 to 21.5,
// so that the voxels it shares with the black ceiling around it show half its
// light, as much as the half they hold of it). One voxel bounce gives each
// floor voxel albedo x L x the square's view factor from where its rays start:
// VOXEL_RAY_START (0.51) of a voxel above the voxel's centre, which is the
// floor's plane here. The view factor from there is 3.5 % above the floor's
// own, and from a whole voxel up, where the rays started before, 7.0 %
// (docs/quality.md, "Where a voxel's rays start"). Measured -0.31 % against
// the first; bound 1.5 times that, which a start a voxel up (+3.4 %) or on
// the floor (-3.4 %) would not meet.
TEST_F(BounceRays, FloorUnderAnEmittingSquareSeesItFromJustAboveItsVoxel) {
    scene::Scene s;
    const int black = addMaterial(s, glm::vec3(0.0f)), emitter = addMaterial(s, glm::vec3(0.0f), glm::vec3(kL)),
              floor = addMaterial(s, glm::vec3(kRho));
    const auto world = [](double voxel) { return float(-1.0 + voxel * 2.0 / kN); };
    constexpr double kSquareLo = 10.5, kSquareHi = 21.5;
    const float a = world(kSquareLo), b = world(kSquareHi);
    // The box's faces on their planes, facing in; the ceiling a frame around the square.
    for (int axis = 0; axis < 3; axis += 2)
        for (const float sign : {1.0f, -1.0f}) {
            glm::vec3 lo(-kHalf), hi(kHalf);
            lo[axis] = hi[axis] = -sign * kHalf;
            addRect(s, black, lo, hi, axis, sign);
        }
    addRect(s, floor, glm::vec3(-kHalf, -kHalf, -kHalf), glm::vec3(kHalf, -kHalf, kHalf), 1, 1.0f);
    addRect(s, emitter, glm::vec3(a, kHalf, a), glm::vec3(b, kHalf, b), 1, -1.0f);
    addRect(s, black, glm::vec3(-kHalf, kHalf, -kHalf), glm::vec3(a, kHalf, kHalf), 1, -1.0f);
    addRect(s, black, glm::vec3(b, kHalf, -kHalf), glm::vec3(kHalf, kHalf, kHalf), 1, -1.0f);
    addRect(s, black, glm::vec3(a, kHalf, -kHalf), glm::vec3(b, kHalf, a), 1, -1.0f);
    addRect(s, black, glm::vec3(a, kHalf, b), glm::vec3(b, kHalf, kHalf), 1, -1.0f);
    addTopDownCamera(s, 0.0f, 1.0f);
    constexpr uint32_t kManyRays = 128;
    const Rgba16Volume after = radianceAfter(s, 1, nullptr, false, kManyRays);
    ASSERT_NEAR(after.at(16, kHigh, 16).r, kL, 1e-3) << "the square's middle";
    ASSERT_NEAR(after.at(int(kSquareLo), kHigh, 16).r, 0.5f * kL, 0.01f) << "its edge's voxels: half";
    const auto viewFactor = [&](double x, double z, double h) {
        return cornerViewFactor(kSquareHi - x, kSquareHi - z, h) + cornerViewFactor(x - kSquareLo, kSquareHi - z, h) +
               cornerViewFactor(kSquareHi - x, z - kSquareLo, h) + cornerViewFactor(x - kSquareLo, z - kSquareLo, h);
    };
    // Voxel units: the floor and the ceiling through the centres of layers kLow and kHigh.
    const double height = kHigh - kLow;
    double got = 0.0, fromStart = 0.0, fromFloor = 0.0, fromVoxelUp = 0.0;
    for (int z = kInnerLo; z <= kInnerHi; ++z)
        for (int x = kInnerLo; x <= kInnerHi; ++x) {
            got += after.at(x, kLow, z).r;
            fromStart += kRho * kL * viewFactor(x + 0.5, z + 0.5, height - shader::VOXEL_RAY_START);
            fromFloor += kRho * kL * viewFactor(x + 0.5, z + 0.5, height);
            fromVoxelUp += kRho * kL * viewFactor(x + 0.5, z + 0.5, height - 1.0);
        }
    std::printf("  floor's reflected light %.5f: the view factor from the rays' start gives %.5f (%+.2f%%), from "
                "the floor %.5f, from a voxel up %.5f\n",
                got, fromStart, 100.0 * (got / fromStart - 1.0), fromFloor, fromVoxelUp);
    EXPECT_NEAR(got / fromStart, 1.0, 0.005);
    ASSERT_GT(fromVoxelUp / fromStart, 1.03);
    ASSERT_LT(fromFloor / fromStart, 0.97);
}

}  // namespace
}  // namespace dvsgi::test
