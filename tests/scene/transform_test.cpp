// World transforms, draw list, bounds, sampler semantics and defaults, on
// scenes built in memory.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

#include "scene/load.h"

using namespace dvsgi::scene;

namespace {

Scene unitTriangleScene() {
    Scene s;
    Primitive p;
    p.vertices.resize(3);
    p.vertices[0].position = {0, 0, 0};
    p.vertices[1].position = {1, 0, 0};
    p.vertices[2].position = {0, 1, 0};
    p.indices = {0, 1, 2};
    s.primitives.push_back(p);
    s.meshes.push_back(Mesh{"tri", {0}});
    s.materials.push_back(Material{});
    return s;
}

void expectVec(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

}  // namespace

TEST(Transform, ParentTranslateChildRotate) {
    Scene s = unitTriangleScene();
    Node parent;
    parent.translation = {10, 0, 0};
    parent.children = {1};
    Node child;
    child.parent = 0;
    child.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
    child.scale = {2, 2, 2};
    child.mesh = 0;
    s.nodes = {parent, child};
    s.roots = {0};
    auto world = worldMatrices(s);
    // (1,0,0) scaled to (2,0,0), rotated to (0,2,0), then moved by the parent.
    expectVec(glm::vec3(world[1] * glm::vec4(1, 0, 0, 1)), {10, 2, 0});
    auto items = drawItems(s, world);
    ASSERT_EQ(items.size(), 1u);
    EXPECT_EQ(items[0].node, 1);
    Bounds b = worldBounds(s, items);
    ASSERT_TRUE(b.valid());
    expectVec(b.min, {8, 0, 0});
    expectVec(b.max, {10, 2, 0});
}

TEST(Transform, UnreachableNodesAreIgnored) {
    Scene s = unitTriangleScene();
    Node n;
    n.mesh = 0;
    n.translation = {5, 5, 5};
    s.nodes = {n};
    auto world = worldMatrices(s);  // no roots
    EXPECT_EQ(world[0], glm::mat4(1.0f));
    EXPECT_TRUE(drawItems(s, world).empty());
    EXPECT_FALSE(worldBounds(s, {}).valid());
}

TEST(Transform, CyclicGraphTerminates) {
    Scene s = unitTriangleScene();
    Node a, b;
    a.children = {1};
    b.children = {0};
    b.mesh = 0;
    s.nodes = {a, b};
    s.roots = {0};
    auto world = worldMatrices(s);
    EXPECT_EQ(drawItems(s, world).size(), 1u);
}

TEST(Transform, LightDirectionFollowsNode) {
    Scene s;
    Light l;
    l.type = LightType::Spot;
    s.lights = {l};
    Node n;
    n.light = 0;
    n.translation = {1, 2, 3};
    n.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));  // -Z -> -X
    n.scale = {3, 3, 3};
    s.nodes = {n};
    s.roots = {0};
    auto placed = placedLights(s, worldMatrices(s));
    ASSERT_EQ(placed.size(), 1u);
    expectVec(placed[0].position, {1, 2, 3});
    expectVec(placed[0].direction, {-1, 0, 0});
}

namespace {

AnimationChannel channel(AnimPath path, Interpolation interp, std::vector<float> times,
                         std::vector<glm::vec4> values) {
    AnimationChannel c;
    c.node = 0;
    c.path = path;
    c.interpolation = interp;
    c.times = std::move(times);
    c.values = std::move(values);
    return c;
}

Scene animated(AnimationChannel c) {
    Scene s;
    s.nodes.resize(1);
    s.roots = {0};
    s.animations.push_back(Animation{"a", {std::move(c)}});
    return s;
}

}  // namespace

TEST(Animation, LinearTranslationAndClamp) {
    Scene s = animated(channel(AnimPath::Translation, Interpolation::Linear, {1, 3}, {{0, 0, 0, 0}, {4, 8, -2, 0}}));
    applyAnimations(s, 2.0f);
    expectVec(s.nodes[0].translation, {2, 4, -1});
    applyAnimations(s, 0.0f);
    expectVec(s.nodes[0].translation, {0, 0, 0});
    applyAnimations(s, 5.0f);
    expectVec(s.nodes[0].translation, {4, 8, -2});
}

TEST(Animation, StepScale) {
    Scene s = animated(channel(AnimPath::Scale, Interpolation::Step, {0, 1, 2}, {{1, 1, 1, 0}, {2, 2, 2, 0}, {3, 3, 3, 0}}));
    applyAnimations(s, 0.99f);
    expectVec(s.nodes[0].scale, {1, 1, 1});
    applyAnimations(s, 1.0f);
    expectVec(s.nodes[0].scale, {2, 2, 2});
    applyAnimations(s, 1.5f);
    expectVec(s.nodes[0].scale, {2, 2, 2});
}

TEST(Animation, SlerpTakesShortestArc) {
    // 170 deg about Y stored with negative w: lerping the raw components would
    // swing the long way through 180+; slerp must go the short way.
    glm::quat a = glm::angleAxis(0.0f, glm::vec3(0, 1, 0));
    glm::quat b = -glm::angleAxis(glm::radians(170.0f), glm::vec3(0, 1, 0));
    Scene s = animated(channel(AnimPath::Rotation, Interpolation::Linear, {0, 1},
                               {{a.x, a.y, a.z, a.w}, {b.x, b.y, b.z, b.w}}));
    applyAnimations(s, 0.5f);
    glm::quat q = s.nodes[0].rotation;
    EXPECT_NEAR(std::abs(q.w), std::cos(glm::radians(42.5f)), 1e-5);
    EXPECT_NEAR(std::abs(q.y), std::sin(glm::radians(42.5f)), 1e-5);
    EXPECT_NEAR(glm::length(q), 1.0f, 1e-6);
}

TEST(Animation, CubicSpline) {
    // Keys 0 -> 1 with zero tangents: Hermite gives 3s^2 - 2s^3.
    std::vector<glm::vec4> v = {{0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}, {1, 2, 3, 0}, {0, 0, 0, 0}};
    Scene s = animated(channel(AnimPath::Translation, Interpolation::CubicSpline, {0, 2}, v));
    applyAnimations(s, 0.5f);
    float t = 0.25f, h = 3 * t * t - 2 * t * t * t;
    expectVec(s.nodes[0].translation, glm::vec3(1, 2, 3) * h);
    // An out-tangent on key 0 adds (s^3 - 2s^2 + s) * dt * m0.
    s.animations[0].channels[0].values[2] = {1, 0, 0, 0};
    applyAnimations(s, 0.5f);
    EXPECT_NEAR(s.nodes[0].translation.x, h + (t * t * t - 2 * t * t + t) * 2.0f, 1e-5);
    applyAnimations(s, 9.0f);
    expectVec(s.nodes[0].translation, {1, 2, 3});
}

TEST(Animation, BadChannelsAreIgnored) {
    Scene s = animated(channel(AnimPath::Translation, Interpolation::Linear, {0, 1}, {{1, 1, 1, 0}}));
    s.animations[0].channels.push_back(channel(AnimPath::Scale, Interpolation::Linear, {}, {}));
    s.animations[0].channels.back().node = 42;
    applyAnimations(s, 0.5f);
    expectVec(s.nodes[0].translation, {0, 0, 0});
}

TEST(Defaults, CameraFramesBoundsAndSunAdded) {
    Scene s = unitTriangleScene();
    Node n;
    n.mesh = 0;
    s.nodes = {n};
    s.roots = {0};
    addDefaults(s);
    auto world = worldMatrices(s);
    auto cams = placedCameras(s, world);
    ASSERT_EQ(cams.size(), 1u);
    EXPECT_NEAR(cams[0].camera.yfov, 0.6860478f, 1e-6);
    glm::vec3 eye = glm::vec3(cams[0].world[3]);
    glm::vec3 forward = -glm::vec3(cams[0].world[2]);
    expectVec(forward, {0, 0, -1});
    EXPECT_NEAR(eye.x, 0.5f, 1e-5);
    EXPECT_NEAR(eye.y, 0.5f, 1e-5);
    EXPECT_GT(eye.z, 0.0f);
    // Every corner of the bounds lies inside the vertical field of view.
    for (glm::vec3 corner : {glm::vec3(0, 0, 0), glm::vec3(1, 1, 0), glm::vec3(0, 1, 0)}) {
        glm::vec3 d = corner - eye;
        float angle = std::atan(std::abs(d.y) / -d.z);
        EXPECT_LE(angle, 0.5f * cams[0].camera.yfov);
        EXPECT_GT(-d.z, cams[0].camera.znear);
        EXPECT_LT(-d.z, cams[0].camera.zfar);
    }
    auto lights = placedLights(s, world);
    ASSERT_EQ(lights.size(), 1u);
    EXPECT_EQ(lights[0].light.name, "default_sun");
    EXPECT_EQ(lights[0].light.type, LightType::Directional);
    EXPECT_FLOAT_EQ(lights[0].light.intensity, 3.0f);
    EXPECT_EQ(lights[0].light.color, glm::vec3(1));
    expectVec(lights[0].direction, glm::normalize(glm::vec3(-0.3f, -1.0f, -0.5f)));
    EXPECT_EQ(s.roots.size(), 3u);  // the new nodes are roots
    EXPECT_EQ(s.nodes[s.roots[1]].name, "default_camera");
    EXPECT_EQ(s.nodes[s.roots[2]].name, "default_sun");

    size_t nodes = s.nodes.size();
    addDefaults(s);  // idempotent
    EXPECT_EQ(s.nodes.size(), nodes);
}

TEST(Defaults, EmissiveSceneGetsNoSun) {
    Scene s = unitTriangleScene();
    s.materials[0].emissiveFactor = {1, 1, 1};
    Node n;
    n.mesh = 0;
    s.nodes = {n};
    s.roots = {0};
    addDefaults(s);
    EXPECT_TRUE(s.lights.empty());
    EXPECT_EQ(s.cameras.size(), 1u);
}

TEST(Defaults, EmptySceneStillGetsCamera) {
    Scene s;
    addDefaults(s);
    EXPECT_EQ(s.cameras.size(), 1u);
    EXPECT_EQ(s.lights.size(), 1u);
}
