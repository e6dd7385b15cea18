// Scene values that overflow, go negative or make a camera singular are
// rejected (or repaired) by loadScene; large hierarchies load in linear time.
#include <cmath>

#include <sys/stat.h>

#include <gtest/gtest.h>

#include "scene/load.h"
#include "test_support.h"

using namespace dvsgi::scene;
using namespace scene_test;

namespace {

// triangleScene plus light 0 on node 1.
GltfBuilder withLight(const json& light) {
    GltfBuilder b = triangleScene();
    b.doc["extensions"]["KHR_lights_punctual"]["lights"] = json::array({light});
    b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    b.doc["scenes"][0]["nodes"].push_back(1);
    return b;
}

// triangleScene plus camera 0 on a node with `node` fields.
GltfBuilder withCamera(const json& perspective, json node = json::object()) {
    GltfBuilder b = triangleScene();
    b.doc["cameras"] = json::array({{{"type", "perspective"}, {"perspective", perspective}}});
    node["camera"] = 0;
    b.addNode(node);
    b.doc["scenes"][0]["nodes"].push_back(1);
    return b;
}

const json kGoodPerspective = {{"yfov", 0.7}, {"znear", 0.1}, {"zfar", 100}};

}  // namespace

TEST(SceneValues, LightIntensityNearFloatMaxRejected) {
    TempDir dir;
    auto b = withLight({{"type", "point"}, {"intensity", 3e38}});
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "light 0: intensity x color = ");
    auto c = withLight({{"type", "point"}, {"intensity", 1e4}, {"color", {3e38, 1, 1}}});
    expectError(c.writeGltfExternal(dir, "b.gltf", "b.bin"), "exceeds the limit");
}

TEST(SceneValues, NegativeLightValuesRejected) {
    TempDir dir;
    auto b = withLight({{"type", "point"}, {"intensity", -5}});
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "light 0: intensity -5 is negative");
    auto c = withLight({{"type", "directional"}, {"color", {1, -0.5, 1}}});
    expectError(c.writeGltfExternal(dir, "b.gltf", "b.bin"), "light 0: color -0.5 is negative");
}

TEST(SceneValues, SpotConeAnglesChecked) {
    TempDir dir;
    auto b = withLight({{"type", "spot"}, {"spot", {{"innerConeAngle", 0.5}, {"outerConeAngle", 2.0}}}});
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "spot cone angles");
}

TEST(SceneValues, BaseColourNegativeRejectedAboveOneClamped) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    b.doc["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, -1, 0.5, 1}}}}}});
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "material 0: baseColorFactor -1 is negative");

    b.doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {3e38, 0.5, 0.5, 1};
    Scene s = loadScene(b.writeGltfExternal(dir, "b.gltf", "b.bin"));
    EXPECT_EQ(s.materials[0].baseColorFactor, glm::vec4(1, 0.5, 0.5, 1));
    bool warned = false;
    for (const std::string& w : s.warnings) warned = warned || w.find("baseColorFactor above 1") != std::string::npos;
    EXPECT_TRUE(warned);
}

TEST(SceneValues, EmissionOverflowAndNegativeRejected) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    b.doc["materials"] = json::array(
        {{{"emissiveFactor", {1, 1, 1}},
          {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 3e38}}}}}}});
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "emissiveFactor x emissiveStrength");
    b.doc["materials"][0].erase("extensions");
    b.doc["materials"][0]["emissiveFactor"] = {0, -2, 0};
    expectError(b.writeGltfExternal(dir, "b.gltf", "b.bin"), "emissiveFactor -2 is negative");
}

TEST(SceneValues, DegenerateCamerasRejected) {
    TempDir dir;
    struct Case {
        json perspective;
        json node;
        const char* fragment;
    };
    const Case cases[] = {
        {kGoodPerspective, {{"scale", {0, 0, 0}}}, "camera's transform is singular"},
        {kGoodPerspective, {{"scale", {1, 0, 1}}}, "camera's transform is singular"},
        {kGoodPerspective, {{"matrix", {1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 5, 1}}}, "singular"},
        {{{"yfov", 3.1416}, {"znear", 0.1}, {"zfar", 100}}, json::object(), "yfov 3.14159989 must be in (0, pi)"},
        {{{"yfov", 4.0}, {"znear", 0.1}, {"zfar", 100}}, json::object(), "yfov"},
        {{{"yfov", 0.7}, {"znear", 1.0}, {"zfar", 1.0000001}}, json::object(), "zfar"},
        {{{"yfov", 0.7}, {"znear", 0.1}, {"zfar", 100}, {"aspectRatio", -1}}, json::object(), "aspectRatio"},
    };
    int n = 0;
    for (const Case& c : cases) {
        auto b = withCamera(c.perspective, c.node);
        std::string name = "c" + std::to_string(n++);
        expectError(b.writeGltfExternal(dir, name + ".gltf", name + ".bin"), c.fragment);
    }
    auto ok = withCamera(kGoodPerspective, {{"scale", {0.001, 0.001, 0.001}}});
    EXPECT_NO_THROW(loadScene(ok.writeGltfExternal(dir, "ok.gltf", "ok.bin")));
}

TEST(SceneValues, HugeNodeScaleOverflowingTheBoundsRejected) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    b.doc["nodes"][0]["scale"] = {3e38, 3e38, 3e38};
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "scene extent");
}

TEST(SceneValues, GltfZeroNormalReplacedByTheFaceNormal) {
    TempDir dir;
    GltfBuilder b;
    // Counter-clockwise seen from +Z: the face normal is +Z.
    int pos = b.addVec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const float nan = std::nanf("");
    int nrm = b.addVec3({{0, 0, 0}, {nan, nan, nan}, {0, 2, 0}});
    b.addMesh(pos, nrm, -1);
    b.addNode({{"mesh", 0}});
    Scene s = loadScene(b.writeGltfExternal(dir, "a.gltf", "a.bin"));
    const auto& v = s.primitives[0].vertices;
    EXPECT_EQ(v[0].normal, glm::vec3(0, 0, 1));
    EXPECT_EQ(v[1].normal, glm::vec3(0, 0, 1));
    EXPECT_EQ(v[2].normal, glm::vec3(0, 1, 0));  // usable: only normalized
    bool warned = false;
    for (const std::string& w : s.warnings) warned = warned || w.find("2 vertex normal(s)") != std::string::npos;
    EXPECT_TRUE(warned);
}

TEST(SceneValues, QuaternionNearFloatMaxIsNormalizedNotZeroed) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    b.doc["nodes"][0]["rotation"] = {0, 3e38, 0, 3e38};  // 90 degrees about Y
    Scene s = loadScene(b.writeGltfExternal(dir, "a.gltf", "a.bin"));
    EXPECT_NEAR(s.nodes[0].rotation.w, std::sqrt(0.5f), 1e-6);
    EXPECT_NEAR(s.nodes[0].rotation.y, std::sqrt(0.5f), 1e-6);
}

// The cycle check walked every node's whole parent chain: quadratic, minutes
// for this file. It must now be linear (this test takes well under a second).
TEST(SceneNodes, LongParentChainLoads) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    const int n = 200000;
    json& nodes = b.doc["nodes"];
    nodes[0]["children"] = {1};
    for (int i = 1; i < n; ++i) {
        json node = json::object();
        if (i + 1 < n) node["children"] = {i + 1};
        nodes.push_back(std::move(node));
    }
    Scene s = loadScene(b.writeGltfExternal(dir, "chain.gltf", "chain.bin"));
    EXPECT_EQ(s.nodes[n - 1].parent, n - 2);
    EXPECT_EQ(drawItems(s, worldMatrices(s)).size(), 1u);
}

TEST(SceneNodes, FiftyThousandInstancesLoad) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    json& nodes = b.doc["nodes"];
    json& roots = b.doc["scenes"][0]["nodes"];
    for (int i = 1; i < 50000; ++i) {
        nodes.push_back({{"mesh", 0}, {"translation", {i % 100, i / 100, 0}}});
        roots.push_back(i);
    }
    Scene s = loadScene(b.writeGltfExternal(dir, "many.gltf", "many.bin"));
    EXPECT_EQ(drawItems(s, worldMatrices(s)).size(), 50000u);
}

TEST(SceneNodes, CycleStillFound) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    b.addNode({{"children", {2}}});
    b.addNode({{"children", {3}}});
    b.addNode({{"children", {1}}});
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "cycle");
}

TEST(SceneErrors, JsonNumberOverflowNamesTheFile) {
    TempDir dir;
    writeText(dir.file("a.gltf"), R"({"asset": {"version": "2.0"}, "nodes": [{"translation": [1e400, 0, 0]}]})");
    expectError(dir.file("a.gltf"), "invalid JSON");
}

TEST(SceneErrors, IndexMinusOneHasAReadableCount) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    b.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = -1;
    std::string msg = loadError(b.writeGltfExternal(dir, "a.gltf", "a.bin"));
    EXPECT_NE(msg.find("accessor index -1 out of range (3 accessors)"), std::string::npos) << msg;
    b.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 18446744073709551615ull;
    msg = loadError(b.writeGltfExternal(dir, "b.gltf", "b.bin"));
    EXPECT_EQ(msg.find("18446744073709551615 accessors"), std::string::npos) << msg;
}

TEST(SceneErrors, DirectoryAndFifoSaySo) {
    TempDir dir;
    fs::create_directories(dir.path() / "folder.gltf");
    expectError(dir.file("folder.gltf"), "is a directory");
    ASSERT_EQ(mkfifo(dir.file("pipe.gltf").c_str(), 0600), 0);
    expectError(dir.file("pipe.gltf"), "is not a regular file");
    expectError(dir.file("absent.gltf"), "no such file");
}
