// The temporal accumulation pass (render/temporal_indirect.h) alone, on
// synthetic frames (temporal_indirect_harness.h) in which the surfaces or the
// camera move: disoccluded pixels take no history, newly visible ones blend at
// the frame's weight, a floor seen at grazing angles keeps its history, a
// texel whose stored depth overflowed is rejected, and the frame count behind
// the weight.
#include <cmath>
#include <cstdio>
#include <vector>

#include "temporal_indirect_harness.h"

namespace dvsgi::test::temporal {
namespace {

// The quad moves sideways between frames under a still camera: wall pixels it
// uncovered and pixels it newly covers take this frame's term alone; pixels
// that saw the same surface blend.
TEST_F(TemporalIndirect, DisocclusionRejectsHistory) {
    constexpr int kBefore = 5;
    const Camera camera{{0.0f, 0.0f, 5.0f}};
    const Scene a{-0.9f, 0.0f}, b{-0.4f, 0.5f};
    Harness h;
    Frame f = makeFrame(a, camera);
    fill(f, 1.0f, 10.0f);
    for (int k = 0; k < kBefore; ++k) h.run(f, 0.1f);
    Frame g = makeFrame(b, camera);
    fill(g, 2.0f, 20.0f);
    const Outputs o = h.run(g, 0.1f);
    const float alpha = 1.0f / (kBefore + 1);
    int counts[4] = {0, 0, 0, 0}, bad = 0;
    for (uint32_t y = 1; y + 1 < kH; ++y)
        for (uint32_t x = 1; x + 1 < kW; ++x) {
            // Pixels whose 3x3 neighbourhood sees one surface in both frames.
            const size_t i = size_t(y) * kW + x;
            if (!sameSurfaceAround(f, g, x, y) || g.surface[i] < 0) continue;
            const int was = f.surface[i], is = g.surface[i];
            const float cur = g.diffuse[i].r, old = f.diffuse[i].r;
            const float expected = was == is ? old + alpha * (cur - old) : cur;
            const int kind = (was == 0 ? 0 : 2) + (is == 0 ? 0 : 1);  // wall->wall, wall->quad, quad->wall, quad->quad
            ++counts[kind];
            if (!close(o.diffuse[i].r, expected, 1.5e-3) && ++bad <= 5)
                std::printf("  (%u, %u) kind %d: %g, expected %g\n", x, y, kind, o.diffuse[i].r, expected);
        }
    std::printf("  wall kept %d, newly covered %d, uncovered %d, quad kept %d pixels; %d wrong\n", counts[0],
                counts[1], counts[2], counts[3], bad);
    EXPECT_EQ(bad, 0);
    for (int c : counts) EXPECT_GT(c, 50);
}

// One blend weight for the whole frame: four frames in, the quad moves,
// uncovering part of the wall and covering another part; on the next frame
// the history holds five frames, and every pixel that saw the same surface
// last frame moves 1/6 of the way to the new term (the running mean of the
// frames since the history started), those just uncovered or covered too,
// whose own history holds one frame (weighing a pixel's own frames moved
// them half way: the flicker of newly visible surfaces), and not alphaMin.
TEST_F(TemporalIndirect, NewlyVisiblePixelsBlendAtTheFramesWeight) {
    constexpr int kBefore = 4;
    constexpr float kMinAlpha = 0.1f;
    const float alpha = render::temporalBlendWeight(kMinAlpha, kBefore + 1, true);
    ASSERT_FLOAT_EQ(alpha, 1.0f / 6.0f);
    const Camera camera{{0.0f, 0.0f, 5.0f}};
    const Scene a{-0.9f, 0.0f}, b{-0.4f, 0.5f};
    Harness h;
    Frame f = makeFrame(a, camera);
    fill(f, 1.0f, 10.0f);
    for (int k = 0; k < kBefore; ++k) h.run(f, kMinAlpha);
    Frame g = makeFrame(b, camera);
    fill(g, 2.0f, 20.0f);
    const Outputs moved = h.run(g, kMinAlpha);
    fill(g, 3.0f, 30.0f);
    const Outputs next = h.run(g, kMinAlpha);
    int uncovered = 0, covered = 0, kept = 0, bad = 0;
    for (uint32_t y = 1; y + 1 < kH; ++y)
        for (uint32_t x = 1; x + 1 < kW; ++x) {
            const size_t i = size_t(y) * kW + x;
            if (!sameSurfaceAround(f, g, x, y) || g.surface[i] < 0) continue;
            const float old = moved.diffuse[i].r, cur = g.diffuse[i].r;
            const float expected = old + alpha * (cur - old);
            if (f.surface[i] == g.surface[i]) ++kept;
            else if (g.surface[i] == 0) ++uncovered;
            else ++covered;
            if (!close(next.diffuse[i].r, expected, 1.5e-3) && ++bad <= 5)
                std::printf("  (%u, %u): %g, expected %g (last frame %g)\n", x, y, next.diffuse[i].r, expected, old);
        }
    std::printf("  uncovered %d, newly covered %d, kept %d pixels; %d wrong\n", uncovered, covered, kept, bad);
    EXPECT_EQ(bad, 0);
    EXPECT_GT(uncovered, 50);
    EXPECT_GT(covered, 50);
    EXPECT_GT(kept, 500);
}

// A floor seen at a grazing angle by a camera that walks forward: near the
// horizon the view depths of vertically neighbouring pixels differ by far more
// than the tolerance, yet every floor pixel that last frame saw takes its
// history, because a tap counts as the same surface when its point lies on
// the pixel's tangent plane. (Comparing each tap's depth with the point's
// rejected whole rows there, which then showed the raw gather.)
TEST_F(TemporalIndirect, GrazingFloorKeepsItsHistory) {
    constexpr int kBefore = 4;
    constexpr float kMinAlpha = 0.1f;
    const float alpha = render::temporalBlendWeight(kMinAlpha, kBefore, true);
    const Camera previous{{0.0f, 0.0f, 0.0f}}, current{{0.0f, 0.0f, -0.05f}};
    Frame f = makeFloorFrame(previous);
    fill(f, 1.0f, 0.0f);
    Harness h;
    for (int k = 0; k < kBefore; ++k) h.run(f, kMinAlpha);
    Frame g = makeFloorFrame(current);
    fill(g, 2.0f, 0.0f);
    const Outputs o = h.run(g, kMinAlpha);
    const glm::mat4 prevVp = previous.viewProj();
    int checked = 0, grazing = 0, bad = 0;
    for (uint32_t y = 1; y + 1 < kH; ++y)
        for (uint32_t x = 1; x + 1 < kW; ++x) {
            const size_t i = size_t(y) * kW + x;
            if (!sameSurfaceAround(f, g, x, y) || g.surface[i] < 0) continue;
            // Where last frame's camera saw this pixel's point: on screen, and
            // how much the view depth changes from one row to the next there.
            const glm::vec4 clip = prevVp * glm::vec4(pointAt(g, x, y), 1.0f);
            const glm::vec2 q = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(kW, kH);
            if (q.x < 1.0f || q.y < 1.0f || q.x > kW - 1.0f || q.y > kH - 1.0f) continue;
            ++checked;
            const Hit below = castFloor(previous, uint32_t(q.x), uint32_t(q.y) + 1);
            const float belowDepth = (prevVp * glm::vec4(below.point, 1.0f)).w;
            if (below.found && std::abs(belowDepth - clip.w) > 2.0f * sh::TEMPORAL_DEPTH_TOLERANCE * clip.w) ++grazing;
            const float expected = 1.0f + alpha * (2.0f - 1.0f);
            if (!close(o.diffuse[i].r, expected, 1.5e-3) && ++bad <= 5)
                std::printf("  (%u, %u): %g, expected %g\n", x, y, o.diffuse[i].r, expected);
        }
    std::printf("  %d floor pixels checked, %d where the next row's view depth differs by more than twice the "
                "tolerance; %d wrong\n", checked, grazing, bad);
    EXPECT_EQ(bad, 0);
    EXPECT_GT(checked, 1000);
    EXPECT_GT(grazing, 200);
}

// Last frame's stored view depth can overflow RGBA16F (beyond 65504 m it is
// +inf): the point rebuilt from it is not finite, its distance to the tangent
// plane may be NaN, and such a texel must be rejected like any other that
// saw another surface. A block of history texels holding +inf: the pixels
// whose four taps all lie in it keep this frame's term exactly, the others
// blend.
TEST_F(TemporalIndirect, OverflowedStoredDepthRejectsTheTexel) {
    const Camera camera{{0.05f, 0.02f, 5.0f}};
    const Scene scene;
    Frame f = makeFrame(scene, camera);
    fill(f, 2.0f, 2.0f);
    const size_t n = size_t(kW) * kH;
    std::vector<glm::vec4> history(n, glm::vec4(1.0f, 1.0f, 1.0f, 4.0f)), surface(n, glm::vec4(0.0f));
    const glm::mat4 vp = f.viewProj;
    auto inBlock = [](uint32_t x, uint32_t y) { return x >= 40 && x < 56 && y >= 10 && y < 54; };
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) {
            const size_t i = size_t(y) * kW + x;
            if (f.depth[i] >= 1.0f) continue;
            const float depth = (vp * glm::vec4(pointAt(f, x, y), 1.0f)).w;
            surface[i] = toHalf(glm::vec4(0.0f, 0.0f, 1.0f, inBlock(x, y) ? 1e6f : depth));
        }
    ASSERT_TRUE(std::isinf(toHalf(1e6f)));
    Harness h;
    // The same camera last frame: every pixel reprojects onto itself.
    h.setHistory(history, surface, vp, 4);
    const float alpha = render::temporalBlendWeight(0.1f, 4, true);
    const Outputs o = h.run(f, 0.1f);
    int kept = 0, blended = 0, bad = 0;
    for (uint32_t y = 1; y + 1 < kH; ++y)
        for (uint32_t x = 1; x + 1 < kW; ++x) {
            const size_t i = size_t(y) * kW + x;
            if (f.surface[i] < 0 || !sameSurfaceAround(f, f, x, y)) continue;
            // Inside the block by a pixel: every tap is an overflowed texel.
            const bool rejected = inBlock(x - 1, y - 1) && inBlock(x + 1, y + 1);
            const bool outside = !inBlock(x - 1, y - 1) && !inBlock(x + 1, y - 1) && !inBlock(x - 1, y + 1) &&
                                 !inBlock(x + 1, y + 1);
            if (!rejected && !outside) continue;
            const float expected = rejected ? 2.0f : 1.0f + alpha * (2.0f - 1.0f);
            (rejected ? kept : blended)++;
            if (!std::isfinite(o.diffuse[i].r) || !close(o.diffuse[i].r, expected, 1.5e-3)) {
                if (++bad <= 5) std::printf("  (%u, %u): %g, expected %g\n", x, y, o.diffuse[i].r, expected);
            }
        }
    std::printf("  %d pixels with every tap overflowed kept this frame's term, %d blended; %d wrong\n", kept, blended,
                bad);
    EXPECT_EQ(bad, 0);
    EXPECT_GT(kept, 300);
    EXPECT_GT(blended, 1000);
}

// The frame count behind the weight: a hold of three frames restarts it, and
// the first frame after the hold weighs 1/2, the next 1/3.
TEST(TemporalState, HistoryFramesRestartAfterAHold) {
    render::TemporalState s;
    const glm::mat4 vp(1.0f);
    for (int k = 0; k < 30; ++k) {
        s.beginFrame();
        s.advance(vp);
    }
    EXPECT_TRUE(s.valid);
    EXPECT_EQ(s.frames, 30u);
    s.drop(3);
    for (int k = 0; k < 3; ++k) {
        s.beginFrame();
        EXPECT_FALSE(s.valid) << "held frame " << k;
        s.advance(vp);
        EXPECT_EQ(s.frames, 1u);
    }
    s.beginFrame();
    ASSERT_TRUE(s.valid);
    EXPECT_FLOAT_EQ(render::temporalBlendWeight(0.05f, s.frames, true), 0.5f);
    EXPECT_FLOAT_EQ(render::temporalBlendWeight(0.05f, s.frames, false), 0.05f);  // a settled light
    s.advance(vp);
    s.beginFrame();
    EXPECT_FLOAT_EQ(render::temporalBlendWeight(0.05f, s.frames, true), 1.0f / 3.0f);
    for (int k = 0; k < 100; ++k) {
        s.advance(vp);
        s.beginFrame();
    }
    EXPECT_FLOAT_EQ(render::temporalBlendWeight(0.05f, s.frames, true), 0.05f);
}

}  // namespace
}  // namespace dvsgi::test::temporal
