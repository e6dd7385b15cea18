// Directional shadows with a focus (render/shadows.h, ShadowFocus): with a
// clipmap, a sun over a scene much larger than level 0's window gets a second
// shadow view around the camera. On the host: the focus view is centred on the
// camera, spans its sphere, moves in whole texels, and leaves the scene-wide
// view as it was. On lavapipe: a small occluder near the camera in a 200 m
// scene casts a full shadow, which the scene-wide map alone (texels of 28 cm)
// cannot resolve.
#include <cmath>
#include <cstdio>

#include <glm/gtc/constants.hpp>

#include "gpu_fixture.h"
#include "render/shadows.h"
#include "shared/composite_pass.h"

namespace dvsgi::test {
namespace {

namespace sh = dvsgi::shader;

scene::PlacedLight sun(glm::vec3 direction) {
    scene::PlacedLight p;
    p.light.name = "sun";
    p.light.type = scene::LightType::Directional;
    p.light.intensity = 3.0f;
    p.position = glm::vec3(0.0f, 50.0f, 0.0f);
    p.direction = glm::normalize(direction);
    return p;
}

scene::Bounds bigBounds() {
    scene::Bounds b;
    b.min = glm::vec3(-100.0f, -1.0f, -100.0f);
    b.max = glm::vec3(100.0f, 10.0f, 100.0f);
    return b;
}

glm::vec2 ndc(const sh::GpuShadowView& v, glm::vec3 p) {
    const glm::vec4 c = v.viewProj * glm::vec4(p, 1.0f);
    return glm::vec2(c) / c.w;
}

TEST(ShadowFocus, DirectionalLightGetsAViewAroundTheFocusFirst) {
    const std::vector<scene::PlacedLight> lights{sun(glm::vec3(0.3f, -1.0f, 0.2f))};
    const uint32_t size = 1024;
    const render::LightSetup plain = render::setupLights(lights, bigBounds(), size, true);
    const render::ShadowFocus focus{glm::vec3(10.0f, 0.5f, -5.0f), 4.0f};
    const render::LightSetup focused = render::setupLights(lights, bigBounds(), size, true, focus);
    ASSERT_EQ(plain.views.size(), 1u);
    ASSERT_EQ(focused.views.size(), 2u);
    EXPECT_EQ(focused.lights[0].shadow.x, 0u);
    EXPECT_EQ(focused.lights[0].shadow.y, 2u);
    // The scene-wide view comes second, unchanged.
    EXPECT_EQ(focused.views[1].viewProj, plain.views[0].viewProj);
    EXPECT_EQ(focused.views[1].params, plain.views[0].params);
    // The focus view: its centre within a texel of the map's middle, texels of
    // 2 r / size, and the sphere inside the map along both of its axes.
    const sh::GpuShadowView& v = focused.views[0];
    const float texelNdc = 2.0f / float(size);
    EXPECT_LE(glm::length(ndc(v, focus.centre)), texelNdc);
    EXPECT_FLOAT_EQ(v.params.x, 2.0f * focus.radius / float(size));
    const glm::vec3 dir = glm::vec3(focused.lights[0].direction);
    const glm::vec3 across = glm::normalize(glm::cross(dir, glm::vec3(0, 1, 0)));
    EXPECT_NEAR(std::abs(ndc(v, focus.centre + across * focus.radius).x), 1.0f, 2.0f * texelNdc);
    // Every point of the scene's bounds lies within the view's depth range
    // (0..1: the project builds glm with GLM_FORCE_DEPTH_ZERO_TO_ONE).
    for (int corner = 0; corner < 8; ++corner) {
        const scene::Bounds b = bigBounds();
        const glm::vec3 p(corner & 1 ? b.max.x : b.min.x, corner & 2 ? b.max.y : b.min.y, corner & 4 ? b.max.z : b.min.z);
        const glm::vec4 c = v.viewProj * glm::vec4(p, 1.0f);
        EXPECT_GT(c.z / c.w, 0.0f) << corner;
        EXPECT_LT(c.z / c.w, 1.0f) << corner;
    }
    // A focus no smaller than the scene's bounding sphere gets no view of its own.
    const float sceneRadius = 0.5f * glm::length(bigBounds().max - bigBounds().min);
    EXPECT_EQ(render::shadowFocusRadius(bigBounds(), 4.0f), 4.0f);
    EXPECT_EQ(render::shadowFocusRadius(bigBounds(), 1.01f * render::kShadowFocusFraction * sceneRadius), 0.0f);
    const render::LightSetup none = render::setupLights(lights, bigBounds(), size, true, {focus.centre, 0.0f});
    EXPECT_EQ(none.views.size(), 1u);
    EXPECT_EQ(none.lights[0].shadow.y, 1u);
}

// The focus follows the camera in whole texels: a fixed point's map
// coordinate moves by a whole number of texels whatever the camera does, so
// shadow edges do not crawl as the camera walks.
TEST(ShadowFocus, TheFocusMovesInWholeTexels) {
    const std::vector<scene::PlacedLight> lights{sun(glm::vec3(0.3f, -1.0f, 0.2f))};
    const uint32_t size = 1024;
    const glm::vec3 probe(3.3f, 0.0f, -2.1f);
    const render::ShadowFocus start{glm::vec3(2.0f, 1.0f, -1.0f), 4.0f};
    const glm::vec2 at0 = ndc(render::setupLights(lights, bigBounds(), size, true, start).views[0], probe);
    const float texelNdc = 2.0f / float(size);
    for (float step = 0.0013f; step < 0.2f; step *= 1.7f) {
        render::ShadowFocus moved = start;
        moved.centre += glm::vec3(step, 0.3f * step, -0.7f * step);
        const glm::vec2 shift = (ndc(render::setupLights(lights, bigBounds(), size, true, moved).views[0], probe) - at0) /
                                texelNdc;
        EXPECT_NEAR(shift.x, std::round(shift.x), 2e-3f) << step;
        EXPECT_NEAR(shift.y, std::round(shift.y), 2e-3f) << step;
    }
}

class ShadowFocusRender : public GpuTest {};

// A 10 cm square 0.5 m above a 200 m floor, under the camera, sun slanted:
// its shadow's centre must be fully dark. With a clipmap (level 0's window
// 2 m wide) the focus view's texels are 2 mm; a fitted grid keeps only the
// scene-wide map, whose 28 cm texels cannot hold the square.
TEST_F(ShadowFocusRender, ASmallOccluderNearTheCameraCastsAFullShadowInALargeScene) {
    scene::Scene s;
    const glm::vec3 rho(0.8f);
    const int white = addMaterial(s, rho);
    addQuad(s, white, glm::vec3(0.0f), 100.0f);
    const glm::vec3 dir = glm::normalize(glm::vec3(0.3f, -1.0f, 0.0f));
    // Centred over the point of the floor the camera looks at.
    addQuad(s, white, -dir * (0.5f / -dir.y), 0.05f);
    addTopDownCamera(s, 1.5f, glm::radians(30.0f));
    scene::Light l;
    l.name = "sun";
    l.type = scene::LightType::Directional;
    l.intensity = 3.0f;
    addLight(s, l, glm::vec3(0.0f, 5.0f, 0.0f), dir);
    render::RenderSettings rs;
    rs.width = rs.height = 64;
    rs.shadowMapSize = 1024;
    rs.voxels = 32;
    rs.outputTerm = sh::TERM_DIRECT;
    const float unshadowed = rho.x * 3.0f * (-dir.y) / glm::pi<float>();
    rs.clipmap.levels = 2;
    rs.clipmap.voxelSize = 1.0f / 16.0f;
    const image::ImageRGBA32F focused = render(s, rs);
    rs.clipmap.levels = 0;
    const image::ImageRGBA32F fitted = render(s, rs);
    const float centreFocused = focused.at(32, 32)[0], centreFitted = fitted.at(32, 32)[0];
    const float litFocused = focused.at(4, 4)[0];
    std::printf("  shadow centre / unshadowed: with the focus %.3f, scene-wide map only %.3f; lit corner %.5f\n",
                centreFocused / unshadowed, centreFitted / unshadowed, litFocused / unshadowed);
    EXPECT_EQ(centreFocused, 0.0f);
    EXPECT_NEAR(litFocused, unshadowed, 4e-4f * unshadowed);
    EXPECT_GT(centreFitted, 0.1f * unshadowed);
}

}  // namespace
}  // namespace dvsgi::test
