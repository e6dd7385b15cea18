// glTF importer: containers, geometry, materials, textures, lights, cameras,
// animations.
#include <cmath>
#include <fstream>

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

#include "scene/load.h"
#include "test_support.h"

using namespace dvsgi::scene;
using namespace scene_test;

namespace {

const std::vector<glm::vec3> kQuad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const std::vector<uint32_t> kQuadIdx = {0, 1, 2, 0, 2, 3};

// A one-quad scene: node 0 holds mesh 0.
GltfBuilder quadScene() {
    GltfBuilder b;
    int mesh = b.addTriangleMesh(kQuad, kQuadIdx);
    b.addNode({{"mesh", mesh}, {"name", "quad"}});
    b.doc["scenes"] = json::array({{{"nodes", {0}}}});
    b.doc["scene"] = 0;
    return b;
}

void expectQuad(const Scene& s) {
    ASSERT_EQ(s.primitives.size(), 1u);
    const Primitive& p = s.primitives[0];
    ASSERT_EQ(p.vertices.size(), 4u);
    EXPECT_EQ(p.indices, kQuadIdx);
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(p.vertices[i].position, kQuad[i]);
        EXPECT_EQ(p.vertices[i].normal, glm::vec3(0, 0, 1));
    }
    ASSERT_EQ(s.nodes.size(), 1u);
    EXPECT_EQ(s.nodes[0].name, "quad");
    EXPECT_EQ(s.roots, std::vector<int>{0});
    ASSERT_LT(p.material, s.materials.size());  // the glTF default material was added
}

}  // namespace

TEST(Gltf, ExternalBin) {
    TempDir dir;
    GltfBuilder b = quadScene();
    std::string path = b.writeGltfExternal(dir, "quad.gltf", "quad data.bin");  // space: URI is not encoded
    Scene s = loadGltf(path);
    expectQuad(s);
    EXPECT_EQ(s.source, path);
    EXPECT_TRUE(s.warnings.empty());
}

TEST(Gltf, PercentEncodedUri) {
    TempDir dir;
    GltfBuilder b = quadScene();
    std::string path = b.writeGltfExternal(dir, "quad.gltf", "quad data.bin");
    json doc = json::parse(std::ifstream(path));
    doc["buffers"][0]["uri"] = "quad%20data.bin";
    writeText(path, doc.dump());
    expectQuad(loadGltf(path));
}

TEST(Gltf, DataUri) {
    TempDir dir;
    GltfBuilder b = quadScene();
    expectQuad(loadGltf(b.writeGltfDataUri(dir, "quad.gltf")));
}

TEST(Gltf, Glb) {
    TempDir dir;
    GltfBuilder b = quadScene();
    expectQuad(loadGltf(b.writeGlb(dir, "quad.glb")));
}

TEST(Gltf, LoadSceneAddsDefaultsAndMaterial) {
    TempDir dir;
    GltfBuilder b = quadScene();
    Scene s = loadScene(b.writeGlb(dir, "quad.glb"));
    auto world = worldMatrices(s);
    ASSERT_EQ(placedCameras(s, world).size(), 1u);
    auto lights = placedLights(s, world);
    ASSERT_EQ(lights.size(), 1u);
    EXPECT_EQ(lights[0].light.name, "default_sun");
    EXPECT_EQ(lights[0].light.type, LightType::Directional);
    EXPECT_FLOAT_EQ(lights[0].light.intensity, 3.0f);
    EXPECT_FALSE(s.materials.empty());
}

class GltfIndexType : public ::testing::TestWithParam<int> {};

TEST_P(GltfIndexType, ReadsIndices) {
    TempDir dir;
    GltfBuilder b;
    std::vector<glm::vec3> pos(300, glm::vec3(0));
    for (size_t i = 0; i < pos.size(); ++i) pos[i] = glm::vec3(float(i), float(i % 7), 0);
    std::vector<uint32_t> idx = {0, 1, 2, 250, 251, 252, 2, 1, 0};
    b.addMesh(b.addVec3(pos), -1, b.addIndices(idx, GetParam()));
    b.addNode({{"mesh", 0}});
    Scene s = loadGltf(b.writeGltfExternal(dir, "i.gltf", "i.bin"));
    ASSERT_EQ(s.primitives.size(), 1u);
    // No NORMAL: the mesh is unwelded for flat normals, positions follow the indices.
    const Primitive& p = s.primitives[0];
    ASSERT_EQ(p.indices.size(), idx.size());
    for (size_t i = 0; i < idx.size(); ++i) EXPECT_EQ(p.vertices[p.indices[i]].position, pos[idx[i]]);
}

INSTANTIATE_TEST_SUITE_P(Types, GltfIndexType, ::testing::Values(kUByte, kUShort, kUInt));

TEST(Gltf, NonIndexedFlatNormals) {
    TempDir dir;
    GltfBuilder b;
    b.addMesh(b.addVec3({{0, 0, 0}, {0, 0, 1}, {1, 0, 0}}), -1, -1);
    b.addNode({{"mesh", 0}});
    Scene s = loadGltf(b.writeGltfExternal(dir, "f.gltf", "f.bin"));
    const Primitive& p = s.primitives[0];
    ASSERT_EQ(p.indices, (std::vector<uint32_t>{0, 1, 2}));
    for (const Vertex& v : p.vertices) {
        EXPECT_NEAR(v.normal.x, 0, 1e-6);
        EXPECT_NEAR(v.normal.y, 1, 1e-6);  // counter-clockwise seen from +Y
        EXPECT_NEAR(v.normal.z, 0, 1e-6);
    }
}

TEST(Gltf, InterleavedStrideNormalizedUvAndTangents) {
    TempDir dir;
    GltfBuilder b;
    // Per vertex: float3 position, u16x2 normalized uv, 4 bytes padding -> stride 20.
    struct V { float p[3]; uint16_t uv[2]; uint32_t pad; };
    std::vector<V> verts = {{{0, 0, 0}, {0, 0}, 0}, {{1, 0, 0}, {65535, 0}, 0}, {{0, 1, 0}, {32768, 65535}, 0}};
    int view = b.addView(verts.data(), verts.size() * sizeof(V), sizeof(V));
    int pos = b.addAccessor(view, kFloat, 3, "VEC3");
    int uv = b.addAccessor(view, kUShort, 3, "VEC2", 12, true);
    int tan = b.addVec4({{1, 0, 0, -1}, {1, 0, 0, -1}, {1, 0, 0, -1}});
    b.addMesh(pos, -1, -1);
    b.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = uv;
    b.doc["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] = tan;
    b.addNode({{"mesh", 0}});
    Scene s = loadGltf(b.writeGltfExternal(dir, "s.gltf", "s.bin"));
    const Primitive& p = s.primitives[0];
    EXPECT_TRUE(p.hasTangents);
    EXPECT_EQ(p.vertices[1].position, glm::vec3(1, 0, 0));
    EXPECT_EQ(p.vertices[2].position, glm::vec3(0, 1, 0));
    EXPECT_FLOAT_EQ(p.vertices[1].uv.x, 1.0f);
    EXPECT_NEAR(p.vertices[2].uv.x, 32768.0f / 65535.0f, 1e-7);
    EXPECT_FLOAT_EQ(p.vertices[2].uv.y, 1.0f);
    EXPECT_EQ(p.vertices[0].tangent, glm::vec4(1, 0, 0, -1));
}

TEST(Gltf, MaterialAllFields) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["materials"] = json::array({{
        {"name", "everything"},
        {"pbrMetallicRoughness",
         {{"baseColorFactor", {0.5, 0.25, 0.125, 0.75}}, {"metallicFactor", 0.3}, {"roughnessFactor", 0.6}}},
        {"emissiveFactor", {1.0, 0.5, 0.25}},
        {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 17.0}}}}},
        {"alphaMode", "MASK"},
        {"alphaCutoff", 0.3},
        {"doubleSided", true},
    }});
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    Scene s = loadGltf(b.writeGltfExternal(dir, "m.gltf", "m.bin"));
    ASSERT_EQ(s.materials.size(), 1u);
    const Material& m = s.materials[0];
    EXPECT_EQ(m.name, "everything");
    EXPECT_EQ(m.baseColorFactor, glm::vec4(0.5f, 0.25f, 0.125f, 0.75f));
    EXPECT_FLOAT_EQ(m.metallicFactor, 0.3f);
    EXPECT_FLOAT_EQ(m.roughnessFactor, 0.6f);
    EXPECT_EQ(m.emissiveFactor, glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_FLOAT_EQ(m.emissiveStrength, 17.0f);
    EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(m.alphaCutoff, 0.3f);
    EXPECT_TRUE(m.doubleSided);
    EXPECT_EQ(m.baseColorTexture, -1);
    EXPECT_EQ(s.primitives[0].material, 0u);
}

TEST(Gltf, MaterialDefaults) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["materials"] = json::array({json::object()});
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    Scene s = loadGltf(b.writeGltfExternal(dir, "m.gltf", "m.bin"));
    const Material& m = s.materials[0];
    EXPECT_EQ(m.baseColorFactor, glm::vec4(1));
    EXPECT_FLOAT_EQ(m.metallicFactor, 1.0f);
    EXPECT_FLOAT_EQ(m.roughnessFactor, 1.0f);
    EXPECT_EQ(m.emissiveFactor, glm::vec3(0));
    EXPECT_FLOAT_EQ(m.emissiveStrength, 1.0f);
    EXPECT_EQ(m.alphaMode, AlphaMode::Opaque);
    EXPECT_FLOAT_EQ(m.alphaCutoff, 0.5f);
    EXPECT_FALSE(m.doubleSided);
}

namespace {

// 2x2 texels: red, green / blue, half-transparent white.
const std::vector<uint8_t> kTexels = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128};

void addTexturedMaterial(GltfBuilder& b, const json& image) {
    b.doc["images"] = json::array({image});
    b.doc["textures"] = json::array({{{"source", 0}}});
    b.doc["materials"] = json::array({{
        {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicRoughnessTexture", {{"index", 0}}}}},
        {"normalTexture", {{"index", 0}, {"scale", 0.5}}},
        {"emissiveTexture", {{"index", 0}}},
    }});
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
}

void expectTexturedMaterial(const Scene& s) {
    EXPECT_TRUE(s.warnings.empty()) << (s.warnings.empty() ? "" : s.warnings[0]);
    const Material& m = s.materials[0];
    ASSERT_GE(m.baseColorTexture, 0);
    ASSERT_GE(m.metallicRoughnessTexture, 0);
    // One image used as colour and as data: two textures with their own flag,
    // shared by the users of the same colour space.
    EXPECT_NE(m.baseColorTexture, m.metallicRoughnessTexture);
    EXPECT_EQ(m.emissiveTexture, m.baseColorTexture);
    EXPECT_EQ(m.normalTexture, m.metallicRoughnessTexture);
    EXPECT_FLOAT_EQ(m.normalScale, 0.5f);
    ASSERT_EQ(s.textures.size(), 2u);
    const Texture& c = s.textures[static_cast<size_t>(m.baseColorTexture)];
    const Texture& d = s.textures[static_cast<size_t>(m.metallicRoughnessTexture)];
    EXPECT_TRUE(c.srgb);
    EXPECT_FALSE(d.srgb);
    EXPECT_EQ(c.width, 2u);
    EXPECT_EQ(c.height, 2u);
    EXPECT_EQ(c.rgba8, kTexels);
    EXPECT_EQ(d.rgba8, kTexels);
}

}  // namespace

TEST(Gltf, TextureFromFile) {
    TempDir dir;
    writePng(dir.file("tex.png"), 2, 2, kTexels);
    GltfBuilder b = quadScene();
    addTexturedMaterial(b, {{"uri", "tex.png"}});
    Scene s = loadGltf(b.writeGltfExternal(dir, "t.gltf", "t.bin"));
    expectTexturedMaterial(s);
    EXPECT_EQ(s.textures[0].name, "tex.png");
}

TEST(Gltf, TextureFromDataUri) {
    TempDir dir;
    GltfBuilder b = quadScene();
    addTexturedMaterial(b, {{"uri", "data:image/png;base64," + base64(pngBytes(2, 2, kTexels))}});
    expectTexturedMaterial(loadGltf(b.writeGltfDataUri(dir, "t.gltf")));
}

TEST(Gltf, TextureFromGlbBufferView) {
    TempDir dir;
    GltfBuilder b = quadScene();
    auto png = pngBytes(2, 2, kTexels);
    int view = b.addView(png.data(), png.size());
    addTexturedMaterial(b, {{"bufferView", view}, {"mimeType", "image/png"}});
    expectTexturedMaterial(loadGltf(b.writeGlb(dir, "t.glb")));
}

TEST(Gltf, MissingTextureWarnsAndFallsBack) {
    TempDir dir;
    GltfBuilder b = quadScene();
    addTexturedMaterial(b, {{"uri", "nowhere.png"}});
    Scene s = loadGltf(b.writeGltfExternal(dir, "t.gltf", "t.bin"));
    const Material& m = s.materials[0];
    EXPECT_EQ(m.baseColorTexture, -1);
    EXPECT_EQ(m.metallicRoughnessTexture, -1);
    EXPECT_EQ(m.emissiveTexture, -1);
    EXPECT_EQ(m.normalTexture, -1);
    EXPECT_TRUE(s.textures.empty());
    ASSERT_EQ(s.warnings.size(), 1u);  // one image: reported once
    EXPECT_NE(s.warnings[0].find("nowhere.png"), std::string::npos) << s.warnings[0];
}

TEST(Gltf, UndecodableTextureWarns) {
    TempDir dir;
    writeText(dir.file("bad.png"), "this is not a png");
    GltfBuilder b = quadScene();
    addTexturedMaterial(b, {{"uri", "bad.png"}});
    Scene s = loadGltf(b.writeGltfExternal(dir, "t.gltf", "t.bin"));
    EXPECT_EQ(s.materials[0].baseColorTexture, -1);
    ASSERT_FALSE(s.warnings.empty());
    EXPECT_NE(s.warnings[0].find("bad.png"), std::string::npos);
}

TEST(Gltf, LightsWithDefaults) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["extensions"]["KHR_lights_punctual"]["lights"] = json::array({
        {{"type", "directional"}, {"name", "sun"}, {"intensity", 2.5}},
        {{"type", "point"}, {"color", {1.0, 0.5, 0.25}}, {"range", 3.0}},
        {{"type", "spot"}},
        {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.1}, {"outerConeAngle", 0.4}}}},
    });
    const float h = std::sqrt(0.5f);
    b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"rotation", {-h, 0, 0, h}}});
    b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}, {"translation", {1, 2, 3}}});
    b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
    b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 3}}}}}});
    b.doc["scenes"][0]["nodes"] = {0, 1, 2, 3, 4};
    Scene s = loadGltf(b.writeGltfExternal(dir, "l.gltf", "l.bin"));
    ASSERT_EQ(s.lights.size(), 4u);
    EXPECT_EQ(s.lights[0].type, LightType::Directional);
    EXPECT_EQ(s.lights[0].name, "sun");
    EXPECT_FLOAT_EQ(s.lights[0].intensity, 2.5f);
    EXPECT_EQ(s.lights[0].color, glm::vec3(1));
    EXPECT_EQ(s.lights[1].type, LightType::Point);
    EXPECT_FLOAT_EQ(s.lights[1].intensity, 1.0f);
    EXPECT_EQ(s.lights[1].color, glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_EQ(s.lights[2].type, LightType::Spot);
    EXPECT_FLOAT_EQ(s.lights[2].innerConeAngle, 0.0f);
    EXPECT_FLOAT_EQ(s.lights[2].outerConeAngle, 0.78539816f);
    EXPECT_FLOAT_EQ(s.lights[3].innerConeAngle, 0.1f);
    EXPECT_FLOAT_EQ(s.lights[3].outerConeAngle, 0.4f);

    auto placed = placedLights(s, worldMatrices(s));
    ASSERT_EQ(placed.size(), 4u);
    // -90 degrees about X turns -Z into -Y: the sun shines straight down.
    EXPECT_NEAR(placed[0].direction.x, 0, 1e-6);
    EXPECT_NEAR(placed[0].direction.y, -1, 1e-6);
    EXPECT_NEAR(placed[0].direction.z, 0, 1e-6);
    EXPECT_EQ(placed[1].position, glm::vec3(1, 2, 3));
    EXPECT_EQ(placed[2].direction, glm::vec3(0, 0, -1));
}

TEST(Gltf, Cameras) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["cameras"] = json::array({
        {{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}},
        {{"type", "perspective"}, {"name", "persp"},
         {"perspective", {{"yfov", 0.5}, {"znear", 0.05}, {"zfar", 50}, {"aspectRatio", 1.5}}}},
        {{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}}}},
    });
    b.addNode({{"camera", 2}, {"translation", {0, 0, 5}}});
    b.addNode({{"camera", 0}});
    b.addNode({{"camera", 1}, {"translation", {1, 0, 0}}});
    b.doc["scenes"][0]["nodes"] = {0, 3, 2, 1};
    Scene s = loadGltf(b.writeGltfExternal(dir, "c.gltf", "c.bin"));
    ASSERT_EQ(s.cameras.size(), 2u);
    EXPECT_EQ(s.warnings.size(), 1u);  // the orthographic camera was skipped
    EXPECT_EQ(s.nodes[2].camera, -1);
    auto cams = placedCameras(s, worldMatrices(s));
    ASSERT_EQ(cams.size(), 2u);
    // Node order, not scene order: node 1 (yfov 0.7) comes first.
    EXPECT_FLOAT_EQ(cams[0].camera.yfov, 0.7f);
    EXPECT_FLOAT_EQ(cams[0].camera.aspectRatio, 0.0f);
    EXPECT_FLOAT_EQ(cams[0].world[3].z, 5.0f);
    EXPECT_EQ(cams[1].camera.name, "persp");
    EXPECT_FLOAT_EQ(cams[1].camera.yfov, 0.5f);
    EXPECT_FLOAT_EQ(cams[1].camera.znear, 0.05f);
    EXPECT_FLOAT_EQ(cams[1].camera.zfar, 50.0f);
    EXPECT_FLOAT_EQ(cams[1].camera.aspectRatio, 1.5f);
}

TEST(Gltf, HierarchyMatrixAndSceneSelection) {
    TempDir dir;
    GltfBuilder b = quadScene();
    // Node 1: matrix = translate(1,2,3) * rotate 90 deg about Z * scale 2.
    b.addNode({{"matrix", {0, 2, 0, 0, -2, 0, 0, 0, 0, 0, 2, 0, 1, 2, 3, 1}}, {"children", {2}}});
    b.addNode({{"translation", {1, 0, 0}}, {"mesh", 0}});
    b.doc["scenes"] = json::array({{{"nodes", {0}}}, {{"nodes", {1}}}});
    b.doc["scene"] = 1;
    Scene s = loadGltf(b.writeGltfExternal(dir, "h.gltf", "h.bin"));
    EXPECT_EQ(s.roots, std::vector<int>{1});
    EXPECT_EQ(s.nodes[2].parent, 1);
    EXPECT_NEAR(s.nodes[1].scale.x, 2, 1e-6);
    auto world = worldMatrices(s);
    // Child origin: parent applied to (1,0,0) -> rotate to (0,1,0), scale 2, + (1,2,3).
    glm::vec3 o = glm::vec3(world[2][3]);
    EXPECT_NEAR(o.x, 1, 1e-5);
    EXPECT_NEAR(o.y, 4, 1e-5);
    EXPECT_NEAR(o.z, 3, 1e-5);
    auto items = drawItems(s, world);
    ASSERT_EQ(items.size(), 1u);  // node 0 is not in scene 1
    EXPECT_EQ(items[0].node, 2);

    // Without scenes, every parentless node is a root.
    b.doc.erase("scenes");
    b.doc.erase("scene");
    Scene all = loadGltf(b.writeGltfExternal(dir, "h2.gltf", "h2.bin"));
    EXPECT_EQ(all.roots, (std::vector<int>{0, 1}));
}

TEST(Gltf, Animations) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.addNode({{"name", "spinner"}});
    b.doc["scenes"][0]["nodes"] = {0, 1};
    int times = b.addScalars({0.0f, 1.0f, 2.0f});
    int trans = b.addVec3({{0, 0, 0}, {2, 0, 0}, {2, 4, 0}});
    const float h = std::sqrt(0.5f);
    int rot = b.addVec4({{0, 0, 0, 1}, {0, h, 0, h}, {0, 1, 0, 0}});
    int weights = b.addScalars({0.0f, 1.0f, 0.5f});
    b.doc["animations"] = json::array({{
        {"name", "anim"},
        {"samplers", {{{"input", times}, {"output", trans}},
                      {{"input", times}, {"output", rot}, {"interpolation", "LINEAR"}},
                      {{"input", times}, {"output", trans}, {"interpolation", "STEP"}},
                      {{"input", times}, {"output", weights}}}},
        {"channels", {{{"sampler", 0}, {"target", {{"node", 1}, {"path", "translation"}}}},
                      {{"sampler", 1}, {"target", {{"node", 1}, {"path", "rotation"}}}},
                      {{"sampler", 2}, {"target", {{"node", 0}, {"path", "scale"}}}},
                      {{"sampler", 3}, {"target", {{"node", 0}, {"path", "weights"}}}}}},
    }});
    Scene s = loadGltf(b.writeGltfExternal(dir, "a.gltf", "a.bin"));
    ASSERT_EQ(s.animations.size(), 1u);
    EXPECT_EQ(s.animations[0].channels.size(), 3u);  // weights skipped
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("weights"), std::string::npos);
    EXPECT_TRUE(s.nodes[1].dynamic);
    EXPECT_TRUE(s.nodes[0].dynamic);

    applyAnimations(s, 0.5f);
    EXPECT_NEAR(s.nodes[1].translation.x, 1.0f, 1e-6);
    // Slerp halfway between identity and 90 deg about Y: 45 deg about Y.
    glm::quat q = s.nodes[1].rotation;
    EXPECT_NEAR(std::abs(q.w), std::cos(glm::radians(22.5f)), 1e-5);
    EXPECT_NEAR(std::abs(q.y), std::sin(glm::radians(22.5f)), 1e-5);
    EXPECT_EQ(s.nodes[0].scale, glm::vec3(0, 0, 0));  // step holds key 0
    applyAnimations(s, 1.5f);
    EXPECT_NEAR(s.nodes[1].translation.y, 2.0f, 1e-6);
    EXPECT_EQ(s.nodes[0].scale, glm::vec3(2, 0, 0));
    applyAnimations(s, 10.0f);  // clamped to the last key
    EXPECT_EQ(s.nodes[1].translation, glm::vec3(2, 4, 0));
    EXPECT_NEAR(std::abs(s.nodes[1].rotation.y), 1.0f, 1e-6);
}
