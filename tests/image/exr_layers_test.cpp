// Multi-layer (AOV) EXR files and the atomic replacement of every EXR write.
#include "image/image_io.h"

#include "aov_sample.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace dvsgi::image;
using namespace dvsgi::image::test;

namespace {

// The layers as readExrLayers returns them: sorted by name.
const std::vector<std::pair<std::string, std::vector<std::string>>> kSortedLayers = {
    {"albedo", {"R", "G", "B"}}, {"ao", {"Y"}},  {"depth", {"Z"}},
    {"direct", {"R", "G", "B"}}, {"indirect", {"R", "G", "B"}},
    {"normal", {"X", "Y", "Z"}}, {"specular", {"R", "G", "B"}},
};

void expectLayersMatch(const ExrLayerFile& got, const std::vector<ExrLayer>& written, PixelType type) {
    ASSERT_EQ(got.width, kAovWidth);
    ASSERT_EQ(got.height, kAovHeight);
    ASSERT_EQ(got.layers.size(), kSortedLayers.size());
    ASSERT_EQ(got.types.size(), got.layers.size());
    for (size_t i = 0; i < got.layers.size(); ++i) {
        const ExrLayer& layer = got.layers[i];
        SCOPED_TRACE(layer.name);
        EXPECT_EQ(layer.name, kSortedLayers[i].first);
        EXPECT_EQ(layer.channels, kSortedLayers[i].second);
        EXPECT_EQ(got.types[i], type);
        const ExrLayer* source = nullptr;
        for (const ExrLayer& w : written)
            if (w.name == layer.name) source = &w;
        ASSERT_NE(source, nullptr);
        ASSERT_EQ(layer.pixels.size(), source->pixels.size());
        size_t inexact = 0;
        for (size_t k = 0; k < layer.pixels.size(); ++k) {
            const float want = source->pixels[k], v = layer.pixels[k];
            if (type == PixelType::Float) {
                ASSERT_EQ(v, want) << k;
            } else {
                ASSERT_LE(std::abs(v - want), std::abs(want) * 0x1p-11f) << k;
                inexact += v != want;
            }
        }
        // k/7 is rarely a half: equality everywhere would mean no half was stored.
        if (type == PixelType::Half) {
            EXPECT_GT(inexact, 0u);
        }
    }
}

std::vector<fs::path> filesIn(const fs::path& dir) {
    std::vector<fs::path> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace

TEST(ExrLayers, SevenLayersRoundTripExactlyAsFloat) {
    const fs::path dir = scratchDir();
    const std::string path = (dir / "aov.exr").string();
    const std::vector<ExrLayer> layers = makeAovLayers();
    writeExrLayers(path, kAovWidth, kAovHeight, layers, PixelType::Float);
    expectLayersMatch(readExrLayers(path), layers, PixelType::Float);
}

TEST(ExrLayers, SevenLayersRoundTripWithinHalfPrecision) {
    const fs::path dir = scratchDir();
    const std::string path = (dir / "aov.exr").string();
    const std::vector<ExrLayer> layers = makeAovLayers();
    writeExrLayers(path, kAovWidth, kAovHeight, layers, PixelType::Half);
    expectLayersMatch(readExrLayers(path), layers, PixelType::Half);
}

TEST(ExrLayers, UnnamedLayerIsTheImageReadExrSees) {
    const fs::path dir = scratchDir();
    const std::string path = (dir / "beauty.exr").string();
    std::vector<ExrLayer> layers = makeAovLayers(4, 3);
    layers[0].name = "";  // "direct" becomes plain R, G, B
    writeExrLayers(path, 4, 3, layers, PixelType::Float);

    const ImageRGBA32F img = readExr(path);
    ASSERT_EQ(img.width, 4u);
    ASSERT_EQ(img.height, 3u);
    for (uint32_t y = 0; y < 3; ++y)
        for (uint32_t x = 0; x < 4; ++x)
            for (int c = 0; c < 3; ++c) EXPECT_EQ(img.at(x, y)[c], aovValue(0, c, x, y));

    const ExrLayerFile file = readExrLayers(path);
    ASSERT_EQ(file.layers.size(), 7u);
    EXPECT_EQ(file.layers[0].name, "");
    EXPECT_EQ(file.layers[0].channels, (std::vector<std::string>{"R", "G", "B"}));
    EXPECT_EQ(file.layers[0].pixels, layers[0].pixels);
}

TEST(ExrLayers, ReadsAnRgbFileAsTheUnnamedLayer) {
    const fs::path dir = scratchDir();
    const std::string path = (dir / "rgba.exr").string();
    ImageRGBA32F img = ImageRGBA32F::blank(5, 2);
    for (size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = float(i) * 0.5f;
    writeExr(path, img, ExrOptions{PixelType::Half, /*alpha=*/true});
    const ExrLayerFile file = readExrLayers(path);
    ASSERT_EQ(file.layers.size(), 1u);
    EXPECT_EQ(file.layers[0].name, "");
    EXPECT_EQ(file.layers[0].channels, (std::vector<std::string>{"R", "G", "B", "A"}));
    EXPECT_EQ(file.types, std::vector<PixelType>{PixelType::Half});
    EXPECT_EQ(file.layers[0].pixels, img.rgba);  // multiples of 0.5 up to 19.5 are exact halves
}

TEST(ExrLayers, InconsistentLayersAreRejectedWithoutWritingAFile) {
    const fs::path dir = scratchDir();
    const std::string path = (dir / "bad.exr").string();
    const uint32_t w = 4, h = 3;
    auto layer = [&](std::string name, std::vector<std::string> channels) {
        const size_t n = channels.size();
        return ExrLayer{std::move(name), std::move(channels), std::vector<float>(w * h * n, 1.0f)};
    };
    auto write = [&](std::vector<ExrLayer> layers) {
        return [&path, layers] { writeExrLayers(path, w, h, layers, PixelType::Float); };
    };
    expectIoError(path, "no layers", write({}));
    expectIoError(path, "has 2 channels (1, 3 or 4 expected)", write({layer("uv", {"U", "V"})}));
    expectIoError(path, "channel 'ao.Y' is given twice", write({layer("ao", {"Y"}), layer("ao", {"Y"})}));
    expectIoError(path, "channel name 'a.b'", write({layer("x", {"a.b"})}));
    expectIoError(path, "channel name ''", write({layer("x", {""})}));
    ExrLayer shortLayer = layer("direct", {"R", "G", "B"});
    shortLayer.pixels.pop_back();
    expectIoError(path, "layer 'direct' has 35 floats, expected 36", write({shortLayer}));
    expectIoError(path, "empty image (0x3)",
                  [&] { writeExrLayers(path, 0, 3, {layer("ao", {"Y"})}, PixelType::Half); });
    EXPECT_TRUE(filesIn(dir).empty());
}

TEST(ExrAtomic, ReplacingAFileLeavesNoTemporaryFiles) {
    const fs::path dir = scratchDir();
    const std::string path = (dir / "frame.exr").string();
    ImageRGBA32F first = ImageRGBA32F::blank(8, 8), second = ImageRGBA32F::blank(8, 8);
    first.rgba[0] = 1.0f;
    second.rgba[0] = 2.0f;
    writeExr(path, first);
    writeExr(path, second);
    EXPECT_EQ(readExr(path).rgba[0], 2.0f);
    writeExrLayers(path, kAovWidth, kAovHeight, makeAovLayers(), PixelType::Half);
    EXPECT_EQ(readExrLayers(path).layers.size(), 7u);
    EXPECT_EQ(filesIn(dir), std::vector<fs::path>{"frame.exr"});
}

// A write that fails half way (here: the file size limit, as a full disk
// would) must report the file and leave the previous file untouched.
TEST(ExrAtomic, FailedWriteKeepsThePreviousFile) {
    const fs::path dir = scratchDir();
    const std::string path = (dir / "frame.exr").string();
    ImageRGBA32F old = ImageRGBA32F::blank(16, 16);
    for (size_t i = 0; i < old.rgba.size(); ++i) old.rgba[i] = float(i);
    writeExr(path, old);
    const std::vector<uint8_t> oldBytes = fileBytes(path);

    // Random floats do not compress: this needs megabytes, the limit allows 64 KiB.
    ImageRGBA32F big = ImageRGBA32F::blank(512, 512);
    uint32_t s = 1;
    for (float& v : big.rgba) v = float((s = s * 1664525u + 1013904223u) >> 8);

    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        // In the child only: the limit would break every later test.
        signal(SIGXFSZ, SIG_IGN);  // turns the signal into EFBIG from write()
        const rlimit limit{64 * 1024, 64 * 1024};
        setrlimit(RLIMIT_FSIZE, &limit);
        int code = 3;
        try {
            writeExr(path, big);
            code = 1;  // the write should not have fitted
        } catch (const IoError& e) {
            const std::string msg = e.what();
            code = msg.rfind(path + ": ", 0) == 0 && msg.find("File too large") != std::string::npos ? 0 : 2;
            if (code) std::fprintf(stderr, "unexpected message: %s\n", msg.c_str());
        }
        _exit(code);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status)) << "child died with status " << status;
    EXPECT_EQ(WEXITSTATUS(status), 0) << "1: no error, 2: wrong message, 3: other exception";
    EXPECT_EQ(fileBytes(path), oldBytes);
    EXPECT_EQ(filesIn(dir), std::vector<fs::path>{"frame.exr"});
}

TEST(ExrAtomic, PngPreviewIsReplacedAtomicallyToo) {
    const fs::path dir = scratchDir();
    const std::string path = (dir / "preview.png").string();
    writePng(path, ImageRGBA32F::blank(4, 4), 0.0f);
    writePng(path, ImageRGBA32F::blank(8, 8), 0.0f);
    EXPECT_EQ(filesIn(dir), std::vector<fs::path>{"preview.png"});
    EXPECT_GT(fileBytes(path).size(), 8u);
}
