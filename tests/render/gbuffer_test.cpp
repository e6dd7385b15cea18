// The G-buffer draws opaque materials with a shader that cannot discard (so
// the depth test runs before shading) and cut-out materials after them with
// one that can: the opaque variant's SPIR-V holds no instruction that ends an
// invocation, and a top-down view of three quads (a cut-out quad with its left
// half kept, an opaque floor under it, a small opaque quad above it) shows
// each surface only where it exists and is nearest. Materials with no
// emissive or metallic-roughness texture are drawn with variants that sample
// the base colour alone.
#include <cmath>
#include <cstdio>

#include "gpu_fixture.h"
#include "render/gbuffer.h"
#include "render/renderer.h"

namespace dvsgi::test {
namespace {

// Instructions of a SPIR-V module that end or demote a fragment invocation.
int discardInstructions(gpu::Spirv code) {
    constexpr uint32_t kOpKill = 252, kOpTerminateInvocation = 4416, kOpDemoteToHelperInvocation = 5380;
    int n = 0;
    for (size_t i = 5; i < code.size();) {  // after the five-word header
        const uint32_t words = code[i] >> 16, op = code[i] & 0xFFFFu;
        n += op == kOpKill || op == kOpTerminateInvocation || op == kOpDemoteToHelperInvocation;
        if (words == 0) break;  // malformed: stop rather than loop
        i += words;
    }
    return n;
}

// Instructions of a SPIR-V module that sample an image (implicit level of detail).
int sampleInstructions(gpu::Spirv code) {
    constexpr uint32_t kOpImageSampleImplicitLod = 87;
    int n = 0;
    for (size_t i = 5; i < code.size();) {
        const uint32_t words = code[i] >> 16, op = code[i] & 0xFFFFu;
        n += op == kOpImageSampleImplicitLod;
        if (words == 0) break;
        i += words;
    }
    return n;
}

TEST(GBufferShaders, OnlyTheAlphaTestedVariantCanDiscard) {
    for (bool baseColorOnly : {false, true}) {
        EXPECT_EQ(discardInstructions(render::gbufferFragmentShader(false, baseColorOnly)), 0);
        EXPECT_GT(discardInstructions(render::gbufferFragmentShader(true, baseColorOnly)), 0);
    }
}

// Materials without an emissive or metallic-roughness texture are drawn with
// variants that sample the base colour alone: llvmpipe takes every sample in
// a shader, whichever way its branch goes.
TEST(GBufferShaders, BaseColorOnlyVariantsSampleOneTexture) {
    for (bool alphaTested : {false, true}) {
        EXPECT_EQ(sampleInstructions(render::gbufferFragmentShader(alphaTested, false)), 3);
        EXPECT_EQ(sampleInstructions(render::gbufferFragmentShader(alphaTested, true)), 1);
    }
}

// One frame holding both kinds of material, opaque and cut-out (so all four
// variants draw, in the scene's order): each quad shows its own base colour,
// metallic, roughness and emission texels, and the base-colour-only quad none
// of the others'.
TEST_F(GpuTest, GBufferGivesEachMaterialItsOwnTextures) {
    scene::Scene s;
    const int base = addUniformTexture(s, 200, 100, 50), mr = addUniformTexture(s, 0, 128, 128),
              em = addUniformTexture(s, 64, 128, 255);
    const int plain = addMaterial(s, glm::vec3(1.0f)), rough = addMaterial(s, glm::vec3(1.0f)),
              glow = addMaterial(s, glm::vec3(1.0f), glm::vec3(2.0f)),
              cutGlow = addMaterial(s, glm::vec3(1.0f), glm::vec3(2.0f));
    for (int m : {plain, rough, glow, cutGlow}) s.materials[size_t(m)].baseColorTexture = base;
    s.materials[size_t(rough)].metallicRoughnessTexture = mr;
    s.materials[size_t(rough)].metallicFactor = 1.0f;
    s.materials[size_t(rough)].roughnessFactor = 0.8f;
    s.materials[size_t(glow)].emissiveTexture = em;
    s.materials[size_t(cutGlow)].emissiveTexture = em;
    s.materials[size_t(cutGlow)].alphaMode = scene::AlphaMode::Mask;  // opaque texels: covered everywhere
    // Seen from 2 m above with a 60 degree field of view, world x (and z) maps
    // to pixel (x / (2 tan 30) + 1) * 16 - 0.5 of 32: x = -0.7, 0, 0.7 to
    // columns 6, 16, 25, z = 0 and 0.7 to rows 16 and 25 (quads 8 pixels wide).
    addQuad(s, rough, glm::vec3(-0.7f, 0.0f, 0.0f), 0.3f);
    addQuad(s, plain, glm::vec3(0.0f), 0.3f);
    addQuad(s, glow, glm::vec3(0.7f, 0.0f, 0.0f), 0.3f);
    addQuad(s, cutGlow, glm::vec3(0.0f, 0.0f, 0.7f), 0.3f);
    addTopDownCamera(s, 2.0f, glm::radians(60.0f));
    render::RenderSettings rs;
    rs.width = rs.height = 32;
    rs.voxels = 0;  // no voxels and no lights: the output is the emission
    render::Renderer r(context(), s, rs);
    r.renderFrame();
    const render::Renderer::SurfaceImages g = r.readSurface();
    const image::ImageRGBA32F out = r.readOutput();

    const glm::vec3 albedo(200.0f / 255.0f, 100.0f / 255.0f, 50.0f / 255.0f);
    const glm::vec3 glowing = 2.0f * glm::vec3(64.0f, 128.0f, 255.0f) / 255.0f;
    struct Expected {
        uint32_t column, row;
        float metallic, roughness;
        glm::vec3 emission;
    };
    const Expected quads[] = {{6, 16, 128.0f / 255.0f, 0.8f * 128.0f / 255.0f, glm::vec3(0.0f)},
                              {16, 16, 0.0f, 1.0f, glm::vec3(0.0f)},
                              {25, 16, 0.0f, 1.0f, glowing},
                              {16, 25, 0.0f, 1.0f, glowing}};
    // The G-buffer is RGBA16F (11 significant bits: 5e-4 relative).
    for (const Expected& q : quads)
        for (uint32_t x = q.column - 1; x <= q.column + 1; ++x)
            for (uint32_t y = q.row - 1; y <= q.row + 1; ++y) {
                const float* a = g.albedo.at(x, y);
                for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], albedo[c], 1e-3f) << x << "," << y;
                EXPECT_NEAR(a[3], q.metallic, 1e-3f) << x << "," << y;
                EXPECT_NEAR(g.normal.at(x, y)[3], q.roughness, 1e-3f) << x << "," << y;
                for (int c = 0; c < 3; ++c) EXPECT_NEAR(out.at(x, y)[c], q.emission[c], 2e-3f) << x << "," << y;
            }
}

TEST_F(GpuTest, GBufferCutOutsShowOnlyWhereTheyExistAndBehindOpaqueSurfaces) {
    scene::Scene s;
    scene::Texture t;  // 8x1: opaque for u < 0.5, cut out for u >= 0.5
    t.name = "half";
    t.width = 8;
    t.height = 1;
    for (uint32_t x = 0; x < 8; ++x) t.rgba8.insert(t.rgba8.end(), {255, 255, 255, uint8_t(x < 4 ? 255 : 0)});
    s.textures.push_back(t);
    const glm::vec3 red(0.8f, 0.1f, 0.1f), blue(0.1f, 0.1f, 0.8f), green(0.1f, 0.8f, 0.1f);
    const int cut = addMaterial(s, red);
    s.materials[size_t(cut)].baseColorTexture = 0;
    s.materials[size_t(cut)].alphaMode = scene::AlphaMode::Mask;
    addQuad(s, cut, glm::vec3(0.0f, 0.5f, 0.0f), 1.0f);  // u = x / 2 + 0.5: kept where x < 0
    addQuad(s, addMaterial(s, blue), glm::vec3(0.0f), 1.5f);
    addQuad(s, addMaterial(s, green), glm::vec3(0.0f, 1.0f, 0.0f), 0.25f);
    addTopDownCamera(s, 2.0f, glm::radians(60.0f));  // image right = +x, up = -z
    render::RenderSettings rs;
    rs.width = rs.height = 32;
    rs.voxels = 0;  // the G-buffer alone
    render::Renderer r(context(), s, rs);
    r.renderFrame();
    const image::ImageRGBA32F albedo = r.readSurface().albedo;

    // World x of a column's centre on a plane `d` below the camera.
    const float tanHalf = std::tan(glm::radians(30.0f));
    auto worldX = [&](uint32_t col, float d) { return ((float(col) + 0.5f) / 16.0f - 1.0f) * d * tanHalf; };
    auto near = [](const float* p, glm::vec3 c) {
        return std::abs(p[0] - c.r) < 0.02f && std::abs(p[1] - c.g) < 0.02f && std::abs(p[2] - c.b) < 0.02f;
    };
    int checked = 0, wrong = 0;
    for (uint32_t y = 0; y < 32; ++y)
        for (uint32_t x = 0; x < 32; ++x) {
            const float zAtGreen = ((float(y) + 0.5f) / 16.0f - 1.0f) * tanHalf;  // d = 1
            const float xAtGreen = worldX(x, 1.0f), xAtCut = worldX(x, 1.5f);
            glm::vec3 expected;
            if (std::abs(xAtGreen) < 0.23f && std::abs(zAtGreen) < 0.23f)
                expected = green;  // opaque, above the cut-out
            else if (std::abs(xAtGreen) < 0.27f && std::abs(zAtGreen) < 0.27f)
                continue;  // the green quad's edge
            else if (xAtCut < -0.1f)
                expected = red;  // the kept half
            else if (xAtCut > 0.1f)
                expected = blue;  // the floor through the cut-out half
            else
                continue;  // the texture blends across the cut
            ++checked;
            if (!near(albedo.at(x, y), expected)) ++wrong;
        }
    std::printf("pixels checked %d, wrong %d\n", checked, wrong);
    EXPECT_GT(checked, 700);
    EXPECT_EQ(wrong, 0);
}

// --texture-anisotropy: stripes running away from a low camera, 4 texels a
// period across the view. Filtering by the footprint's long side (isotropic)
// picks a mip level where they are grey; anisotropic filtering keeps them.
TEST_F(GpuTest, TextureAnisotropyKeepsStripesSeenAtAGrazingAngle) {
    if (!context().features.samplerAnisotropy) GTEST_SKIP() << "the device has no anisotropic filtering";
    scene::Scene s;
    scene::Texture t;
    t.name = "stripes";
    t.width = t.height = 64;
    for (uint32_t y = 0; y < 64; ++y)
        for (uint32_t x = 0; x < 64; ++x) {
            const uint8_t v = (x / 2) % 2 ? 255 : 0;
            t.rgba8.insert(t.rgba8.end(), {v, v, v, 255});
        }
    t.srgb = false;
    s.textures.push_back(t);
    const int striped = addMaterial(s, glm::vec3(1.0f));
    s.materials[size_t(striped)].baseColorTexture = 0;
    addQuad(s, striped, glm::vec3(0.0f), 4.0f);  // u along x: stripes run along z, away from the camera
    scene::Camera c;
    c.yfov = glm::radians(40.0f);
    c.znear = 0.01f;
    c.zfar = 100.0f;
    s.cameras.push_back(c);
    scene::Node n;
    n.camera = 0;
    n.translation = glm::vec3(0.0f, 0.25f, 3.9f);
    n.rotation = glm::angleAxis(-0.12f, glm::vec3(1, 0, 0));  // looking along -z, a little down
    s.nodes.push_back(n);
    s.roots.push_back(int(s.nodes.size() - 1));
    render::RenderSettings rs;
    rs.width = rs.height = 64;
    rs.voxels = 0;  // the G-buffer alone
    double contrast[2] = {};
    for (int i = 0; i < 2; ++i) {
        rs.textureAnisotropy = i == 0 ? 1u : 8u;
        render::Renderer r(context(), s, rs);
        r.renderFrame();
        const image::ImageRGBA32F albedo = r.readSurface().albedo;
        // Mean absolute difference of neighbouring pixels along the far rows.
        double sum = 0.0;
        int n = 0;
        for (uint32_t y = 26; y < 34; ++y)
            for (uint32_t x = 8; x + 1 < 56; ++x, ++n) sum += std::abs(albedo.at(x + 1, y)[0] - albedo.at(x, y)[0]);
        contrast[i] = sum / n;
    }
    std::printf("stripe contrast on the far rows: anisotropy 1: %.4f, 8: %.4f\n", contrast[0], contrast[1]);
    // Measured 0.0588 and 0.1232 (2.1x) on lavapipe.
    EXPECT_GT(contrast[1], 1.7 * contrast[0]);
}

}  // namespace
}  // namespace dvsgi::test
