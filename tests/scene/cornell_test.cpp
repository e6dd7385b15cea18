// builtinCornellBox() must be the shared cornell-lights.gltf, compiled in.
#include <filesystem>

#include <gtest/gtest.h>

#include "scene/load.h"

using namespace dvsgi::scene;

namespace {

void expectNear(const glm::vec3& a, const glm::vec3& b, float eps = 1e-6f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

void expectNear(const glm::mat4& a, const glm::mat4& b, float eps = 1e-6f) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[c][r], b[c][r], eps) << "[" << c << "][" << r << "]";
}

}  // namespace

TEST(Cornell, BuiltinIsSelfConsistent) {
    Scene s = builtinCornellBox();
    EXPECT_EQ(s.source, "builtin:cornell");
    auto world = worldMatrices(s);
    auto items = drawItems(s, world);
    size_t tris = 0;
    for (const DrawItem& it : items) tris += s.primitives[it.primitive].indices.size() / 3;
    EXPECT_EQ(tris, 36u);
    Bounds b = worldBounds(s, items);
    EXPECT_NEAR(b.min.x, -0.2764f, 1e-4);
    EXPECT_NEAR(b.max.x, 0.2796f, 1e-4);
    EXPECT_NEAR(b.max.y, 0.5488f, 1e-4);
    EXPECT_NEAR(b.max.z, 0.5592f, 1e-4);
    auto lights = placedLights(s, world);
    ASSERT_EQ(lights.size(), 2u);
    // The sun enters through the open front (see cornell-gltf.md).
    expectNear(lights[1].direction, {-0.2346f, -0.4226f, 0.8754f}, 1e-4f);
    auto cams = placedCameras(s, world);
    ASSERT_EQ(cams.size(), 1u);
    expectNear(-glm::vec3(cams[0].world[2]), {0, 0, 1});  // looks along +Z
    EXPECT_EQ(s.warnings.size(), 0u);
}

TEST(Cornell, BuiltinMatchesSharedGltf) {
    std::filesystem::path file =
        std::filesystem::path(DVSGI_SHARED_DIR) / "scenes/cornell-box/cornell-lights.gltf";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
    Scene f = loadScene(file.string());
    Scene b = builtinCornellBox();
    EXPECT_TRUE(f.warnings.empty());

    ASSERT_EQ(b.nodes.size(), f.nodes.size());  // loadScene added no defaults
    EXPECT_EQ(b.roots, f.roots);
    for (size_t i = 0; i < b.nodes.size(); ++i) {
        EXPECT_EQ(b.nodes[i].name, f.nodes[i].name);
        EXPECT_EQ(b.nodes[i].mesh, f.nodes[i].mesh);
        EXPECT_EQ(b.nodes[i].camera, f.nodes[i].camera);
        EXPECT_EQ(b.nodes[i].light, f.nodes[i].light);
    }

    ASSERT_EQ(b.materials.size(), f.materials.size());
    for (size_t i = 0; i < b.materials.size(); ++i) {
        const Material &x = b.materials[i], &y = f.materials[i];
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.baseColorFactor, y.baseColorFactor);
        EXPECT_EQ(x.emissiveFactor, y.emissiveFactor);
        EXPECT_EQ(x.emissiveStrength, y.emissiveStrength);
        EXPECT_EQ(x.metallicFactor, y.metallicFactor);
        EXPECT_EQ(x.roughnessFactor, y.roughnessFactor);
        EXPECT_EQ(x.alphaMode, y.alphaMode);
        EXPECT_EQ(x.doubleSided, y.doubleSided);
    }

    // Geometry: bit-identical vertices and indices, mesh by mesh.
    ASSERT_EQ(b.meshes.size(), f.meshes.size());
    for (size_t m = 0; m < b.meshes.size(); ++m) {
        EXPECT_EQ(b.meshes[m].name, f.meshes[m].name);
        ASSERT_EQ(b.meshes[m].primitives.size(), 1u);
        ASSERT_EQ(f.meshes[m].primitives.size(), 1u);
        const Primitive& pb = b.primitives[b.meshes[m].primitives[0]];
        const Primitive& pf = f.primitives[f.meshes[m].primitives[0]];
        EXPECT_EQ(pb.material, pf.material);
        EXPECT_EQ(pb.indices, pf.indices);
        ASSERT_EQ(pb.vertices.size(), pf.vertices.size());
        for (size_t v = 0; v < pb.vertices.size(); ++v) {
            EXPECT_EQ(pb.vertices[v].position, pf.vertices[v].position) << "mesh " << m << " vertex " << v;
            EXPECT_EQ(pb.vertices[v].normal, pf.vertices[v].normal) << "mesh " << m << " vertex " << v;
        }
    }

    auto wb = worldMatrices(b), wf = worldMatrices(f);
    auto ib = drawItems(b, wb), iff = drawItems(f, wf);
    ASSERT_EQ(ib.size(), iff.size());
    size_t tb = 0, tf = 0;
    for (const DrawItem& it : ib) tb += b.primitives[it.primitive].indices.size() / 3;
    for (const DrawItem& it : iff) tf += f.primitives[it.primitive].indices.size() / 3;
    EXPECT_EQ(tb, tf);
    Bounds bb = worldBounds(b, ib), bf = worldBounds(f, iff);
    expectNear(bb.min, bf.min);
    expectNear(bb.max, bf.max);

    auto lb = placedLights(b, wb), lf = placedLights(f, wf);
    ASSERT_EQ(lb.size(), lf.size());
    for (size_t i = 0; i < lb.size(); ++i) {
        EXPECT_EQ(lb[i].light.name, lf[i].light.name);
        EXPECT_EQ(lb[i].light.type, lf[i].light.type);
        expectNear(lb[i].light.color, lf[i].light.color);
        EXPECT_NEAR(lb[i].light.intensity, lf[i].light.intensity, 1e-6);
        EXPECT_NEAR(lb[i].light.innerConeAngle, lf[i].light.innerConeAngle, 1e-6);
        EXPECT_NEAR(lb[i].light.outerConeAngle, lf[i].light.outerConeAngle, 1e-6);
        expectNear(lb[i].position, lf[i].position);
        expectNear(lb[i].direction, lf[i].direction);
    }

    auto cb = placedCameras(b, wb), cf = placedCameras(f, wf);
    ASSERT_EQ(cb.size(), 1u);
    ASSERT_EQ(cf.size(), 1u);
    EXPECT_EQ(cb[0].camera.name, cf[0].camera.name);
    EXPECT_NEAR(cb[0].camera.yfov, cf[0].camera.yfov, 1e-6);
    EXPECT_NEAR(cb[0].camera.aspectRatio, cf[0].camera.aspectRatio, 1e-6);
    EXPECT_NEAR(cb[0].camera.znear, cf[0].camera.znear, 1e-6);
    EXPECT_NEAR(cb[0].camera.zfar, cf[0].camera.zfar, 1e-6);
    expectNear(cb[0].world, cf[0].world);
}

TEST(Cornell, SharedEmissiveVariantGetsNoDefaultSun) {
    std::filesystem::path file =
        std::filesystem::path(DVSGI_SHARED_DIR) / "scenes/cornell-box/cornell-emissive.gltf";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
    Scene s = loadScene(file.string());
    EXPECT_TRUE(s.lights.empty());  // lit by its emissive quad only
    bool emissive = false;
    for (const Material& m : s.materials) emissive = emissive || (m.emissiveStrength == 17.0f);
    EXPECT_TRUE(emissive);
}
