// Converged and feedback bounces (--bounces auto). In a closed box of albedo
// rho and emission L every wall converges to L / (1 - rho t), t the fraction
// of light one bounce carries; with rho = 0.9 ten bounces still leave a third
// of the light missing, so this checks that iterating to convergence reaches
// the infinite series. An open box must let light escape as radiosity on the
// CPU says. A light switched off, or a moved emitter, must leave no lasting
// indirect light under feedback. A renderer whose voxel slots run out grows them and
// renders the same frame.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "gpu_fixture.h"
#include "light_helpers.h"
#include "shared/voxel_data.h"
#include "vxgi/voxel_light_settings.h"

namespace dvsgi::test {
namespace {

constexpr uint32_t kN = 32;
constexpr float kHalf = 0.71875f;  // walls in the middle of voxel layers 4 and 27 of [-1, 1]^3
constexpr int kLow = 4, kHigh = 27, kInnerLo = 10, kInnerHi = 21;
constexpr int kMidZ = int(kN) / 2 - 1;  // the row the closed furnace prints

// The voxel bounce traced the default way unless a test names one.
render::RenderSettings boxSettings(vxgi::BounceTrace trace = vxgi::VoxelLightSettings{}.bounceTrace) {
    render::RenderSettings rs = unitBoxGridSettings(kN, 256);
    rs.voxelLight.bounceTrace = trace;
    return rs;
}

// Mean of one channel over the wall voxels away from edges, all six walls.
double wallMean(const Rgba16Volume& v, int channel = 0) {
    double sum = 0.0;
    int count = 0;
    forEachWallVoxel(kLow, kHigh, kInnerLo, kInnerHi, [&](glm::ivec3 p) {
        sum += v.at(p.x, p.y, p.z)[channel];
        ++count;
    });
    return sum / count;
}

// A box of walls of albedo rho emitting L (the furnace; L = 0: a plain box); with
// openTop its +y face is left out.
scene::Scene emissiveBox(float rho, float L, bool openTop = false) {
    scene::Scene s;
    addInwardBox(s, addMaterial(s, glm::vec3(rho), glm::vec3(L)), glm::vec3(0.0f), kHalf, openTop);
    addTopDownCamera(s, 0.0f, glm::radians(60.0f));
    return s;
}

// The radiance volume after one frame with exactly one voxel bounce.
Rgba16Volume radianceAfterOneBounce(const scene::Scene& s,
                                    vxgi::BounceTrace trace = vxgi::VoxelLightSettings{}.bounceTrace) {
    render::RenderSettings one = boxSettings(trace);
    one.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    one.voxelLight.bounces = 1;
    render::Renderer r(context(), s, one);
    r.renderFrame();
    return readRgba16(r.volumes()->radiance);
}

// The closed box of albedo 0.5 lit by a point light of 1 W/sr under its ceiling.
scene::Scene lampLitBox() {
    scene::Scene s = emissiveBox(0.5f, 0.0f);
    scene::Light light;
    light.name = "lamp";
    light.type = scene::LightType::Point;
    light.intensity = 1.0f;
    addLight(s, light, glm::vec3(0.0f, 0.5f, 0.0f), glm::vec3(0, -1, 0));
    return s;
}

// The open box of albedo 0.5 with a small dynamic emitter facing the floor
// at x = lampX (the node index of the emitter second).
std::pair<scene::Scene, int> lampBox(float lampX) {
    scene::Scene s = emissiveBox(0.5f, 0.0f, true);
    const glm::quat down = glm::angleAxis(glm::pi<float>(), glm::vec3(1, 0, 0));
    const int lamp =
        addQuad(s, addMaterial(s, glm::vec3(0.0f), glm::vec3(20.0f)), glm::vec3(lampX, -0.2f, 0.0f), 0.1f, down);
    s.nodes[size_t(lamp)].dynamic = true;
    return {s, lamp};
}

// Mean radiance of the floor's inner voxels on the -x side (under lampBox(-0.4)).
double lampSideFloorMean(const Rgba16Volume& v) {
    double sum = 0.0;
    int count = 0;
    for (int x = kInnerLo; x < 16; ++x)
        for (int z = kInnerLo; z <= kInnerHi; ++z) {
            sum += v.at(x, kLow, z).r;
            ++count;
        }
    return sum / count;
}

class Converge : public GpuTest {};

// With the voxel bounce's cones (--bounce-trace cones, the paper's).
TEST_F(Converge, ClosedFurnaceReachesTheInfiniteSeriesOfItsTransport) {
    constexpr float kRho = 0.9f, kL = 1.0f;
    const scene::Scene s = emissiveBox(kRho, kL);
    // One bounce measures what fraction t of the light a bounce carries here
    // (L + rho t L); converging must then reach the series' limit L / (1 - rho t).
    const Rgba16Volume first = radianceAfterOneBounce(s, vxgi::BounceTrace::Cones);
    const double t = (wallMean(first) / kL - 1.0) / kRho;

    render::RenderSettings rs = boxSettings(vxgi::BounceTrace::Cones);
    rs.voxelLight.bounceMode = vxgi::BounceMode::Converge;
    rs.voxelLight.convergence = 0.002f;
    rs.voxelLight.maxBounces = 200;
    render::Renderer r(context(), s, rs);
    const render::FrameStats st = r.renderFrame();
    const double limit = kL / (1.0 - kRho * t), exact = kL / (1.0 - kRho);
    const Rgba16Volume converged = readRgba16(r.volumes()->radiance);
    const double got = wallMean(converged);
    std::printf("  one bounce carries t = %.4f; %u bounces, last change %.2e: wall mean %.4f, limit L/(1-rho t) %.4f "
                "(%+.2f%%), exact L/(1-rho) %.4f (%+.2f%%)\n",
                t, st.bounces, st.bounceChange, got, limit, 100.0 * (got / limit - 1.0), exact,
                100.0 * (got / exact - 1.0));
    // Where the light goes: t per voxel along the floor's middle row, wall to
    // wall, and the converged radiance there (docs/quality.md).
    std::printf("  floor row (y %d, z %d), x %d..%d: t after one bounce", kLow, kMidZ, kLow, kHigh);
    for (int x = kLow; x <= kHigh; ++x) std::printf(" %.3f", (first.at(x, kLow, kMidZ)[0] / kL - 1.0) / kRho);
    std::printf("\n  converged");
    for (int x = kLow; x <= kHigh; ++x) std::printf(" %.2f", converged.at(x, kLow, kMidZ)[0]);
    std::printf("\n");
    EXPECT_TRUE(st.converged);
    EXPECT_GT(st.bounces, 15u);  // (rho t)^15 < 0.15: far from converged before that
    // Measured on lavapipe: t = 0.9927 over the inner wall voxels on the
    // first bounce, but along the printed row it falls from 0.995 mid-wall
    // to 0.97-0.98 two to five voxels from each edge (0.91 in the edge
    // voxel); that band is over half of each wall and what the inner walls
    // see, so the converged wall is 7.0 % below L / (1 - rho t) and 12.8 %
    // below L / (1 - rho): at rho = 0.9 a bounce's transport counts ten
    // times over. The light leaves the box far along the cones, through
    // coarse mip cells that hold a wall and the margin (docs/quality.md).
    // While the cone tracer interpolated opacity along the cone, t was 0.889
    // and the wall 49 % below L / (1 - rho). Bounds: 1.5 times the measured
    // losses.
    EXPECT_GT(t, 0.989);
    EXPECT_NEAR(got / limit, 1.0, 0.105);
    EXPECT_GT(got / exact, 1.0 - 1.5 * 0.128);
}

// The bounce's rays (--bounce-trace rays) stop at the first voxel they cross,
// so a closed box keeps all its light: one bounce carries t = 1 and the
// walls converge to L / (1 - rho), the goal within 1 %.
TEST_F(Converge, ClosedFurnaceWithRaysReachesTheExactSeries) {
    constexpr float kRho = 0.9f, kL = 1.0f;
    const scene::Scene s = emissiveBox(kRho, kL);
    const double t = (wallMean(radianceAfterOneBounce(s, vxgi::BounceTrace::Rays)) / kL - 1.0) / kRho;
    render::RenderSettings rs = boxSettings(vxgi::BounceTrace::Rays);
    rs.voxelLight.bounceMode = vxgi::BounceMode::Converge;
    // Tighter than the cones' test: near the limit a bounce adds one or two
    // half-float steps of the radiance (0.08 % each), so the shrinking of the
    // change, from which converging extrapolates what is missing, is noise;
    // at 0.002 it stopped 1.1 % short.
    rs.voxelLight.convergence = 0.0005f;
    rs.voxelLight.maxBounces = 200;
    render::Renderer r(context(), s, rs);
    const render::FrameStats st = r.renderFrame();
    const double got = wallMean(readRgba16(r.volumes()->radiance)), exact = kL / (1.0 - kRho);
    std::printf("  rays: one bounce carries t = %.4f; %u bounces, last change %.2e: wall mean %.4f, L/(1-rho) %.4f "
                "(%+.2f%%)\n",
                t, st.bounces, st.bounceChange, got, exact, 100.0 * (got / exact - 1.0));
    EXPECT_TRUE(st.converged);
    EXPECT_NEAR(t, 1.0, 0.002);  // measured +0.04 % (half-float rounding)
    EXPECT_NEAR(got / exact, 1.0, 0.01);
}

// The open box: the furnace's walls with the top (+y) left out. Calls
// f(voxel, point on the wall's plane, inward normal) for the inner voxels of
// the five walls.
template <typename F>
void forEachOpenBoxWallVoxel(F&& f) {
    const double voxel = 2.0 / kN;
    forEachWallVoxel(kLow, kHigh, kInnerLo, kInnerHi, [&](glm::ivec3 v) {
        if (v.y == kHigh) return;  // the opening
        glm::dvec3 n(0.0);
        glm::dvec3 p = glm::dvec3(v) * voxel + (0.5 * voxel - 1.0);
        for (int a = 0; a < 3; ++a) {
            if (v[a] == kLow) n[a] = 1.0;
            if (v[a] == kHigh) n[a] = -1.0;
            if (n[a] != 0.0) p[a] = -n[a] * kHalf;
        }
        f(v, p, n);
    });
}

// Form factor from point p (unit normal np) to a small patch of area `area`
// at q (unit normal nq): cos cos / (pi r^2) times the area, 0 facing away.
double formFactor(glm::dvec3 p, glm::dvec3 np, glm::dvec3 q, glm::dvec3 nq, double area) {
    const glm::dvec3 d = q - p;
    const double r2 = glm::dot(d, d);
    const double cosP = glm::dot(np, d), cosQ = -glm::dot(nq, d);  // both times r
    return cosP > 0.0 && cosQ > 0.0 ? cosP * cosQ / (glm::pi<double>() * r2 * r2) * area : 0.0;
}

// Radiosity of the open box of half-size h, albedo rho and emission L on the
// CPU: each of the five walls cut into kPatches^2 patches, point-to-point form
// factors between patch centres, B = L + rho F B iterated to convergence.
class OpenBoxRadiosity {
public:
    static constexpr int kPatches = 24;
    OpenBoxRadiosity(double h, double rho, double L) : h_(h) {
        for (int face = 0; face < 5; ++face)
            for (int i = 0; i < kPatches; ++i)
                for (int j = 0; j < kPatches; ++j) {
                    const Patch p = patch(face, i, j);
                    centres_.push_back(p.centre);
                    normals_.push_back(p.normal);
                }
        const size_t n = centres_.size();
        const double area = std::pow(2.0 * h / kPatches, 2.0);
        std::vector<double> F(n * n, 0.0);
        for (size_t a = 0; a < n; ++a)
            for (size_t b = 0; b < n; ++b) F[a * n + b] = formFactor(centres_[a], normals_[a], centres_[b], normals_[b], area);
        B_.assign(n, L);
        for (int it = 0; it < 400; ++it) {
            std::vector<double> next(n, L);
            for (size_t a = 0; a < n; ++a)
                for (size_t b = 0; b < n; ++b) next[a] += rho * F[a * n + b] * B_[b];
            B_.swap(next);
        }
    }
    // Radiance at point p on the wall of inward normal n: its patch's value.
    double at(glm::dvec3 p, glm::dvec3 n) const {
        double best = 1e30, value = 0.0;
        for (size_t a = 0; a < centres_.size(); ++a)
            if (glm::dot(normals_[a], n) > 0.5) {
                const double d = glm::length(centres_[a] - p);
                if (d < best) best = d, value = B_[a];
            }
        return value;
    }

private:
    struct Patch {
        glm::dvec3 centre, normal;
    };
    // Faces: inward normals +x, -x, +y (the floor), +z, -z.
    Patch patch(int face, int i, int j) const {
        static const glm::dvec3 normals[5] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}};
        const glm::dvec3 n = normals[face];
        const int axis = n.x != 0.0 ? 0 : (n.y != 0.0 ? 1 : 2);
        const int u = (axis + 1) % 3, w = (axis + 2) % 3;
        const double cell = 2.0 * h_ / kPatches;
        glm::dvec3 c(0.0);
        c[axis] = -n[axis] * h_;
        c[u] = -h_ + (i + 0.5) * cell;
        c[w] = -h_ + (j + 0.5) * cell;
        return {c, n};
    }
    double h_;
    std::vector<glm::dvec3> centres_, normals_;
    std::vector<double> B_;
};

// Cosine-weighted view factor from point p (unit normal n) to the open top
// (which faces -y), by the midpoint rule.
double viewFactorToTop(glm::dvec3 p, glm::dvec3 n, double h) {
    constexpr int kSteps = 96;
    const double cell = 2.0 * h / kSteps;
    double f = 0.0;
    for (int i = 0; i < kSteps; ++i)
        for (int j = 0; j < kSteps; ++j)
            f += formFactor(p, n, glm::dvec3(-h + (i + 0.5) * cell, h, -h + (j + 0.5) * cell), glm::dvec3(0, -1, 0),
                            cell * cell);
    return f;
}

// One bounce's transport over the open box's walls against view factors,
// and the converged walls against radiosity (printed, returned as ratios).
struct OpenBoxRatios {
    double oneBounce, converged;
};

OpenBoxRatios openBoxRatios(vxgi::BounceTrace trace) {
    constexpr float kRho = 0.9f, kL = 1.0f;
    const char* name = trace == vxgi::BounceTrace::Rays ? "rays" : "cones";
    const scene::Scene s = emissiveBox(kRho, kL, true);
    const Rgba16Volume radiance = radianceAfterOneBounce(s, trace);
    double got = 0.0, want = 0.0;
    int count = 0;
    forEachOpenBoxWallVoxel([&](glm::ivec3 v, glm::dvec3 p, glm::dvec3 n) {
        got += (radiance.at(v.x, v.y, v.z).r / kL - 1.0) / kRho;
        want += 1.0 - viewFactorToTop(p, n, kHalf);
        ++count;
    });
    got /= count;
    want /= count;
    std::printf("  %s: one bounce carries t = %.4f over the open box's walls; view factors give %.4f (%+.1f%%)\n",
                name, got, want, 100.0 * (got / want - 1.0));
    // Converged, against radiosity on the CPU: the five walls cut into
    // kPatches^2 patches each, point-to-point form factors, B = E + rho F B.
    render::RenderSettings conv = boxSettings(trace);
    conv.voxelLight.bounceMode = vxgi::BounceMode::Converge;
    conv.voxelLight.convergence = 0.001f;
    conv.voxelLight.maxBounces = 200;
    render::Renderer rc(context(), s, conv);
    rc.renderFrame();
    const Rgba16Volume converged = readRgba16(rc.volumes()->radiance);
    const OpenBoxRadiosity truth(kHalf, kRho, kL);
    double gotC = 0.0, wantC = 0.0;
    count = 0;
    forEachOpenBoxWallVoxel([&](glm::ivec3 v, glm::dvec3 p, glm::dvec3 n) {
        gotC += converged.at(v.x, v.y, v.z).r;
        wantC += truth.at(p, n);
        ++count;
    });
    gotC /= count;
    wantC /= count;
    std::printf("  %s: converged wall radiance %.4f, radiosity %.4f (%+.1f%%)\n", name, gotC, wantC,
                100.0 * (gotC / wantC - 1.0));
    return {got / want, gotC / wantC};
}

// An open box must let light escape: one bounce carries, at each wall voxel,
// the fraction of its hemisphere that sees walls, 1 - F(opening), and the
// converged walls match radiosity. Light that leaves through the opening does
// not come back (the grid's transparent border).
TEST_F(Converge, OpenBoxLetsLightEscapeAsRadiosityDoes) {
    const OpenBoxRatios r = openBoxRatios(vxgi::BounceTrace::Cones);
    // Measured on lavapipe: +1.8 % (six cones cannot resolve the opening's
    // edge better), converged -2.1 %; bounds 1.5 times that.
    EXPECT_NEAR(r.oneBounce, 1.0, 0.027);
    EXPECT_NEAR(r.converged, 1.0, 0.032);
}

TEST_F(Converge, OpenBoxLetsLightEscapeWithRays) {
    const OpenBoxRatios r = openBoxRatios(vxgi::BounceTrace::Rays);
    // Measured on lavapipe: +0.5 % (+0.7 % while the rays started a voxel
    // off the voxel's centre, not just past its face; +1.7 % while a ray that
    // entered a wall's voxel stopped there, in front of the wall), converged
    // -5.2 % (-5.5 %, and -2.8 % then: at rho = 0.9 the converged light moves
    // about 3.6 times a bounce's change; docs/quality.md); bounds 1.5 times
    // that.
    EXPECT_NEAR(r.oneBounce, 1.0, 0.008);
    EXPECT_NEAR(r.converged, 1.0, 0.078);
}

// With --voxel-temporal-alpha too: a change of lights holds the blend back
// while the light settles, so it goes as fast as without it. The blending
// renderer converges its first frame and then blends over a few feedback
// frames before the switch.
class SwitchedOff : public GpuTest, public ::testing::WithParamInterface<float> {};

TEST_P(SwitchedOff, LightLeavesNoIndirectLightUnderFeedback) {
    scene::Scene s = lampLitBox();
    render::RenderSettings rs = boxSettings();
    const bool blended = GetParam() < 1.0f;
    rs.voxelLight.bounceMode = blended ? vxgi::BounceMode::Converge : vxgi::BounceMode::Feedback;
    rs.voxelLight.temporalAlpha = GetParam();
    render::Renderer r(context(), s, rs);
    // Feedback: frame k holds k - 1 bounces; 20 frames are converged for rho = 0.5.
    for (int f = 0; f < (blended ? 4 : 20); ++f) r.renderFrame();
    const double lit = wallMean(readRgba16(r.volumes()->radiance));
    const double indirect = lit - wallMean(readDirect(*r.volumes()));
    ASSERT_GT(indirect, 0.05 * lit);
    r.scene().lights[0].intensity = 0.0f;
    r.sceneChanged();
    // Each frame keeps what one bounce returns of the last: about rho times it
    // in a closed box, so 1 % is reached after ln(0.01) / ln(rho) = 6.6 frames.
    constexpr int kFrames = 10;
    int frames = 0;
    double left = indirect;
    while (frames < kFrames && left >= 0.01 * indirect) {
        r.renderFrame();
        ++frames;
        left = wallMean(readRgba16(r.volumes()->radiance));
    }
    std::printf("  indirect %.5f with the light on; below 1 %% after %d frame(s) off (%.2e left)\n", indirect, frames,
                left);
    EXPECT_LT(left, 0.01 * indirect) << "after " << kFrames << " frames";
}

INSTANTIATE_TEST_SUITE_P(Converge, SwitchedOff, ::testing::Values(1.0f, 0.25f),
                         [](const ::testing::TestParamInfo<float>& i) {
                             return std::string(i.param < 1.0f ? "Blended" : "Plain");
                         });

// Feedback frames after a converged one keep its light: a frame's bounce reads
// the light of the frame before (the cones its filtered volumes, the rays its
// static voxels' radiance, which the voxel light pass leaves as the bounce
// wrote it). Rays that read the radiance as the voxel light pass rewrites it,
// direct light only, held one bounce from the second frame on: the walls fell
// 18.7 % below the converged light here (measured 0.07 % now).
TEST_F(Converge, FeedbackFramesKeepTheConvergedLight) {
    const scene::Scene s = lampLitBox();
    render::RenderSettings rs = boxSettings();
    rs.voxelLight.convergence = 0.002f;
    rs.voxelLight.maxBounces = 200;
    render::Renderer r(context(), s, rs);
    const render::FrameStats first = r.renderFrame();
    ASSERT_TRUE(first.converged);
    const double converged = wallMean(readRgba16(r.volumes()->radiance));
    const double direct = wallMean(readDirect(*r.volumes()));
    ASSERT_GT(converged, 1.2 * direct);
    double worst = 0.0;
    for (int f = 0; f < 4; ++f) {
        r.renderFrame();
        worst = std::max(worst, std::abs(wallMean(readRgba16(r.volumes()->radiance)) / converged - 1.0));
    }
    std::printf("  walls converged %.5f (direct %.5f); four feedback frames after it: at most %.3f %% off\n", converged,
                direct, 100.0 * worst);
    EXPECT_LT(worst, 0.005);
    // A static re-voxelization (static geometry moved, or asked for) leaves
    // the rays no last light to read: the frame after it converges again.
    r.markStaticDirty();
    const render::FrameStats again = r.renderFrame();
    const double revoxelized = wallMean(readRgba16(r.volumes()->radiance));
    r.revoxelizeStatic();
    r.renderFrame();
    const double revoxelizedApart = wallMean(readRgba16(r.volumes()->radiance));
    std::printf("  after a static re-voxelization in the frame: %.5f (%u bounces); done before the frame: %.5f\n",
                revoxelized, again.bounces, revoxelizedApart);
    EXPECT_NEAR(revoxelized / converged, 1.0, 0.005);
    EXPECT_NEAR(revoxelizedApart / converged, 1.0, 0.005);
}

// Under feedback a moved object's light must not linger where it was: a small
// dynamic emitter lights the open box from its -x side, then moves to the +x
// side. Within 8 frames (measured on lavapipe: 5, 0.4 % left) the floor's -x
// half holds what a renderer that always had the emitter in its new place
// converges to.
TEST_F(Converge, MovedObjectLeavesNoLastingGlowUnderFeedback) {
    render::RenderSettings rs = boxSettings();
    rs.voxelLight.bounceMode = vxgi::BounceMode::Feedback;
    constexpr int kSettle = 20;  // feedback frames to converge with rho = 0.5
    const auto [moved, lamp] = lampBox(-0.4f);
    render::Renderer r(context(), moved, rs);
    for (int f = 0; f < kSettle; ++f) r.renderFrame();
    render::Renderer ref(context(), lampBox(0.4f).first, rs);
    for (int f = 0; f < kSettle; ++f) ref.renderFrame();
    const double want = lampSideFloorMean(readRgba16(ref.volumes()->radiance));
    // Where the emitter was, in excess of the reference.
    auto excess = [&](const Rgba16Volume& v) { return lampSideFloorMean(v) - want; };
    const double glow = excess(readRgba16(r.volumes()->radiance));
    ASSERT_GT(glow, 0.05);
    r.scene().nodes[size_t(lamp)].translation.x = 0.4f;
    r.sceneChanged();
    constexpr int kFrames = 8;
    int frames = 0;
    double left = glow;
    while (frames < kFrames && std::abs(left) >= 0.01 * glow) {
        r.renderFrame();
        ++frames;
        left = excess(readRgba16(r.volumes()->radiance));
    }
    std::printf("  floor under the old place: %.4f above the reference with the emitter there; %+.2e after %d "
                "frame(s) with it moved\n",
                glow, left, frames);
    EXPECT_LT(std::abs(left), 0.01 * glow) << "after " << kFrames << " frames";
}

// --voxel-temporal-alpha a: a feedback frame moves the light each voxel
// reflects only a fraction a of the way to its new value. Two renderers of the
// open box with the dynamic emitter, one blending, converge to the same light;
// the emitter is gathered by the cones (--emitters cones), since a moved area
// light is a change of lights, which holds the blending back. After the
// emitter moves, the floor (all of its light reflected) sees it in the second
// frame, whose bounce reads the first one's volumes; there the blending one's
// floor changes by a times the other's, and the glow where the emitter was
// still goes, more slowly: a frame keeps about 1 - a (1 - t) of it, t the
// fraction of it the next bounce returns.
TEST_F(Converge, VoxelTemporalBlendMovesAFractionOfTheWay) {
    constexpr float kAlpha = 0.25f;
    // The first frame converges; the blend starts with the second feedback frame.
    render::RenderSettings rs = boxSettings();
    rs.voxelLight.bounceMode = vxgi::BounceMode::Converge;
    rs.voxelLight.convergence = 0.002f;
    rs.voxelLight.maxBounces = 200;
    rs.emitterLights = false;
    const auto [s, lamp] = lampBox(-0.4f);
    render::Renderer plain(context(), s, rs);
    rs.voxelLight.temporalAlpha = kAlpha;
    render::Renderer blended(context(), s, rs);
    for (int f = 0; f < 4; ++f) {
        plain.renderFrame();
        blended.renderFrame();
    }
    const double plain0 = lampSideFloorMean(readRgba16(plain.volumes()->radiance));
    const double blended0 = lampSideFloorMean(readRgba16(blended.volumes()->radiance));
    std::printf("  floor under the emitter, converged: %.5f plain, %.5f blended\n", plain0, blended0);
    EXPECT_NEAR(blended0 / plain0, 1.0, 0.005);

    for (render::Renderer* r : {&plain, &blended}) {
        r->scene().nodes[size_t(lamp)].translation.x = 0.4f;
        r->sceneChanged();
        r->renderFrame();
    }
    // The bounce's cones gather last frame's light from the filtered volumes,
    // so with them nothing on the floor moves yet; the rays see the dynamic
    // emitter where it is now.
    int frames = 1;
    if (rs.voxelLight.bounceTrace == vxgi::BounceTrace::Cones) {
        EXPECT_NEAR(lampSideFloorMean(readRgba16(plain.volumes()->radiance)), plain0, 1e-3 * plain0);
        EXPECT_NEAR(lampSideFloorMean(readRgba16(blended.volumes()->radiance)), blended0, 1e-3 * blended0);
        plain.renderFrame();
        blended.renderFrame();
        frames = 2;
    }
    const double plain1 = lampSideFloorMean(readRgba16(plain.volumes()->radiance));
    const double blended1 = lampSideFloorMean(readRgba16(blended.volumes()->radiance));
    const double fraction = (blended1 - blended0) / (plain1 - plain0);
    std::printf("  after the move: plain %.5f, blended %.5f: %.3f of the plain change (alpha %.2f)\n", plain1,
                blended1, fraction, kAlpha);
    EXPECT_NEAR(fraction, kAlpha, 0.01);

    // The glow left where the emitter was, against what the plain renderer
    // settles to with the emitter in its new place.
    for (int f = 0; f < 20; ++f) plain.renderFrame();
    const double settled = lampSideFloorMean(readRgba16(plain.volumes()->radiance));
    const double glow = blended1 - settled;
    constexpr int kFrames = 36;  // measured on lavapipe: 18 (rays), 25 (cones) (1 - a (1 - t) = 0.84 a frame)
    double left = glow;
    while (frames < kFrames && std::abs(left) >= 0.01 * glow) {
        blended.renderFrame();
        ++frames;
        left = lampSideFloorMean(readRgba16(blended.volumes()->radiance)) - settled;
    }
    std::printf("  glow %.4f after the first change; %+.2e after %d frame(s)\n", glow, left, frames);
    EXPECT_LT(std::abs(left), 0.01 * glow) << "after " << kFrames << " frames";
}

// Walls 29 voxels wide: about 5000 occupied voxels, more than one row of slots.
scene::Scene slotGrowthScene() {
    scene::Scene s;
    addInwardBox(s, addMaterial(s, glm::vec3(0.5f), glm::vec3(1.0f)), glm::vec3(0.0f), 0.9f);
    addTopDownCamera(s, 0.0f, glm::radians(60.0f));
    return s;
}

render::RenderSettings slotGrowthSettings(uint32_t slots) {
    render::RenderSettings rs = boxSettings();
    rs.voxelLight.bounceMode = vxgi::BounceMode::Fixed;
    rs.voxelLight.bounces = 2;
    rs.voxelSlots = slots;
    return rs;
}

// A renderer with the default slots, rendered once, and one that starts with a single row.
struct SlotGrowth {
    scene::Scene scene = slotGrowthScene();
    render::Renderer ref{context(), scene, slotGrowthSettings(0)};
    render::Renderer grown{context(), scene, slotGrowthSettings(shader::VOXEL_SLOT_ROW)};
    SlotGrowth() { ref.renderFrame(); }
};

// The grown renderer's radiance and image against the one that had enough slots from the start.
void expectSameAsEnoughSlots(const render::Renderer& ref, const render::Renderer& grown) {
    const Rgba16Volume a = readRgba16(ref.volumes()->radiance), b = readRgba16(grown.volumes()->radiance);
    EXPECT_NEAR(wallMean(b), wallMean(a), 1e-4 * wallMean(a));
    const image::ImageRGBA32F ia = ref.readOutput(), ib = grown.readOutput();
    ASSERT_EQ(ia.rgba.size(), ib.rgba.size());
    for (size_t i = 0; i < ia.rgba.size(); ++i) ASSERT_NEAR(ib.rgba[i], ia.rgba[i], 1e-4f * (1.0f + ia.rgba[i])) << i;
}

TEST_F(Converge, RunningOutOfVoxelSlotsGrowsThemAndRendersTheSameFrame) {
    SlotGrowth g;
    render::Renderer &ref = g.ref, &grown = g.grown;
    grown.renderFrame();
    const uint32_t slots = grown.volumes()->slots;
    std::printf("  %u slots at first, %u after growing (default %u)\n", shader::VOXEL_SLOT_ROW, slots,
                ref.volumes()->slots);
    EXPECT_GT(slots, shader::VOXEL_SLOT_ROW);
    grown.renderFrame();  // a later frame (dynamic path) needs no more
    EXPECT_EQ(grown.volumes()->slots, slots);
    expectSameAsEnoughSlots(ref, grown);
}

// The bench's path: static re-voxelizations in submissions of their own
// (Renderer::revoxelizeStatic), the second of which clears only the listed
// voxels. Claims dropped in the first leave index words no list entry names;
// the renderer must grow the storage then, not carry them into the second.
TEST_F(Converge, RunningOutOfSlotsInAStaticReVoxelizationGrowsThem) {
    SlotGrowth g;
    g.grown.revoxelizeStatic();
    g.grown.revoxelizeStatic();
    g.grown.renderFrame();
    EXPECT_GT(g.grown.volumes()->slots, shader::VOXEL_SLOT_ROW);
    expectSameAsEnoughSlots(g.ref, g.grown);
}

}  // namespace
}  // namespace dvsgi::test
