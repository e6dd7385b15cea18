// Analytic checks of the deferred direct-lighting path (shadow maps, G-buffer,
// lighting, composite) on programmatic scenes, with validation on.
#include <cmath>
#include <cstdio>

#include <glm/gtc/constants.hpp>
#include <glm/gtx/quaternion.hpp>

#include "gpu_fixture.h"

namespace dvsgi::test {
namespace {

constexpr float kPi = glm::pi<float>();

glm::vec3 pixel(const image::ImageRGBA32F& img, uint32_t x, uint32_t y) {
    const float* p = img.at(x, y);
    return {p[0], p[1], p[2]};
}

// The worst relative error expectNear saw in the current test (where the
// expected value is above its absolute floor), printed for the tolerance table.
double gWorstRel = 0.0;

void expectNear(glm::vec3 got, glm::vec3 want, float relTol, const char* what, uint32_t x, uint32_t y,
                float absTol = 1e-6f) {
    for (int c = 0; c < 3; ++c)
        if (std::abs(want[c]) > absTol)
            gWorstRel = std::max(gWorstRel, double(std::abs(got[c] - want[c]) / std::abs(want[c])));
    for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(got[c], want[c], std::max(relTol * std::abs(want[c]), absTol))
            << what << " at pixel (" << x << ", " << y << ") channel " << c;
}

scene::Light directional(float E, glm::vec3 color = glm::vec3(1.0f)) {
    scene::Light l;
    l.name = "sun";
    l.type = scene::LightType::Directional;
    l.intensity = E;
    l.color = color;
    return l;
}

scene::Light point(float I) {
    scene::Light l;
    l.name = "point";
    l.type = scene::LightType::Point;
    l.intensity = I;
    return l;
}

render::RenderSettings settings(uint32_t size) {
    render::RenderSettings s;
    s.width = s.height = size;
    s.shadowMapSize = 1024;
    s.voxels = 0;  // direct light only: these are analytic checks of the direct path
    return s;
}

// Tolerances are about 1.5x the worst error measured on lavapipe (printed per
// test; table in docs/RELIABILITY.md), which comes from fp16 normals in the
// G-buffer; values that are exact there have float-rounding bounds.
class DirectLighting : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        gWorstRel = 0.0;
    }
    void TearDown() override {
        std::printf("  worst relative error against the closed form: %.2e\n", gWorstRel);
        GpuTest::TearDown();
    }
};

// At 87 degrees the sun grazes the plane 3 degrees high: a surface must not
// shadow itself however steep its depth is in the shadow map.
TEST_F(DirectLighting, LambertPlaneUnderDirectionalLightIsRhoEOverPi) {
    for (float incidenceDeg : {0.0f, 60.0f, 87.0f}) {
        scene::Scene s;
        const glm::vec3 rho(0.5f, 0.25f, 0.8f);
        addQuad(s, addMaterial(s, rho), glm::vec3(0), 20.0f);
        addTopDownCamera(s, 2.0f, glm::radians(40.0f));
        const float a = glm::radians(incidenceDeg);
        addLight(s, directional(2.0f), glm::vec3(0, 5, 0), glm::vec3(std::sin(a), -std::cos(a), 0));
        const render::RenderSettings rs = settings(48);
        const image::ImageRGBA32F img = render(s, rs);
        const glm::vec3 want = rho * 2.0f * std::cos(a) / kPi;
        for (uint32_t y = 0; y < rs.height; ++y)
            for (uint32_t x = 0; x < rs.width; ++x) expectNear(pixel(img, x, y), want, 4e-4f, "directional", x, y);
    }
}

TEST_F(DirectLighting, PointLightFollowsInverseSquareAndCosine) {
    scene::Scene s;
    const glm::vec3 rho(0.6f);
    addQuad(s, addMaterial(s, rho), glm::vec3(0), 20.0f);
    addTopDownCamera(s, 2.0f, glm::radians(60.0f));
    const glm::vec3 lp(0.3f, 0.8f, -0.2f);
    const float I = 3.0f;
    addLight(s, point(I), lp, glm::vec3(0, -1, 0));
    const render::RenderSettings rs = settings(64);
    const image::ImageRGBA32F img = render(s, rs);
    for (uint32_t y = 0; y < rs.height; ++y)
        for (uint32_t x = 0; x < rs.width; ++x) {
            const glm::vec3 P = pixelOnPlane(s, rs, x, y, 0.0f);
            const glm::vec3 toLight = lp - P;
            const float d2 = glm::dot(toLight, toLight);
            const float cosTheta = toLight.y / std::sqrt(d2);
            expectNear(pixel(img, x, y), rho * I * cosTheta / (kPi * d2), 1.1e-3f, "point", x, y);
        }
}

TEST_F(DirectLighting, SpotLightUsesSquaredGltfFalloff) {
    scene::Scene s;
    const glm::vec3 rho(0.5f);
    addQuad(s, addMaterial(s, rho), glm::vec3(0), 20.0f);
    addTopDownCamera(s, 2.0f, glm::radians(70.0f));
    scene::Light spot = point(5.0f);
    spot.type = scene::LightType::Spot;
    spot.innerConeAngle = glm::radians(20.0f);
    spot.outerConeAngle = glm::radians(40.0f);
    const glm::vec3 lp(0.0f, 1.0f, 0.0f);
    addLight(s, spot, lp, glm::vec3(0, -1, 0));
    const render::RenderSettings rs = settings(64);
    const image::ImageRGBA32F img = render(s, rs);
    int inside = 0, penumbra = 0;
    for (uint32_t y = 0; y < rs.height; ++y)
        for (uint32_t x = 0; x < rs.width; ++x) {
            const glm::vec3 P = pixelOnPlane(s, rs, x, y, 0.0f);
            const glm::vec3 toLight = lp - P;
            const float d2 = glm::dot(toLight, toLight), d = std::sqrt(d2);
            const float cosAxis = -toLight.y / d * -1.0f;  // angle between -toLight and the axis (0,-1,0)
            const float t = glm::clamp((cosAxis - std::cos(spot.outerConeAngle)) /
                                           (std::cos(spot.innerConeAngle) - std::cos(spot.outerConeAngle)),
                                       0.0f, 1.0f);
            const glm::vec3 want = rho * 5.0f * t * t * (toLight.y / d) / (kPi * d2);
            const glm::vec3 got = pixel(img, x, y);
            if (t == 0.0f) {
                ASSERT_LT(got.x, 1e-6f) << "outside the cone at (" << x << ", " << y << ")";
                continue;
            }
            inside += t == 1.0f;
            penumbra += t > 0.0f && t < 1.0f;
            // At the cone's outer edge t^2 -> 0 and the value is ~1e-6: keep an absolute floor there.
            expectNear(got, want, 5e-3f, "spot", x, y, 1e-4f * 5.0f * 0.5f / kPi);
        }
    EXPECT_GT(inside, 100);
    EXPECT_GT(penumbra, 100);
}

// Light arrives along (1,-1,0) toward the origin; a small square half-way
// blocks it. The camera looks straight down, so it sees the shadowed plane at
// the image centre beside the occluder. Checked for every light type: the
// directional map, the spot map and the point-light cube.
TEST_F(DirectLighting, OccluderCastsShadowForEveryLightType) {
    for (scene::LightType type : {scene::LightType::Directional, scene::LightType::Spot, scene::LightType::Point}) {
        SCOPED_TRACE(int(type));
        scene::Scene s;
        const glm::vec3 rho(0.8f);
        const int white = addMaterial(s, rho);
        addQuad(s, white, glm::vec3(0), 4.0f);
        addQuad(s, white, glm::vec3(-0.4f, 0.4f, 0.0f), 0.1f);
        addTopDownCamera(s, 2.0f, glm::radians(50.0f));
        const glm::vec3 lp(-0.8f, 0.8f, 0.0f), dir = glm::normalize(glm::vec3(1, -1, 0));
        scene::Light l = type == scene::LightType::Directional ? directional(3.0f) : point(2.0f);
        l.type = type;
        l.innerConeAngle = glm::radians(30.0f);  // the probes below lie within 20 degrees of the axis
        l.outerConeAngle = glm::radians(50.0f);
        addLight(s, l, lp, dir);
        const render::RenderSettings rs = settings(64);
        const image::ImageRGBA32F img = render(s, rs);

        auto unshadowed = [&](glm::vec3 P) {
            if (type == scene::LightType::Directional) return rho * 3.0f * (-dir.y) / kPi;
            const glm::vec3 toLight = lp - P;
            const float d2 = glm::dot(toLight, toLight);
            return rho * 2.0f * (toLight.y / std::sqrt(d2)) / (kPi * d2);
        };
        const glm::vec3 inShadow = pixel(img, 32, 32);
        std::printf("  light type %d: shadowed centre %.3e of the unshadowed value\n", int(type),
                    inShadow.x / unshadowed(pixelOnPlane(s, rs, 32, 32, 0.0f)).x);
        // Deep inside the shadow every filter tap of the map is occluded.
        EXPECT_EQ(inShadow.x, 0.0f) << "centre should be shadowed";
        // A lit probe on the far side of the shadow.
        const uint32_t px = 50, py = 20;
        expectNear(pixel(img, px, py), unshadowed(pixelOnPlane(s, rs, px, py, 0.0f)), 4e-4f, "lit probe", px, py);
    }
}

// Shadow-map bias at edges where two surfaces meet (lib/shadow_map.glsl). The
// sun travels down at 25 degrees from the vertical toward +x; the camera looks
// straight down. A coarse map (256 texels over the whole scene: a texel is
// about four pixels) puts every sub-texel error in plain view.
constexpr float kGraze = glm::radians(25.0f);
constexpr float kFloorHalf = 4.0f;

render::RenderSettings coarseShadowSettings(scene::Scene& s) {
    addQuad(s, addMaterial(s, glm::vec3(0.5f)), glm::vec3(0), kFloorHalf);
    addTopDownCamera(s, 1.0f, glm::radians(40.0f));
    addLight(s, directional(2.0f), glm::vec3(0, 5, 0), glm::vec3(std::sin(kGraze), -std::cos(kGraze), 0));
    render::RenderSettings rs = settings(64);
    rs.shadowMapSize = 256;
    return rs;
}

// The scene-wide directional view's texel (render/shadows.cpp: its square is the bounds' diagonal).
float coarseTexel(float top) {
    return glm::length(glm::vec3(2.0f * kFloorHalf, top, 2.0f * kFloorHalf)) / 256.0f;
}

// A wall stands on the floor along x = 0, its face toward the sun, which grazes
// it at 25 degrees as cornell-lights' sun grazes the Cornell box's ceiling. The
// floor behind it is in its shadow for x in (0, height x tan 25 degrees). A
// caster's slope-scaled bias pushed the wall's depth back by 1.5 x its steep
// slope, and light came through the corner a texel and more behind the wall
// (cornell-lights' row 107). The lookup compares the floor with the wall's own
// plane: the whole shadow is dark from a texel behind the wall (nearer, the
// 2 x 2 filter taps still see the lit floor in front of it).
TEST_F(DirectLighting, GrazedWallShadowsTheFloorRightBehindIt) {
    scene::Scene s;
    const float half = 0.2f;  // the wall: 0.4 m high, 0.4 m long
    render::RenderSettings rs = coarseShadowSettings(s);
    addQuad(s, addMaterial(s, glm::vec3(0.5f)), glm::vec3(0, half, 0), half,
            glm::rotation(glm::vec3(0, 1, 0), glm::vec3(-1, 0, 0)));
    const image::ImageRGBA32F img = render(s, rs);
    const float texel = coarseTexel(2.0f * half), shadowEnd = 2.0f * half * std::tan(kGraze);
    int dark = 0, lit = 0;
    for (uint32_t y = 0; y < rs.height; ++y)
        for (uint32_t x = 0; x < rs.width; ++x) {
            const glm::vec3 P = pixelOnPlane(s, rs, x, y, 0.0f);
            if (std::abs(P.z) > half - texel) continue;
            if (P.x > texel && P.x < shadowEnd - texel) {
                ++dark;
                EXPECT_EQ(pixel(img, x, y).x, 0.0f)
                    << "floor in the wall's shadow at x = " << P.x << " m (" << P.x / texel
                    << " texels behind the wall), pixel " << x << ", " << y;
            } else if (P.x < -texel || P.x > shadowEnd + texel) {
                ++lit;
                expectNear(pixel(img, x, y), glm::vec3(0.5f * 2.0f * std::cos(kGraze) / kPi), 4e-4f, "lit floor", x, y);
            }
        }
    std::printf("  texel %.4f m; %d shadowed and %d lit floor pixels checked\n", texel, dark, lit);
    EXPECT_GT(dark, 150);
    EXPECT_GT(lit, 1000);
}

// A closed box on the floor: its top and the side facing the sun meet at an
// edge both see the sun over. The side's plane, extended past that edge, runs
// inside the box under the top, so a lookup that trusted the caster's plane
// alone darkened the top along the edge (Sibenik's faceted pillars); the lookup
// also asks whether the caster lies in front of the receiver's own plane.
TEST_F(DirectLighting, LitBoxTopIsLitUpToItsEdges) {
    scene::Scene s;
    const float half = 0.1f;
    render::RenderSettings rs = coarseShadowSettings(s);
    const int grey = addMaterial(s, glm::vec3(0.5f));
    const glm::vec3 up(0, 1, 0);
    for (const glm::vec3& n : {glm::vec3(0, 1, 0), glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 0, 1),
                               glm::vec3(0, 0, -1)})
        addQuad(s, grey, glm::vec3(0, half, 0) + n * half, half, glm::rotation(up, n));
    const image::ImageRGBA32F img = render(s, rs);
    const float texel = coarseTexel(2.0f * half);
    int checked = 0;
    for (uint32_t y = 0; y < rs.height; ++y)
        for (uint32_t x = 0; x < rs.width; ++x) {
            const glm::vec3 P = pixelOnPlane(s, rs, x, y, 2.0f * half);
            // The top, all of it but a pixel's width along its edges.
            if (std::max(std::abs(P.x), std::abs(P.z)) > half - 0.012f) continue;
            ++checked;
            expectNear(pixel(img, x, y), glm::vec3(0.5f * 2.0f * std::cos(kGraze) / kPi), 4e-4f, "box top", x, y);
        }
    std::printf("  texel %.4f m; %d pixels of the box's top checked\n", texel, checked);
    EXPECT_GT(checked, 100);
}

TEST_F(DirectLighting, EmissionIsOneSidedUnlessDoubleSided) {
    const glm::vec3 Le(3.0f, 1.5f, 0.75f);
    const glm::quat flip = glm::angleAxis(glm::pi<float>(), glm::vec3(1, 0, 0));  // faces down, away from camera
    struct Case { bool flipped, doubleSided; float expectRed; };
    for (Case c : {Case{false, false, 3.0f}, Case{true, false, 0.0f}, Case{true, true, 3.0f}}) {
        scene::Scene s;
        addQuad(s, addMaterial(s, glm::vec3(0.0f), Le, c.doubleSided), glm::vec3(0), 5.0f,
                c.flipped ? flip : glm::quat(1, 0, 0, 0));
        addTopDownCamera(s, 2.0f, glm::radians(40.0f));
        const image::ImageRGBA32F img = render(s, settings(16));
        std::printf("  flipped %d doubleSided %d: %.7f (expected %.1f)\n", c.flipped, c.doubleSided, pixel(img, 8, 8).x,
                    c.expectRed);
        // 3.0 is exact in fp16 (the G-buffer's emission) and nothing else adds light.
        EXPECT_NEAR(pixel(img, 8, 8).x, c.expectRed, 1e-6f) << "flipped " << c.flipped << " doubleSided " << c.doubleSided;
    }
}

TEST_F(DirectLighting, BackgroundIsBlackAndLightsAdd) {
    scene::Scene s;
    const glm::vec3 rho(0.5f);
    addQuad(s, addMaterial(s, rho), glm::vec3(0), 0.5f);  // small: the image corners see nothing
    addTopDownCamera(s, 2.0f, glm::radians(60.0f));
    addLight(s, directional(1.0f, glm::vec3(1, 0, 0)), glm::vec3(0, 5, 0), glm::vec3(0, -1, 0));
    addLight(s, directional(2.0f, glm::vec3(0, 0, 1)), glm::vec3(0, 5, 0), glm::vec3(0, -1, 0));
    const image::ImageRGBA32F img = render(s, settings(32));
    expectNear(pixel(img, 0, 0), glm::vec3(0.0f), 0.0f, "background", 0, 0);
    expectNear(pixel(img, 16, 16), rho * glm::vec3(1.0f, 0.0f, 2.0f) / kPi, 1e-5f, "sum of lights", 16, 16);
}

// The composite pass box-filters k x k internal pixels into one output pixel.
TEST_F(DirectLighting, SupersamplingIsTheBoxAverageOfTheFineImage) {
    scene::Scene s;
    addQuad(s, addMaterial(s, glm::vec3(0.7f)), glm::vec3(0), 20.0f);
    addTopDownCamera(s, 1.0f, glm::radians(60.0f));
    addLight(s, point(1.0f), glm::vec3(0.1f, 0.3f, 0.0f), glm::vec3(0, -1, 0));
    render::RenderSettings fine = settings(64), coarse = settings(32);
    coarse.supersample = 2;
    const image::ImageRGBA32F a = render(s, fine), b = render(s, coarse);
    for (uint32_t y = 0; y < 32; ++y)
        for (uint32_t x = 0; x < 32; ++x) {
            const glm::vec3 avg = (pixel(a, 2 * x, 2 * y) + pixel(a, 2 * x + 1, 2 * y) + pixel(a, 2 * x, 2 * y + 1) +
                                   pixel(a, 2 * x + 1, 2 * y + 1)) * 0.25f;
            expectNear(pixel(b, x, y), avg, 1e-6f, "supersample", x, y);
        }
}

}  // namespace
}  // namespace dvsgi::test
