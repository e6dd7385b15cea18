// OBJ/MTL/PLY inputs that made assimp abort, loop or pass NaN along must end
// in a LoadError naming the file, and nearby valid inputs must still load.
#include <gtest/gtest.h>

#include "scene/load.h"
#include "test_support.h"

using namespace dvsgi::scene;
using namespace scene_test;

namespace {

const char* kPlyHeader = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                         "property float z\nelement face 1\nproperty list uchar int vertex_indices\n";

std::string ply(const std::string& body) { return std::string(kPlyHeader) + "end_header\n" + body; }

// Little- or big-endian binary PLY of one triangle.
std::vector<uint8_t> binaryPly(bool bigEndian, uint8_t corners) {
    std::string header = std::string("ply\nformat ") + (bigEndian ? "binary_big_endian" : "binary_little_endian") +
                         " 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                         "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    std::vector<uint8_t> out(header.begin(), header.end());
    auto put = [&](const void* p, size_t n) {
        const uint8_t* b = static_cast<const uint8_t*>(p);
        for (size_t i = 0; i < n; ++i) out.push_back(b[bigEndian ? n - 1 - i : i]);
    };
    const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    for (float f : pos) put(&f, 4);
    out.push_back(corners);
    for (int32_t i = 0; i < corners; ++i) put(&i, 4);
    return out;
}

size_t triangles(const Scene& s) {
    size_t n = 0;
    for (const Primitive& p : s.primitives) n += p.indices.size() / 3;
    return n;
}

}  // namespace

TEST(PlyPrecheck, MissingEndHeaderIsAnErrorNotAHang) {
    TempDir dir;
    writeText(dir.file("a.ply"), std::string(kPlyHeader) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    expectError(dir.file("a.ply"), "no end_header");
}

TEST(PlyPrecheck, TruncatedAscii) {
    TempDir dir;
    writeText(dir.file("a.ply"), ply("0 0 0\n1 0 0\n"));
    expectError(dir.file("a.ply"), "truncated");
}

TEST(PlyPrecheck, TruncatedBinary) {
    TempDir dir;
    auto bytes = binaryPly(false, 3);
    bytes.resize(bytes.size() - 5);
    writeBytes(dir.file("a.ply"), bytes);
    expectError(dir.file("a.ply"), "truncated");
}

TEST(PlyPrecheck, HugeCountWithLittleData) {
    TempDir dir;
    std::string text = ply("0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    text.replace(text.find("vertex 3"), 8, "vertex 4000000000");
    writeText(dir.file("a.ply"), text);
    expectError(dir.file("a.ply"), "truncated");
}

TEST(PlyPrecheck, FaceWithZeroIndices) {
    TempDir dir;
    writeText(dir.file("a.ply"), ply("0 0 0\n1 0 0\n0 1 0\n0\n"));
    expectError(dir.file("a.ply"), "face 0 has 0 vertex indices");
    writeBytes(dir.file("b.ply"), binaryPly(false, 0));
    expectError(dir.file("b.ply"), "face 0 has 0 vertex indices");
}

TEST(PlyPrecheck, FaceIndexOutOfRange) {
    TempDir dir;
    writeText(dir.file("a.ply"), ply("0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n"));
    expectError(dir.file("a.ply"), "refers to vertex 9 of 3");
}

TEST(PlyPrecheck, NonFinitePosition) {
    TempDir dir;
    writeText(dir.file("a.ply"), ply("0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"));
    expectError(dir.file("a.ply"), "vertex 1 has a non-finite position");
    writeText(dir.file("b.ply"), ply("0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n"));
    expectError(dir.file("b.ply"), "non-finite position");
}

TEST(PlyPrecheck, NotANumber) {
    TempDir dir;
    writeText(dir.file("a.ply"), ply("0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n"));
    expectError(dir.file("a.ply"), "'zero' is not a number");
}

TEST(PlyPrecheck, NoVertexElement) {
    TempDir dir;
    writeText(dir.file("a.ply"), "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
                                 "end_header\n3 0 1 2\n");
    expectError(dir.file("a.ply"), "no 'vertex' element");
}

TEST(PlyPrecheck, ValidBinaryBothEndiannessesLoad) {
    TempDir dir;
    writeBytes(dir.file("le.ply"), binaryPly(false, 3));
    writeBytes(dir.file("be.ply"), binaryPly(true, 3));
    for (const char* name : {"le.ply", "be.ply"}) {
        Scene s = loadScene(dir.file(name));
        EXPECT_EQ(triangles(s), 1u) << name;
        Bounds b = worldBounds(s, drawItems(s, worldMatrices(s)));
        EXPECT_EQ(b.max, glm::vec3(1, 1, 0)) << name;
    }
}

TEST(ObjPrecheck, NonFinitePositionNamesTheLine) {
    TempDir dir;
    writeText(dir.file("a.obj"), "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
    expectError(dir.file("a.obj"), "line 2 ('v'): value 'nan' is not finite");
    writeText(dir.file("b.obj"), "v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n");
    expectError(dir.file("b.obj"), "line 2");
}

TEST(ObjPrecheck, FaceWithTooFewVertices) {
    TempDir dir;
    writeText(dir.file("a.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf\nf 1 2\n");
    expectError(dir.file("a.obj"), "line 4: 'f' with 0 vertices");
}

TEST(ObjPrecheck, IndexOutOfRange) {
    TempDir dir;
    writeText(dir.file("a.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
    expectError(dir.file("a.obj"), "vertex index 4 out of range (3 defined)");
    writeText(dir.file("b.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n");
    expectError(dir.file("b.obj"), "vertex index -4 out of range");
    writeText(dir.file("c.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n");
    expectError(dir.file("c.obj"), "malformed vertex reference '0'");
    writeText(dir.file("d.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n");
    expectError(dir.file("d.obj"), "normal index 2 out of range");
}

// Found by fuzz_objply: assimp reads any statement starting with 'f' as a
// face, so "f12 48//12" reached its out-of-range error path, which leaks.
TEST(ObjPrecheck, StatementsAssimpWouldMisreadAreRefused) {
    TempDir dir;
    writeText(dir.file("a.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf12 48//12\n");
    expectError(dir.file("a.obj"), "line 5: unknown statement 'f12' (assimp would read it as 'f')");
    writeText(dir.file("b.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nface 1 2 3\n");
    expectError(dir.file("b.obj"), "unknown statement 'face'");
    writeText(dir.file("c.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nvtx 0 0\nf 1 2 3\n");
    expectError(dir.file("c.obj"), "unknown statement 'vtx' (assimp would read it as 'v')");
}

// Found by fuzz_objply: assimp's in-memory IO crashed when an OBJ read from
// memory named an mtllib.
TEST(ObjPrecheck, MtllibFromMemoryDoesNotCrash) {
    const std::string obj = "mtllib vtm\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    Scene s = loadWithAssimpFromMemory("mem.obj", ".obj", reinterpret_cast<const uint8_t*>(obj.data()), obj.size());
    EXPECT_EQ(triangles(s), 1u);
}

TEST(ObjPrecheck, RelativeIndicesAndQuadsStillLoad) {
    TempDir dir;
    writeText(dir.file("a.obj"), "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf -4 -3 -2 -1\n");
    Scene s = loadScene(dir.file("a.obj"));
    EXPECT_EQ(triangles(s), 2u);
}

TEST(ObjPrecheck, MtlNanOpacityNamesTheValue) {
    TempDir dir;
    writeText(dir.file("m.mtl"), "newmtl a\nKd 1 1 1\nd nan\n");
    writeText(dir.file("a.obj"), "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
    std::string msg = loadError(dir.file("a.obj"));
    EXPECT_NE(msg.find("m.mtl"), std::string::npos) << msg;
    EXPECT_NE(msg.find("('d'): value 'nan' is not finite"), std::string::npos) << msg;
}

TEST(ObjValues, NegativeDiffuseColourRejected) {
    TempDir dir;
    writeText(dir.file("m.mtl"), "newmtl a\nKd 0.5 -1 0.5\n");
    writeText(dir.file("a.obj"), "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
    expectError(dir.file("a.obj"), "diffuse colour (Kd) -1 is negative");
}

TEST(ObjValues, ZeroAndNanNormalsReplacedByTheFaceNormal) {
    TempDir dir;
    // The triangle lies in the x = 0 plane, counter-clockwise seen from +X.
    writeText(dir.file("a.obj"), "v 0 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 0\nf 1//1 2//1 3//1\n");
    writeText(dir.file("b.obj"), "v 0 0 0\nv 0 1 0\nv 0 0 1\nvn nan nan nan\nf 1//1 2//1 3//1\n");
    for (const char* name : {"a.obj", "b.obj"}) {
        Scene s = loadScene(dir.file(name));
        ASSERT_EQ(s.primitives.size(), 1u) << name;
        for (const Vertex& v : s.primitives[0].vertices) {
            EXPECT_NEAR(v.normal.x, 1.0f, 1e-5) << name;
            EXPECT_NEAR(v.normal.y, 0.0f, 1e-5) << name;
            EXPECT_NEAR(v.normal.z, 0.0f, 1e-5) << name;
            EXPECT_TRUE(std::isfinite(v.tangent.x) && std::isfinite(v.tangent.y) && std::isfinite(v.tangent.z))
                << name;
        }
    }
}

TEST(ObjReferences, TextureAndMtlOutsideTheFolderRejected) {
    TempDir dir;
    fs::create_directories(dir.path() / "scene");
    writePng(dir.file("secret.png"), 1, 1, {1, 2, 3, 255});
    writeText(dir.file("scene/m.mtl"), "newmtl a\nKd 1 1 1\nmap_Kd ../secret.png\n");
    writeText(dir.file("scene/a.obj"), "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
    expectError(dir.file("scene/a.obj"), "texture '../secret.png' points outside the scene's folder");

    writeText(dir.file("outside.mtl"), "newmtl a\nKd 1 1 1\n");
    writeText(dir.file("scene/b.obj"), "mtllib ../outside.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    expectError(dir.file("scene/b.obj"), "mtllib '../outside.mtl' points outside");

    // The option lifts the confinement for scenes the user trusts.
    LoadOptions o;
    o.allowOutsideReferences = true;
    Scene s = loadScene(dir.file("scene/a.obj"), o);
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.textures[0].rgba8[0], 1);
}
