// Raster passes draw only the chunks of 64 triangles whose bounds reach the
// view's clip volume (gpuscene::visibleDraws). Two checks: on the host, every
// triangle that an exact clip of its polygon against the six planes finds
// inside the volume lies in a kept run, for random perspective and
// orthographic views of two instances of a scattered mesh; on the GPU, a lit
// frame (G-buffer and a point light's six shadow faces) is bit-identical to
// the frame of the same scene whose chunks cannot be culled.
#include <array>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "gpu_fixture.h"
#include "gpuscene/draw_list.h"
#include "gpuscene/scene_gpu.h"

namespace dvsgi::test {
namespace {

using glm::dvec4;

// Whether some point of the triangle lies inside Vulkan's clip volume:
// Sutherland-Hodgman against the six planes, in double precision.
bool triangleReachesClipVolume(const std::array<dvec4, 3>& tri) {
    std::vector<dvec4> poly(tri.begin(), tri.end());
    auto plane = [](const dvec4& p, int k) {
        switch (k) {
        case 0: return p.w + p.x;
        case 1: return p.w - p.x;
        case 2: return p.w + p.y;
        case 3: return p.w - p.y;
        case 4: return p.z;
        default: return p.w - p.z;
        }
    };
    for (int k = 0; k < 6 && !poly.empty(); ++k) {
        std::vector<dvec4> out;
        for (size_t i = 0; i < poly.size(); ++i) {
            const dvec4& a = poly[i];
            const dvec4& b = poly[(i + 1) % poly.size()];
            const double fa = plane(a, k), fb = plane(b, k);
            if (fa >= 0) out.push_back(a);
            if ((fa >= 0) != (fb >= 0)) out.push_back(a + (b - a) * (fa / (fa - fb)));
        }
        poly = out;
    }
    return !poly.empty();
}

// Appends the polygon a, b, c[, d] (a triangle or a quad) as triangles.
void appendPolygon(scene::Primitive& p, std::initializer_list<glm::vec3> corners) {
    const uint32_t base = uint32_t(p.vertices.size());
    for (const glm::vec3& at : corners) {
        scene::Vertex v;
        v.position = at;
        v.normal = glm::vec3(0, 1, 0);
        p.vertices.push_back(v);
    }
    p.indices.insert(p.indices.end(), {base, base + 1, base + 2});
    if (corners.size() == 4) p.indices.insert(p.indices.end(), {base, base + 2, base + 3});
}

// Groups of 32 quads (one chunk of 64 triangles each) around random
// centres, and a last group of 7, so the primitive's last chunk is partial.
scene::Primitive scatteredQuads(std::mt19937& rng, int groups) {
    std::uniform_real_distribution<float> centre(-10.0f, 10.0f), offset(-0.8f, 0.8f), unit(-1.0f, 1.0f);
    scene::Primitive p;
    for (int g = 0; g <= groups; ++g) {
        const glm::vec3 c(centre(rng), centre(rng), centre(rng));
        for (int q = g < groups ? 32 : 7; q > 0; --q) {
            const glm::vec3 o = c + glm::vec3(offset(rng), offset(rng), offset(rng));
            const glm::vec3 u(unit(rng) * 0.2f, unit(rng) * 0.2f, unit(rng) * 0.2f);
            const glm::vec3 v(unit(rng) * 0.2f, unit(rng) * 0.2f, unit(rng) * 0.2f);
            appendPolygon(p, {o - u - v, o + u - v, o + u + v, o - u + v});
        }
    }
    return p;
}

// A random perspective (with or without the renderer's flipped y) or
// orthographic view of the scattered groups.
glm::mat4 randomView(std::mt19937& rng, int i) {
    std::uniform_real_distribution<float> pos(-14.0f, 14.0f), fov(0.3f, 2.2f), extent(2.0f, 12.0f);
    const glm::vec3 eye(pos(rng), pos(rng), pos(rng)), target(pos(rng) * 0.5f, pos(rng) * 0.5f, pos(rng) * 0.5f);
    glm::mat4 proj;
    if (i % 3 == 2) {
        const float e = extent(rng);
        proj = glm::ortho(-e, e, -e * 0.7f, e * 0.7f, 0.5f, 25.0f);
    } else {
        proj = glm::perspective(fov(rng), 1.6f, 0.05f, i % 2 ? 12.0f : 40.0f);
    }
    if (i % 4 == 0) proj[1][1] *= -1.0f;
    return proj * glm::lookAt(eye, target, glm::vec3(0, 1, 0));
}

struct CullCount {
    uint64_t kept = 0, total = 0, missed = 0;
};

// Culls every draw for `viewProj` and counts the triangles an exact clip finds
// inside the volume that no run of the list holds.
void checkView(const scene::Scene& s, const gpuscene::SceneGpu& gpu, const glm::mat4& viewProj, CullCount& c) {
    const gpuscene::DrawList list = gpuscene::visibleDraws(gpu, viewProj, gpuscene::DrawFilter::All);
    c.kept += list.triangles();
    // The scene's own placement, not SceneGpu's copy, which culling reads.
    const std::vector<scene::DrawItem> items = scene::drawItems(s, scene::worldMatrices(s));
    for (uint32_t d = 0; d < gpu.ranges.size(); ++d) {
        const scene::Primitive& prim = s.primitives[items[d].primitive];
        const glm::dmat4 toClip = glm::dmat4(viewProj) * glm::dmat4(items[d].world);
        const std::vector<gpuscene::DrawRun>& runs = gpu.ranges[d].alphaTested ? list.alphaTested : list.opaque;
        for (size_t t = 0; t + 2 < prim.indices.size(); t += 3) {
            ++c.total;
            std::array<dvec4, 3> tri;
            for (size_t k = 0; k < 3; ++k)
                tri[k] = toClip * dvec4(glm::dvec3(prim.vertices[prim.indices[t + k]].position), 1.0);
            if (!triangleReachesClipVolume(tri)) continue;
            const uint32_t index = gpu.ranges[d].firstIndex + uint32_t(t);
            bool inRun = false;
            for (const gpuscene::DrawRun& r : runs)
                inRun = inRun || (r.draw == d && index >= r.firstIndex && index + 3 <= r.firstIndex + r.indexCount);
            c.missed += !inRun;
        }
    }
}

TEST_F(GpuTest, DrawCullingKeepsEveryTriangleThatReachesTheClipVolume) {
    std::mt19937 rng(7);
    scene::Scene s;
    const int mat = addMaterial(s, glm::vec3(0.5f));
    const int cut = addMaterial(s, glm::vec3(0.5f));
    s.materials[size_t(cut)].alphaMode = scene::AlphaMode::Mask;
    addMeshNode(s, scatteredQuads(rng, 60), mat, glm::vec3(0.0f), glm::quat(1, 0, 0, 0), glm::vec3(1.0f));
    const glm::quat turn = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 2, 3)));
    const int moving =
        addMeshNode(s, scatteredQuads(rng, 40), cut, glm::vec3(2.0f, -1.0f, 0.5f), turn, glm::vec3(0.8f, 1.3f, 1.0f));
    s.nodes[size_t(moving)].dynamic = true;
    gpuscene::SceneGpu gpu(context(), s, 1.0f);
    ASSERT_EQ(gpu.ranges.size(), 2u);
    ASSERT_TRUE(gpu.ranges[1].alphaTested);
    const uint64_t triangles[2] = {s.primitives[0].indices.size() / 3, s.primitives[1].indices.size() / 3};
    ASSERT_NE(triangles[0] % gpuscene::SceneGpu::kBoundsChunk, 0u);  // a partial last chunk

    CullCount c;
    for (int i = 0; i < 60; ++i) checkView(s, gpu, randomView(rng, i), c);
    // The moving node, moved: culling follows its new world matrix.
    s.nodes[size_t(moving)].translation = glm::vec3(-6.0f, 3.0f, 4.0f);
    s.nodes[size_t(moving)].rotation = glm::angleAxis(2.1f, glm::vec3(0, 1, 0));
    gpu.updateDraws(context(), s, scene::drawItems(s, scene::worldMatrices(s)));
    for (int i = 0; i < 30; ++i) checkView(s, gpu, randomView(rng, i), c);
    EXPECT_EQ(c.missed, 0u);
    // Not vacuous: most of the scattered groups are outside most views.
    EXPECT_LT(double(c.kept), 0.5 * double(c.total)) << c.kept << " of " << c.total << " triangles kept";
    EXPECT_GT(c.kept, 0u);

    // The filters pick by the node's dynamic flag.
    const glm::mat4 all = glm::ortho(-30.0f, 30.0f, -30.0f, 30.0f, -30.0f, 30.0f);
    const gpuscene::DrawList statics = gpuscene::visibleDraws(gpu, all, gpuscene::DrawFilter::Static);
    const gpuscene::DrawList dynamics = gpuscene::visibleDraws(gpu, all, gpuscene::DrawFilter::Dynamic);
    EXPECT_EQ(statics.triangles(), triangles[0]);
    EXPECT_EQ(dynamics.triangles(), triangles[1]);
    EXPECT_TRUE(statics.alphaTested.empty());
    EXPECT_TRUE(dynamics.opaque.empty());
    for (const gpuscene::DrawRun& r : statics.opaque) EXPECT_EQ(r.draw, 0u);
    for (const gpuscene::DrawRun& r : dynamics.alphaTested) EXPECT_EQ(r.draw, 1u);
}

// A floor of 64 x 64 quads laid out in blocks of 8 x 4 (one chunk each, 1 m by
// 0.5 m), reaching past the view on three sides, and 16 raised occluders.
// With `uncullable`, a zero-area triangle spanning the
// whole scene comes before every 31st quad, so each run of 64 triangles holds
// one: it draws nothing but makes every chunk's bounds reach every view.
scene::Scene floorScene(bool uncullable) {
    scene::Scene s;
    auto quad = [](scene::Primitive& p, glm::vec3 c, float h) {
        appendPolygon(p, {c + glm::vec3(-h, 0, -h), c + glm::vec3(-h, 0, h), c + glm::vec3(h, 0, h),
                          c + glm::vec3(h, 0, -h)});
    };
    auto spanning = [](scene::Primitive& p) {
        appendPolygon(p, {glm::vec3(-50, -50, -50), glm::vec3(0, 0, 0), glm::vec3(50, 50, 50)});
    };
    scene::Primitive floor;
    for (int by = 0; by < 16; ++by)
        for (int bx = 0; bx < 8; ++bx)
            for (int q = 0; q < 32; ++q) {
                if (uncullable && ((by * 8 + bx) * 32 + q) % 31 == 0) spanning(floor);
                const int x = bx * 8 + q % 8, z = by * 4 + q / 8;
                quad(floor, glm::vec3(-1.0f + 0.125f * (float(x) + 0.5f), 0.0f, -1.3f + 0.125f * (float(z) + 0.5f)),
                     0.06f);
            }
    if (uncullable) spanning(floor);  // the last chunk's
    scene::Primitive occluders;
    for (int i = 0; i < 16; ++i) {
        if (uncullable && i == 0) spanning(occluders);  // 33 triangles: one chunk
        quad(occluders, glm::vec3(-1.2f + 0.16f * float(i), 0.6f + 0.05f * float(i % 3), 0.5f * float(i % 5) - 1.0f),
             0.15f);
    }
    addMeshNode(s, floor, addMaterial(s, glm::vec3(0.8f)), glm::vec3(0.0f), glm::quat(1, 0, 0, 0), glm::vec3(1.0f));
    addMeshNode(s, occluders, addMaterial(s, glm::vec3(0.4f, 0.5f, 0.6f)), glm::vec3(0.0f), glm::quat(1, 0, 0, 0),
                glm::vec3(1.0f));
    addTopDownCamera(s, 3.0f, glm::radians(60.0f));
    scene::Light point;
    point.name = "point";
    point.intensity = 20.0f;
    addLight(s, point, glm::vec3(0.6f, 2.0f, 0.3f), glm::vec3(0, -1, 0));
    return s;
}

TEST_F(GpuTest, DrawCullingLeavesTheLitFrameUnchanged) {
    render::RenderSettings rs;
    rs.width = rs.height = 64;
    rs.voxels = 0;  // G-buffer, the point light's six shadow faces, direct light
    render::FrameStats stats[2];
    auto renderFrame = [&](const scene::Scene& s, const render::RenderSettings& settings, render::FrameStats* st) {
        render::Renderer r(context(), s, settings);
        const render::FrameStats f = r.renderFrame();
        if (st) *st = f;
        return r.readOutput();
    };
    image::ImageRGBA32F frames[2];
    for (bool uncullable : {false, true}) {
        const scene::Scene s = floorScene(uncullable);
        const gpuscene::SceneGpu gpu(context(), s, 1.0f);
        const scene::PlacedCamera cam = scene::placedCameras(s, scene::worldMatrices(s)).at(0);
        const glm::mat4 viewProj = render::projectionMatrix(cam, rs.width, rs.height) * render::viewMatrix(cam);
        const uint64_t kept = gpuscene::visibleDraws(gpu, viewProj, gpuscene::DrawFilter::All).triangles();
        if (uncullable)
            EXPECT_EQ(kept, gpu.triangleCount);
        else
            EXPECT_LT(double(kept), 0.3 * double(gpu.triangleCount)) << kept << " of " << gpu.triangleCount;
        frames[uncullable] = renderFrame(s, rs, &stats[uncullable]);
        // The frame reports what its raster passes drew: the camera's list,
        // and the six shadow faces' lists (each face only its own part).
        EXPECT_EQ(stats[uncullable].gbufferTriangles, kept);
        if (uncullable)
            EXPECT_EQ(stats[uncullable].shadowTriangles, 6 * gpu.triangleCount);
        else
            EXPECT_LT(stats[uncullable].shadowTriangles, 3 * gpu.triangleCount) << stats[uncullable].shadowTriangles;
    }
    // Not vacuous: the occluders' shadows are in the frame.
    render::RenderSettings unshadowed = rs;
    unshadowed.shadows = false;
    const image::ImageRGBA32F noShadows = renderFrame(floorScene(false), unshadowed, nullptr);
    ASSERT_EQ(frames[0].rgba.size(), frames[1].rgba.size());
    size_t differ = 0, shadowed = 0, lit = 0;
    for (size_t i = 0; i < frames[0].rgba.size(); i += 4) {
        differ += std::memcmp(&frames[0].rgba[i], &frames[1].rgba[i], 4 * sizeof(float)) != 0;
        shadowed += noShadows.rgba[i] > frames[0].rgba[i] + 0.05f;
        lit += frames[0].rgba[i] + frames[0].rgba[i + 1] + frames[0].rgba[i + 2] > 0.05f;
    }
    std::printf("pixels: %zu lit, %zu in shadow, %zu differing; triangles drawn: G-buffer %llu, shadows %llu\n", lit,
                shadowed, differ, (unsigned long long)stats[0].gbufferTriangles,
                (unsigned long long)stats[0].shadowTriangles);
    EXPECT_EQ(differ, 0u);
    EXPECT_GT(lit, 1000u);
    EXPECT_GT(shadowed, 50u);
}

}  // namespace
}  // namespace dvsgi::test
