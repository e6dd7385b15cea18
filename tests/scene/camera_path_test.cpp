// Camera paths: parsing (and its errors), interpolation, and placing a scene's
// camera node under a transformed parent.
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "scene/camera_path.h"

namespace dvsgi::scene {
namespace {

glm::vec3 forward(const glm::mat4& world) { return glm::normalize(-glm::vec3(world[2])); }
glm::vec3 position(const glm::mat4& world) { return glm::vec3(world[3]); }

void expectNear(glm::vec3 a, glm::vec3 b, float tol, const std::string& what) {
    EXPECT_LT(glm::length(a - b), tol) << what << ": (" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x
                                       << ", " << b.y << ", " << b.z << ")";
}

const char* kWalk = R"({
  "interpolation": "linear",
  "keyframes": [
    {"time": 0, "position": [0, 1, 5], "target": [0, 1, 0], "yfov_degrees": 40},
    {"time": 2, "position": [4, 1, 5], "target": [4, 1, 0], "yfov_degrees": 60},
    {"time": 3, "position": [4, 3, 5], "orientation": [0, 0.7071068, 0, 0.7071068]}
  ]
})";

TEST(CameraPath, KeysArePassedExactly) {
    const CameraPath p = parseCameraPath(kWalk, "walk.json");
    ASSERT_EQ(p.keys.size(), 3u);
    CameraPose a = sampleCameraPath(p, 0.0f), b = sampleCameraPath(p, 2.0f), c = sampleCameraPath(p, 3.0f);
    expectNear(position(a.world), {0, 1, 5}, 1e-5f, "key 0");
    expectNear(forward(a.world), {0, 0, -1}, 1e-5f, "key 0 looks at its target");
    expectNear(position(b.world), {4, 1, 5}, 1e-5f, "key 1");
    expectNear(position(c.world), {4, 3, 5}, 1e-5f, "key 2");
    // A quarter turn about +Y: -Z turns to -X.
    expectNear(forward(c.world), {-1, 0, 0}, 1e-5f, "key 2 orientation");
    ASSERT_TRUE(a.yfov && b.yfov);
    EXPECT_NEAR(*a.yfov, glm::radians(40.0f), 1e-6f);
    EXPECT_NEAR(*b.yfov, glm::radians(60.0f), 1e-6f);
}

TEST(CameraPath, LinearInterpolatesPositionAndFieldOfView) {
    const CameraPath p = parseCameraPath(kWalk, "walk.json");
    const CameraPose m = sampleCameraPath(p, 1.0f);
    expectNear(position(m.world), {2, 1, 5}, 1e-5f, "midpoint");
    expectNear(forward(m.world), {0, 0, -1}, 1e-5f, "same orientation at both keys");
    ASSERT_TRUE(m.yfov);
    EXPECT_NEAR(*m.yfov, glm::radians(50.0f), 1e-5f);
    // Between keys 1 and 2 the orientation turns halfway: 45 degrees.
    expectNear(forward(sampleCameraPath(p, 2.5f).world), glm::normalize(glm::vec3(-1, 0, -1)), 1e-5f, "slerp");
}

TEST(CameraPath, ClampsOutsideTheKeysAndWrapsWhenLooping) {
    CameraPath p = parseCameraPath(kWalk, "walk.json");
    expectNear(position(sampleCameraPath(p, -5.0f).world), {0, 1, 5}, 1e-5f, "before");
    expectNear(position(sampleCameraPath(p, 9.0f).world), {4, 3, 5}, 1e-5f, "after");
    p.loop = true;
    expectNear(position(sampleCameraPath(p, 4.0f).world), {2, 1, 5}, 1e-5f, "one period later");
    expectNear(position(sampleCameraPath(p, -2.0f).world), {2, 1, 5}, 1e-5f, "one period earlier");
}

TEST(CameraPath, CatmullRomPassesTheKeysSmoothly) {
    const std::string text = R"({"keyframes": [
      {"time": 0, "position": [0, 0, 0], "target": [0, 0, -1]},
      {"time": 1, "position": [1, 0, 0], "target": [1, 0, -1]},
      {"time": 2, "position": [1, 1, 0], "target": [1, 1, -1]},
      {"time": 3, "position": [0, 1, 0], "target": [0, 1, -1]}]})";
    const CameraPath p = parseCameraPath(text, "square.json");
    EXPECT_TRUE(p.catmullRom);  // the default
    for (int k = 0; k < 4; ++k)
        expectNear(position(sampleCameraPath(p, float(k)).world), p.keys[size_t(k)].position, 1e-5f, "key");
    // The velocity is continuous across an inner key: equal one-sided differences.
    const float h = 1e-3f;
    const glm::vec3 before = (position(sampleCameraPath(p, 1.0f).world) -
                              position(sampleCameraPath(p, 1.0f - h).world)) / h;
    const glm::vec3 after = (position(sampleCameraPath(p, 1.0f + h).world) -
                             position(sampleCameraPath(p, 1.0f).world)) / h;
    expectNear(before, after, 0.02f, "velocity at key 1");
    // Uniform Catmull-Rom: the tangent at key 1 is half the chord from key 0 to key 2.
    expectNear(before, 0.5f * (p.keys[2].position - p.keys[0].position), 0.02f, "tangent");
}

void expectError(const std::string& text, const std::string& fragment) {
    try {
        parseCameraPath(text, "bad.json");
        ADD_FAILURE() << "accepted: " << text;
    } catch (const std::runtime_error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("bad.json"), std::string::npos) << m;
        EXPECT_NE(m.find(fragment), std::string::npos) << "'" << m << "' lacks '" << fragment << "'";
    }
}

TEST(CameraPath, MalformedPathsNameTheFileAndTheProblem) {
    expectError("{", "not valid JSON");
    expectError("[]", "top level");
    expectError(R"({"keyframes": []})", "non-empty");
    expectError(R"({"keys": []})", "unknown field 'keys'");
    expectError(R"({"keyframes": [{"position": [0,0,0], "target": [0,0,-1]}]})", "no 'time'");
    expectError(R"({"keyframes": [{"time": 0, "target": [0,0,-1]}]})", "no 'position'");
    expectError(R"({"keyframes": [{"time": 0, "position": [0,0,0]}]})", "exactly one of");
    expectError(R"({"keyframes": [{"time": 0, "position": [0,0,0], "target": [0,0,-1], "orientation": [0,0,0,1]}]})",
                "exactly one of");
    expectError(R"({"keyframes": [{"time": 0, "position": [0,0], "target": [0,0,-1]}]})", "array of 3");
    expectError(R"({"keyframes": [{"time": 0, "position": [0,0,0], "target": [0,0,0]}]})", "on 'position'");
    expectError(R"({"keyframes": [{"time": 0, "position": [0,0,0], "orientation": [0,0,0,0]}]})", "zero quaternion");
    expectError(R"({"keyframes": [{"time": 0, "position": [0,0,0], "target": [0,0,-1], "yfov_degrees": 180}]})",
                "(0, 180)");
    expectError(R"({"keyframes": [{"time": 1, "position": [0,0,0], "target": [0,0,-1]},
                                  {"time": 1, "position": [1,0,0], "target": [1,0,-1]}]})",
                "keyframe 1 'time' does not increase");
    expectError(R"({"keyframes": [{"time": "0", "position": [0,0,0], "target": [0,0,-1]}]})", "not a number");
    expectError(R"({"interpolation": "cubic", "keyframes": [{"time": 0, "position": [0,0,0], "target": [0,0,-1]}]})",
                "catmull-rom");
    expectError(R"({"loop": 1, "keyframes": [{"time": 0, "position": [0,0,0], "target": [0,0,-1]}]})", "'loop'");
}

TEST(CameraPath, MissingFileIsNamed) {
    try {
        loadCameraPath("/nonexistent/walk.json");
        ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/walk.json"), std::string::npos) << e.what();
    }
}

TEST(CameraPath, AppliesToTheCameraNodeUnderATransformedParent) {
    Scene s;
    s.cameras.push_back(Camera{"cam"});
    Node parent;
    parent.name = "rig";
    parent.translation = glm::vec3(10, 0, 0);
    parent.rotation = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 2, 3)));
    Node cam;
    cam.name = "cam";
    cam.parent = 0;
    cam.camera = 0;
    parent.children.push_back(1);
    s.nodes = {parent, cam};
    s.roots = {0};
    const CameraPath p = parseCameraPath(kWalk, "walk.json");
    applyCameraPath(s, 0, p, 1.0f);
    const std::vector<PlacedCamera> placed = placedCameras(s, worldMatrices(s));
    ASSERT_EQ(placed.size(), 1u);
    const CameraPose want = sampleCameraPath(p, 1.0f);
    expectNear(position(placed[0].world), position(want.world), 1e-4f, "position");
    expectNear(forward(placed[0].world), forward(want.world), 1e-4f, "direction");
    EXPECT_NEAR(placed[0].camera.yfov, glm::radians(50.0f), 1e-5f);
    EXPECT_THROW(applyCameraPath(s, 1, p, 0.0f), std::runtime_error);  // no second camera
}

TEST(CameraPath, WrittenPathsReadBackTheSame) {
    const CameraPath p = parseCameraPath(kWalk, "walk.json");
    const CameraPath q = parseCameraPath(cameraPathJson(p), "again.json");
    ASSERT_EQ(q.keys.size(), p.keys.size());
    EXPECT_EQ(q.catmullRom, p.catmullRom);
    for (float t : {0.0f, 0.7f, 2.2f, 3.0f}) {
        const CameraPose a = sampleCameraPath(p, t), b = sampleCameraPath(q, t);
        expectNear(position(a.world), position(b.world), 1e-4f, "position");
        expectNear(forward(a.world), forward(b.world), 1e-4f, "direction");
    }
}

}  // namespace
}  // namespace dvsgi::scene
