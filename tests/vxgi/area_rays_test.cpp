// Area lights' visibility at pixels (lighting.comp's AREA_RAYS): from each
// floor pixel a ray to each emitter patch's centre through this frame's
// voxels, starting a voxel off the floor as the gather's rays do and stopping
// two voxels (over the cosine at the emitter) short of it, against the same
// rays marched on the CPU (ray_march.h) through the read-back radiance and
// normals. The visibility term is the mean over the patches that light a
// pixel.
#include <cmath>
#include <cstdio>
#include <string>

#include <glm/gtc/constants.hpp>

#include "gpu_fixture.h"
#include "light_helpers.h"
#include "ray_march.h"
#include "render/emitters.h"
#include "shared/composite_pass.h"
#include "vox_helper.h"

namespace dvsgi::test {
namespace {

class AreaRays : public GpuTest {};

// A 1 m square emitter 1.5 m over a floor, facing it, and a black square beside
// its axis 0.6 m up, above the camera: the floor gets an umbra, a penumbra and
// open light, and the emitter's own voxel layer must not shadow it.
scene::Scene occludedEmitter() {
    scene::Scene s;
    addQuad(s, addMaterial(s, glm::vec3(0.5f)), glm::vec3(0.0f), 2.0f);  // floor, normal +Y
    addQuad(s, addMaterial(s, glm::vec3(0.0f), glm::vec3(1.0f)), glm::vec3(0.0f, 1.5f, 0.0f), 0.5f,
            glm::angleAxis(glm::pi<float>(), glm::vec3(1, 0, 0)));
    addQuad(s, addMaterial(s, glm::vec3(0.0f)), glm::vec3(0.3f, 0.6f, 0.3f), 0.3f);
    addTopDownCamera(s, 0.3f, glm::radians(120.0f));
    return s;
}

render::RenderSettings areaSettings() {
    render::RenderSettings rs;
    rs.width = rs.height = 32;
    rs.shadowMapSize = 256;
    rs.voxels = 32;
    rs.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    rs.voxelLight.bounces = 0;
    return rs;
}

// With the gather's and the bounce's cones as well, the area lights' rays are
// the only reader of the voxels' packed normals and occupancy bits, which
// must then be packed for them alone.
class AreaRaysWith : public AreaRays, public ::testing::WithParamInterface<bool> {};

TEST_P(AreaRaysWith, VisibilityMatchesTheSameRaysMarchedOnTheCpu) {
    const scene::Scene s = occludedEmitter();
    render::RenderSettings rs = areaSettings();
    rs.outputTerm = shader::TERM_SHADOW;
    if (!GetParam()) {
        rs.gather.trace = render::GatherTrace::Cones;
        rs.voxelLight.bounceTrace = vxgi::BounceTrace::Cones;
    }
    render::Renderer r(context(), s, rs);
    r.renderFrame();
    ASSERT_EQ(r.emitterPatchCount(), rs.emitterPatches);
    const image::ImageRGBA32F img = r.readOutput();
    const Rgba16Volume radiance = readRgba16(r.volumes()->radiance);
    const VoxelReadback attributes = readVoxels(*r.volumes());
    const vxgi::GridSpec& g = r.volumes()->grid;
    const auto normalAt = [&](glm::ivec3 c) { return rayNormalOf(attributes, c); };
    const std::vector<shader::GpuLight> patches =
        render::emitterPatches(s, scene::drawItems(s, scene::worldMatrices(s)), rs.emitterPatches).lights;
    const float offset = rs.gather.rayOffsetVoxels;
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    double sumGpu = 0.0, sumCpu = 0.0;
    int pixels = 0, off = 0, shadowed = 0, open = 0;
    for (uint32_t y = 0; y < rs.height; ++y)
        for (uint32_t x = 0; x < rs.width; ++x) {
            const glm::vec3 P = pixelOnPlane(s, rs, x, y, 0.0f);
            const glm::vec3 p = (P - g.origin) / g.voxelSize;
            const auto own = [&](glm::ivec3 c) {
                return std::fabs(glm::dot(glm::vec3(c) + 0.5f - p, up)) < 1.5f && glm::dot(normalAt(c), up) > 0.8f;
            };
            double visible = 0.0;
            int lit = 0;
            for (const shader::GpuLight& l : patches) {
                const glm::vec3 toLight = glm::vec3(l.position) - P;
                const float dist = glm::length(toLight);
                const glm::vec3 L = toLight / dist, axis(l.direction);
                if (glm::dot(up, L) <= 0.0f || glm::dot(axis, -L) <= 0.0f) continue;  // lights nothing here
                const glm::vec3 toEmitter = L * (dist / g.voxelSize) - up * offset;
                float reach = glm::length(toEmitter);
                const glm::vec3 d = toEmitter / reach;
                reach -= 2.0f / std::max(std::fabs(glm::dot(axis, d)), 0.2f);
                float t = INFINITY;
                if (reach > 0.0f) marchRay(radiance, p + up * offset, d, own, normalAt, RayStart::Pixel, false, &t);
                visible += t >= reach ? 1.0 : 0.0;
                ++lit;
            }
            const double cpu = lit ? visible / lit : 1.0, gpu = img.at(x, y)[0];
            sumGpu += gpu;
            sumCpu += cpu;
            off += std::fabs(gpu - cpu) > 1.5 / double(rs.emitterPatches);
            shadowed += cpu < 0.01;
            open += cpu > 0.99;
            ++pixels;
        }
    std::printf("  %d pixels (%d in the umbra, %d open): visibility GPU %.5f, CPU %.5f; %d off by more than a patch\n",
                pixels, shadowed, open, sumGpu / pixels, sumCpu / pixels, off);
    ASSERT_GT(shadowed, 20);
    ASSERT_GT(open, 50);
    ASSERT_GT(pixels - shadowed - open, 50);  // the penumbra
    EXPECT_NEAR(sumGpu / pixels, sumCpu / pixels, 0.002);
    EXPECT_LE(off, pixels / 100);
}

INSTANTIATE_TEST_SUITE_P(Gather, AreaRaysWith, ::testing::Bool(), [](const ::testing::TestParamInfo<bool>& i) {
    return i.param ? std::string("RaysEverywhere") : std::string("ConesForTheRest");
});

// The voxels' shadow rays toward the patches cross the cells the occupancy
// bits show empty in one step where the bits are packed (inject.comp built
// with RAY_OCCUPANCY) and half a voxel at a time where no pass reads them
// (everything by cones): they meet the same voxels, so the voxel light is the
// same to the bit.
TEST_F(AreaRays, VoxelLightIsTheSameWithOrWithoutTheOccupancyBits) {
    const scene::Scene s = occludedEmitter();
    render::RenderSettings withBits = areaSettings();
    render::RenderSettings without = withBits;
    without.gather.trace = render::GatherTrace::Cones;
    without.voxelLight.bounceTrace = vxgi::BounceTrace::Cones;
    without.emitterRays = false;
    const auto voxelLight = [&](const render::RenderSettings& rs) {
        render::Renderer r(context(), s, rs);
        r.renderFrame();
        return readRgba16(r.volumes()->radiance);
    };
    const Rgba16Volume a = voxelLight(withBits), b = voxelLight(without);
    ASSERT_EQ(a.texels.size(), b.texels.size());
    int occupied = 0, shadowed = 0, lit = 0, differ = 0;
    for (size_t i = 0; i < a.texels.size(); ++i) {
        if (a.texels[i].a <= 0.0f) continue;
        ++occupied;
        const float y = a.texels[i].g;
        shadowed += y == 0.0f;
        lit += y > 0.0f;
        differ += a.texels[i] != b.texels[i];
    }
    std::printf("  %d occupied voxels (%d dark, %d lit), %d differ\n", occupied, shadowed, lit, differ);
    ASSERT_GT(lit, 100);
    ASSERT_GT(shadowed, 20);  // the occluder's shadow on the floor and the voxels facing away
    EXPECT_EQ(differ, 0);
}

}  // namespace
}  // namespace dvsgi::test
