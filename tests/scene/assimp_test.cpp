// OBJ+MTL and PLY through assimp, plus the shared OBJ scenes.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "scene/load.h"
#include "test_support.h"

using namespace dvsgi::scene;
using namespace scene_test;

namespace {

size_t triangleCount(const Scene& s) {
    size_t n = 0;
    for (const DrawItem& it : drawItems(s, worldMatrices(s))) n += s.primitives[it.primitive].indices.size() / 3;
    return n;
}

const Material* findMaterial(const Scene& s, const std::string& name) {
    for (const Material& m : s.materials)
        if (m.name == name) return &m;
    return nullptr;
}

const std::vector<uint8_t> kTexels = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128};

const char* kMtl = R"(newmtl shiny
Kd 0.8 0.4 0.2
Ks 0.5 0.5 0.5
Ns 98
map_Kd tex.png

newmtl plain
Kd 0.1 0.2 0.3
Ks 0 0 0
Ns 50
Ke 1 2 3

newmtl missing
Kd 1 1 1
map_Kd gone.png

newmtl cutout
Kd 1 1 1
map_Kd tex.png
map_d mask.png
)";

const char* kObj = R"(mtllib m.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 1
o first
usemtl shiny
f 1/1/1 2/2/1 3/3/1 4/4/1
o second
usemtl plain
f 5/1/1 6/2/1 7/3/1
usemtl missing
f 5/1/1 7/3/1 6/2/1
usemtl cutout
f 1/1/1 6/2/1 7/3/1
)";

}  // namespace

TEST(Assimp, ObjWithMtl) {
    TempDir dir;
    writePng(dir.file("tex.png"), 2, 2, kTexels);
    // Grey mask without alpha: its red channel is the opacity.
    writePng(dir.file("mask.png"), 2, 2, {255, 255, 255, 255, 0, 0, 0, 255, 255, 255, 255, 255, 0, 0, 0, 255});
    writeText(dir.file("m.mtl"), kMtl);
    writeText(dir.file("model.obj"), kObj);
    Scene s = loadScene(dir.file("model.obj"));
    EXPECT_EQ(triangleCount(s), 5u);  // the quad is triangulated

    const Material* shiny = findMaterial(s, "shiny");
    ASSERT_NE(shiny, nullptr);
    EXPECT_NEAR(shiny->baseColorFactor.r, 0.8f, 1e-6);
    EXPECT_NEAR(shiny->baseColorFactor.g, 0.4f, 1e-6);
    EXPECT_NEAR(shiny->baseColorFactor.b, 0.2f, 1e-6);
    EXPECT_FLOAT_EQ(shiny->baseColorFactor.a, 1.0f);
    EXPECT_NEAR(shiny->roughnessFactor, std::sqrt(2.0f / 100.0f), 1e-6);
    EXPECT_FLOAT_EQ(shiny->metallicFactor, 0.0f);
    EXPECT_EQ(shiny->alphaMode, AlphaMode::Opaque);
    ASSERT_GE(shiny->baseColorTexture, 0);
    const Texture& tex = s.textures[static_cast<size_t>(shiny->baseColorTexture)];
    EXPECT_TRUE(tex.srgb);
    EXPECT_EQ(tex.rgba8, kTexels);

    const Material* plain = findMaterial(s, "plain");
    ASSERT_NE(plain, nullptr);
    EXPECT_FLOAT_EQ(plain->roughnessFactor, 1.0f);  // Ks = 0
    EXPECT_EQ(plain->emissiveFactor, glm::vec3(1, 2, 3));
    EXPECT_EQ(plain->baseColorTexture, -1);

    const Material* missing = findMaterial(s, "missing");
    ASSERT_NE(missing, nullptr);
    EXPECT_EQ(missing->baseColorTexture, -1);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("gone.png"), std::string::npos) << s.warnings[0];

    const Material* cutout = findMaterial(s, "cutout");
    ASSERT_NE(cutout, nullptr);
    EXPECT_EQ(cutout->alphaMode, AlphaMode::Mask);
    ASSERT_GE(cutout->baseColorTexture, 0);
    const Texture& cut = s.textures[static_cast<size_t>(cutout->baseColorTexture)];
    ASSERT_EQ(cut.rgba8.size(), 16u);
    EXPECT_EQ(cut.rgba8[3], 255);
    EXPECT_EQ(cut.rgba8[7], 0);
    EXPECT_EQ(cut.rgba8[11], 255);
    EXPECT_EQ(cut.rgba8[15], 0);
    EXPECT_EQ(cut.rgba8[0], 255);  // colour untouched

    // OBJ's v runs upwards; the importer flips it to glTF's top-down v.
    bool found = false;
    for (const DrawItem& it : drawItems(s, worldMatrices(s))) {
        if (s.materials[s.primitives[it.primitive].material].name != "shiny") continue;
        for (const Vertex& v : s.primitives[it.primitive].vertices) {
            if (v.position == glm::vec3(0, 0, 0)) {
                EXPECT_NEAR(v.uv.x, 0.0f, 1e-6);
                EXPECT_NEAR(v.uv.y, 1.0f, 1e-6);
                found = true;
            }
            EXPECT_NEAR(v.normal.z, 1.0f, 1e-5);
        }
    }
    EXPECT_TRUE(found);

    // OBJ has no camera or light: loadScene added a camera, but no sun since
    // the "plain" material emits (Ke) and lights the scene itself.
    auto world = worldMatrices(s);
    EXPECT_EQ(placedCameras(s, world).size(), 1u);
    EXPECT_EQ(placedLights(s, world).size(), 0u);
}

TEST(Assimp, AsciiPly) {
    TempDir dir;
    writeText(dir.file("quad.ply"), R"(ply
format ascii 1.0
element vertex 4
property float x
property float y
property float z
element face 2
property list uchar int vertex_indices
end_header
0 0 0
2 0 0
2 2 0
0 2 0
3 0 1 2
3 0 2 3
)");
    Scene s = loadScene(dir.file("quad.ply"));
    EXPECT_EQ(triangleCount(s), 2u);
    Bounds b = worldBounds(s, drawItems(s, worldMatrices(s)));
    EXPECT_EQ(b.max, glm::vec3(2, 2, 0));
    EXPECT_EQ(placedLights(s, worldMatrices(s)).size(), 1u);  // the default sun
    for (const Primitive& p : s.primitives) {
        ASSERT_LT(p.material, s.materials.size());
        for (const Vertex& v : p.vertices) EXPECT_NEAR(v.normal.z, 1.0f, 1e-5);  // generated
    }
}

TEST(Assimp, Errors) {
    TempDir dir;
    writeText(dir.file("broken.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nend_header\nnonsense\n");
    try {
        loadScene(dir.file("broken.ply"));
        FAIL() << "expected LoadError";
    } catch (const LoadError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(dir.file("broken.ply"), 0), 0u) << e.what();
    }
    writeText(dir.file("empty.obj"), "# nothing\nv 0 0 0\n");
    try {
        loadScene(dir.file("empty.obj"));
        FAIL() << "expected LoadError";
    } catch (const LoadError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(dir.file("empty.obj"), 0), 0u) << e.what();
    }
}

TEST(Assimp, SharedCornellObj) {
    std::filesystem::path file = std::filesystem::path(DVSGI_SHARED_DIR) / "scenes/cornell-box/cornell_box.obj";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
    Scene s = loadScene(file.string());
    EXPECT_EQ(triangleCount(s), 36u);
    EXPECT_NE(findMaterial(s, "red"), nullptr);
    // Units are kept as written: the OBJ is in centimetres.
    Bounds b = worldBounds(s, drawItems(s, worldMatrices(s)));
    EXPECT_NEAR(b.max.y, 54.88f, 0.01f);
}

TEST(Assimp, SharedSponzaObj) {
    std::filesystem::path file = std::filesystem::path(DVSGI_SHARED_DIR) / "scenes/crytek-sponza/sponza.obj";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
    Scene s = loadScene(file.string());
    EXPECT_GT(triangleCount(s), 0u);
    EXPECT_GT(s.textures.size(), 0u);
    for (const std::string& w : s.warnings) ADD_FAILURE() << w;  // every texture is present
    RecordProperty("triangles", static_cast<int>(triangleCount(s)));
}
