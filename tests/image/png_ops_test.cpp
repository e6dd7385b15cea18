#include "image/image_io.h"

#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace fs = std::filesystem;
using namespace dvsgi::image;
using namespace dvsgi::image::test;

namespace {

struct Png8 {
    int w = 0, h = 0;
    std::vector<uint8_t> rgb;
};

Png8 loadPng(const std::string& path) {
    Png8 out;
    int comp = 0;
    unsigned char* p = stbi_load(path.c_str(), &out.w, &out.h, &comp, 3);
    if (!p) throw std::runtime_error("stbi_load failed for " + path);
    out.rgb.assign(p, p + size_t(out.w) * out.h * 3);
    stbi_image_free(p);
    return out;
}

ImageRGBA32F solid(uint32_t w, uint32_t h, float r, float g, float b) {
    ImageRGBA32F img = ImageRGBA32F::blank(w, h);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            img.at(x, y)[0] = r;
            img.at(x, y)[1] = g;
            img.at(x, y)[2] = b;
        }
    return img;
}

}  // namespace

// ---- PNG preview ----------------------------------------------------------

TEST(Png, SrgbEncoding) {
    EXPECT_EQ(encodeSrgb8(0.3183107f), 153);  // 1/pi, the reference PNGs' anchor
    EXPECT_EQ(encodeSrgb8(0.0f), 0);
    EXPECT_EQ(encodeSrgb8(1.0f), 255);
    EXPECT_EQ(encodeSrgb8(7.5f), 255);
    EXPECT_EQ(encodeSrgb8(-3.0f), 0);
    EXPECT_EQ(encodeSrgb8(std::numeric_limits<float>::quiet_NaN()), 0);
    EXPECT_EQ(encodeSrgb8(std::numeric_limits<float>::infinity()), 255);
    EXPECT_EQ(encodeSrgb8(-std::numeric_limits<float>::infinity()), 0);
    EXPECT_EQ(encodeSrgb8(0.002f), 7);   // linear segment: 12.92 * 0.002 * 255 = 6.59
    EXPECT_EQ(encodeSrgb8(0.5f), 188);   // 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354
    EXPECT_EQ(encodeSrgb8(0.18f), 118);  // mid grey
}

TEST(Png, WritesPreviewWithExposure) {
    const fs::path dir = scratchDir();
    ImageRGBA32F img = solid(5, 3, 0.3183107f, 0.3183107f / 2.0f, 0.25f);
    img.at(4, 2)[0] = std::numeric_limits<float>::quiet_NaN();
    img.at(0, 2)[1] = 50.0f;

    const std::string p0 = (dir / "sub" / "ev0.png").string();  // parent is created
    writePng(p0, img, 0.0f);
    Png8 a = loadPng(p0);
    ASSERT_EQ(a.w, 5);
    ASSERT_EQ(a.h, 3);
    EXPECT_EQ(a.rgb[0], 153);
    EXPECT_EQ(a.rgb[1], encodeSrgb8(0.3183107f / 2.0f));
    EXPECT_EQ(a.rgb[2], encodeSrgb8(0.25f));
    EXPECT_EQ(a.rgb[(2 * 5 + 4) * 3 + 0], 0);    // NaN
    EXPECT_EQ(a.rgb[(2 * 5 + 0) * 3 + 1], 255);  // clipped, row 2 is the bottom row

    // +1 EV doubles the radiance before encoding.
    const std::string p1 = (dir / "ev1.png").string();
    writePng(p1, img, 1.0f);
    Png8 b = loadPng(p1);
    EXPECT_EQ(b.rgb[0], encodeSrgb8(2.0f * 0.3183107f));
    EXPECT_EQ(b.rgb[1], 153);
    EXPECT_EQ(b.rgb[2], encodeSrgb8(0.5f));

    const std::string pm = (dir / "evm2.png").string();
    writePng(pm, solid(1, 1, 4.0f * 0.3183107f, 0, 0), -2.0f);
    EXPECT_EQ(loadPng(pm).rgb[0], 153);
}

TEST(Png, MatchesReferencePreview) {
    const fs::path refDir = fs::path(DVSGI_SHARED_DIR) / "reference" / "cornell-box";
    const fs::path exr = refDir / "cornell-emissive.exr", png = refDir / "cornell-emissive.png";
    REQUIRE_FILE(exr);
    REQUIRE_FILE(png);
    const fs::path dir = scratchDir();
    const std::string ours = (dir / "ours.png").string();
    writePng(ours, readExr(exr.string()), 0.0f);
    const Png8 a = loadPng(ours), b = loadPng(png.string());
    ASSERT_EQ(a.w, b.w);
    ASSERT_EQ(a.h, b.h);
    // Same curve, same double-precision maths: every byte is identical.
    size_t off = 0;
    for (size_t i = 0; i < a.rgb.size(); ++i) {
        ASSERT_LE(std::abs(int(a.rgb[i]) - int(b.rgb[i])), 1) << "byte " << i;
        off += a.rgb[i] != b.rgb[i];
    }
    EXPECT_EQ(off, 0u) << off << " of " << a.rgb.size() << " bytes differ";
}

TEST(Png, Errors) {
    const fs::path dir = scratchDir();
    std::ofstream(dir / "plainfile") << "x";
    const std::string bad = (dir / "plainfile" / "x.png").string();
    try {
        writePng(bad, solid(2, 2, 1, 1, 1), 0.0f);
        ADD_FAILURE() << "no IoError";
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(bad + ": ", 0), 0u) << e.what();
    }
    EXPECT_THROW(writePng((dir / "e.png").string(), ImageRGBA32F{}, 0.0f), IoError);
}

// ---- downsampling -----------------------------------------------------------

TEST(Downsample, AveragesBlocks) {
    ImageRGBA32F img = ImageRGBA32F::blank(4, 2);
    for (uint32_t y = 0; y < 2; ++y)
        for (uint32_t x = 0; x < 4; ++x)
            for (int c = 0; c < 4; ++c) img.at(x, y)[c] = float(x + 10 * y + 100 * c);
    const ImageRGBA32F d = downsampleBox(img, 2);
    ASSERT_EQ(d.width, 2u);
    ASSERT_EQ(d.height, 1u);
    for (int c = 0; c < 4; ++c) {
        EXPECT_FLOAT_EQ(d.at(0, 0)[c], (0 + 1 + 10 + 11) / 4.0f + 100 * c);
        EXPECT_FLOAT_EQ(d.at(1, 0)[c], (2 + 3 + 12 + 13) / 4.0f + 100 * c);
    }
    const ImageRGBA32F same = downsampleBox(img, 1);
    EXPECT_EQ(same.rgba, img.rgba);

    // Energy is preserved: the mean is unchanged by pixel-area averaging.
    ImageRGBA32F big = ImageRGBA32F::blank(12, 9);
    for (size_t i = 0; i < big.rgba.size(); ++i) big.rgba[i] = float((i * 37) % 101) * 0.1f;
    const ImageRGBA32F small = downsampleBox(big, 3);
    double sBig = 0, sSmall = 0;
    for (float v : big.rgba) sBig += v;
    for (float v : small.rgba) sSmall += v;
    EXPECT_NEAR(sSmall * 9.0, sBig, 1e-3);
}

TEST(Downsample, RejectsBadFactors) {
    const ImageRGBA32F img = ImageRGBA32F::blank(6, 4);
    EXPECT_THROW(downsampleBox(img, 0), std::invalid_argument);
    EXPECT_THROW(downsampleBox(img, 3), std::invalid_argument);  // 4 rows
    EXPECT_THROW(downsampleBox(img, 4), std::invalid_argument);  // 6 columns
    EXPECT_NO_THROW(downsampleBox(img, 2));
}

// ---- metrics vs the Python tools ------------------------------------------------

namespace {

// A reference with flat regions and hard edges (so the mask has work to do) and
// a candidate with noise, a bias and a non-finite pixel.
void makePair(ImageRGBA32F& cand, ImageRGBA32F& ref) {
    const uint32_t w = 40, h = 30;
    ref = ImageRGBA32F::blank(w, h);
    cand = ImageRGBA32F::blank(w, h);
    uint32_t seed = 12345;
    auto rnd = [&] {
        seed = seed * 1664525u + 1013904223u;
        return float(seed >> 8) / float(1u << 24);
    };
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            float* r = ref.at(x, y);
            const bool bright = x > 25 && y < 12;
            const float base = bright ? 5.0f : (x < 10 ? 0.05f : 0.4f + 0.01f * float(y));
            r[0] = base;
            r[1] = base * 0.8f;
            r[2] = (x + y) % 17 == 0 ? 0.0f : base * 0.5f;
            float* c = cand.at(x, y);
            for (int k = 0; k < 3; ++k) c[k] = r[k] * (1.05f + 0.3f * (rnd() - 0.5f)) + 0.002f;
        }
    cand.at(7, 7)[1] = std::numeric_limits<float>::quiet_NaN();
}

}  // namespace

TEST(Metrics, MatchCompareTool) {
    REQUIRE_PYTHON_OIIO();
    const fs::path tool = fs::path(DVSGI_SHARED_DIR) / "tools" / "compare.py";
    REQUIRE_FILE(tool);
    const fs::path dir = scratchDir();
    ImageRGBA32F cand, ref;
    makePair(cand, ref);
    writeExr((dir / "cand.exr").string(), cand);
    writeExr((dir / "ref.exr").string(), ref);
    const PyResult r = runCommand(
        dir, std::string(kPython) + " " + shellQuote(tool.string()) + " " +
                 shellQuote((dir / "cand.exr").string()) + " " +
                 shellQuote((dir / "ref.exr").string()) + " --json " +
                 shellQuote((dir / "m.json").string()));
    ASSERT_EQ(r.status, 0) << r.output;
    const auto m = nlohmann::json::parse(readText(dir / "m.json"));

    const ImageStats s = compareImages(cand, ref);
    EXPECT_NEAR(s.relRmse, m["rel_rmse"].get<double>(), 1e-9);
    EXPECT_NEAR(s.meanLumRatio, m["mean_lum_ratio"].get<double>(), 1e-9);
    EXPECT_NEAR(s.relRmsePixel, m["rel_rmse_pixel"].get<double>(), 1e-9);
    EXPECT_NEAR(s.fracWithinTol, m["frac_within_tol"].get<double>(), 1e-12);
    EXPECT_GT(s.relRmse, 0.01);  // the test pair really differs

    const ImageStats self = compareImages(ref, ref);
    EXPECT_EQ(self.relRmse, 0.0);
    EXPECT_EQ(self.meanLumRatio, 1.0);
    EXPECT_EQ(self.fracWithinTol, 1.0);
}

TEST(Metrics, MatchMaskedRmseTool) {
    REQUIRE_PYTHON_OIIO();
    const fs::path tool = fs::path(DVSGI_SHARED_DIR) / "tools" / "masked_rmse.py";
    REQUIRE_FILE(tool);
    const fs::path dir = scratchDir();
    ImageRGBA32F cand, ref;
    makePair(cand, ref);
    cand.at(7, 7)[1] = 0.3f;  // the tool propagates NaN; keep the number meaningful
    writeExr((dir / "cand.exr").string(), cand);
    writeExr((dir / "ref.exr").string(), ref);
    const PyResult r = runCommand(dir, std::string(kPython) + " " + shellQuote(tool.string()) +
                                           " " + shellQuote((dir / "cand.exr").string()) + " " +
                                           shellQuote((dir / "ref.exr").string()));
    ASSERT_EQ(r.status, 0) << r.output;
    std::istringstream in(r.output);
    double rel = 0, lumRatio = 0, kept = 0;
    ASSERT_TRUE(in >> rel >> lumRatio >> kept) << r.output;

    double ours = 0;
    const double relOurs = maskedRelRmse(cand, ref, &ours);
    // The tool prints 4 / 4 / 3 decimals.
    EXPECT_NEAR(relOurs, rel, 0.5e-4 + 1e-9);
    EXPECT_NEAR(ours, kept, 0.5e-3 + 1e-9);
    EXPECT_GT(ours, 0.3);
    EXPECT_LT(ours, 0.95);
    EXPECT_NEAR(compareImages(cand, ref).meanLumRatio, lumRatio, 0.5e-4 + 1e-9);
}

TEST(Metrics, MaskedEdgeCases) {
    ImageRGBA32F ref = solid(8, 8, 1, 1, 1), cand = solid(8, 8, 1.1f, 1.1f, 1.1f);
    double kept = 0;
    EXPECT_NEAR(maskedRelRmse(cand, ref, &kept), 0.1, 1e-6);
    EXPECT_EQ(kept, 1.0);
    // A checkerboard is all edges: nothing kept, NaN like numpy's empty mean.
    for (uint32_t y = 0; y < 8; ++y)
        for (uint32_t x = 0; x < 8; ++x)
            for (int c = 0; c < 3; ++c) ref.at(x, y)[c] = (x + y) % 2 ? 1.0f : 0.0f;
    EXPECT_TRUE(std::isnan(maskedRelRmse(cand, ref, &kept)));
    EXPECT_EQ(kept, 0.0);
    EXPECT_THROW(maskedRelRmse(cand, solid(4, 8, 1, 1, 1)), std::invalid_argument);
    EXPECT_THROW(compareImages(cand, solid(8, 4, 1, 1, 1)), std::invalid_argument);
}
