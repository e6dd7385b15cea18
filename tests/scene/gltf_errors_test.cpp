// Malformed input must end in a LoadError that names the file, never a crash.
#include <random>

#include <gtest/gtest.h>

#include "scene/load.h"
#include "test_support.h"

using namespace dvsgi::scene;
using namespace scene_test;

TEST(GltfErrors, MissingFile) {
    TempDir dir;
    expectError(dir.file("absent.gltf"), "no such file");
}

TEST(GltfErrors, UnknownExtension) {
    TempDir dir;
    writeText(dir.file("scene.xyz"), "hello");
    expectError(dir.file("scene.xyz"), "unsupported scene format '.xyz' (supported: .gltf .glb .obj .ply)");
}

TEST(GltfErrors, InvalidJson) {
    TempDir dir;
    writeText(dir.file("bad.gltf"), "{ \"asset\": { \"version\": \"2.0\" }, ");
    expectError(dir.file("bad.gltf"), "invalid JSON");
}

TEST(GltfErrors, MissingAsset) {
    TempDir dir;
    writeText(dir.file("bad.gltf"), "{}");
    expectError(dir.file("bad.gltf"), "asset");
}

TEST(GltfErrors, AccessorOutOfRange) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    b.doc["accessors"][0]["count"] = 4;  // 3 positions stored
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "accessor 0 reads past the end");
}

TEST(GltfErrors, AccessorIndexOutOfRange) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    b.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 99;
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "accessor index 99 out of range");
}

TEST(GltfErrors, BufferViewPastBuffer) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    b.doc["bufferViews"][1]["byteOffset"] = 1000000;
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "reads past the end of buffer 0");
}

TEST(GltfErrors, WrongAccessorType) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    b.doc["accessors"][0]["type"] = "VEC2";
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "expected VEC3");
}

TEST(GltfErrors, MissingBin) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    std::string path = b.writeGltfExternal(dir, "a.gltf", "a.bin");
    std::filesystem::remove(dir.file("a.bin"));
    expectError(path, "cannot read 'a.bin'");
}

TEST(GltfErrors, ShortBin) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    std::string path = b.writeGltfExternal(dir, "a.gltf", "a.bin");
    writeBytes(dir.file("a.bin"), {1, 2, 3});
    expectError(path, "byteLength");
}

TEST(GltfErrors, BadMeshIndexInNode) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    b.doc["nodes"][0]["mesh"] = 5;
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "node 0: mesh index 5 out of range");
}

TEST(GltfErrors, NegativeIndex) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    b.doc["nodes"][0]["mesh"] = -1;
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "out of range");
}

TEST(GltfErrors, VertexIndexOutOfRange) {
    TempDir dir;
    GltfBuilder b;
    b.addMesh(b.addVec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, b.addIndices({0, 1, 7}, kUShort));
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "vertex index 7 out of range");
}

TEST(GltfErrors, UnsupportedPrimitiveMode) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    b.doc["meshes"][0]["primitives"][0]["mode"] = 1;
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "unsupported primitive mode");
}

TEST(GltfErrors, SparseAccessor) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    b.doc["accessors"][0]["sparse"] = {{"count", 1}};
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "sparse");
}

TEST(GltfErrors, CyclicHierarchy) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    b.addNode({{"children", {2}}});
    b.addNode({{"children", {1}}});
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "cycle");
}

TEST(GltfErrors, WrongJsonTypes) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    b.doc["nodes"][0]["translation"] = "up";
    expectError(b.writeGltfExternal(dir, "a.gltf", "a.bin"), "translation");
    GltfBuilder c = triangleScene();
    c.doc["meshes"] = 3;
    expectError(c.writeGltfExternal(dir, "b.gltf", "b.bin"), "meshes");
}

TEST(GltfErrors, TruncatedGlb) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    auto bytes = b.glbBytes();
    bytes.resize(bytes.size() - 10);
    writeBytes(dir.file("t.glb"), bytes);
    expectError(dir.file("t.glb"), "GLB");
}

// Random corruption of a valid GLB: every outcome must be a scene or a
// LoadError. Run under a sanitizer build to also catch silent bad reads.
TEST(GltfErrors, CorruptedGlbNeverCrashes) {
    TempDir dir;
    GltfBuilder b = triangleScene();
    b.doc["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 1}}}}}});
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    const auto good = b.glbBytes();
    std::mt19937 rng(1234);
    std::string path = dir.file("c.glb");
    int errors = 0;
    for (int iter = 0; iter < 400; ++iter) {
        auto bytes = good;
        int flips = 1 + static_cast<int>(rng() % 4);
        for (int f = 0; f < flips; ++f) bytes[rng() % bytes.size()] = static_cast<uint8_t>(rng());
        if (rng() % 5 == 0) bytes.resize(rng() % bytes.size());
        writeBytes(path, bytes);
        try {
            loadScene(path);
        } catch (const LoadError& e) {
            ++errors;
            EXPECT_EQ(std::string(e.what()).rfind(path, 0), 0u) << e.what();
        }
    }
    EXPECT_GT(errors, 0);
}
