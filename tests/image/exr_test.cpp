#include "image/image_io.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <functional>
#include <iterator>
#include <random>

namespace fs = std::filesystem;
using namespace dvsgi::image;
using namespace dvsgi::image::test;

namespace {

// Deterministic HDR test content: smooth ramps, tiny and huge values, zeros,
// negatives (a renderer bug must survive the round trip unchanged too).
ImageRGBA32F makeTestImage(uint32_t w, uint32_t h) {
    ImageRGBA32F img = ImageRGBA32F::blank(w, h);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            float* p = img.at(x, y);
            p[0] = float(x) / float(w) + 0.001f * float(y);
            p[1] = std::pow(10.0f, float(int(x + y) % 9) - 4.0f);  // 1e-4 .. 1e4
            p[2] = float(y) * 0.37f - float(x) * 0.11f;
        }
    img.at(0, 0)[0] = 1e4f;
    img.at(w - 1, h - 1)[1] = 3.0e38f;
    if (w >= 4) {
        img.at(1, 0)[1] = 65504.0f * 7.0f;
        img.at(2, 0)[2] = 1e-30f;
        img.at(3, 0)[0] = 0.0f;
    }
    return img;
}

void expectBitExactRgb(const ImageRGBA32F& got, const ImageRGBA32F& want) {
    ASSERT_EQ(got.width, want.width);
    ASSERT_EQ(got.height, want.height);
    ASSERT_EQ(got.rgba.size(), want.rgba.size());
    size_t mismatches = 0;
    for (size_t i = 0; i < want.pixelCount(); ++i) {
        for (int c = 0; c < 3; ++c)
            if (std::bit_cast<uint32_t>(got.rgba[i * 4 + c]) !=
                std::bit_cast<uint32_t>(want.rgba[i * 4 + c]) && mismatches++ < 5)
                ADD_FAILURE() << "pixel " << i << " channel " << c << ": got "
                              << got.rgba[i * 4 + c] << ", want " << want.rgba[i * 4 + c];
        // Frames are written without alpha; reading supplies 1.
        EXPECT_EQ(got.rgba[i * 4 + 3], 1.0f);
    }
    EXPECT_EQ(mismatches, 0u);
}

std::vector<uint8_t> fileBytes(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

void writeBytes(const fs::path& p, const std::vector<uint8_t>& b) {
    std::ofstream f(p, std::ios::binary);
    f.write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
}

// Reading must either succeed or throw IoError naming the path: never crash.
void expectIoErrorOrSuccess(const std::string& path) {
    try {
        (void)readExr(path);
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
    }
}

void expectIoError(const std::string& path, const std::string& fragment,
                   const std::function<void()>& fn) {
    try {
        fn();
        ADD_FAILURE() << "no IoError for " << path;
    } catch (const IoError& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
        EXPECT_NE(msg.find(fragment), std::string::npos) << msg;
    }
}

}  // namespace

TEST(Exr, RoundTripIsBitExact) {
    const fs::path dir = scratchDir();
    // 16-line chunks: 41 rows leaves a partial last chunk.
    for (auto [w, h] : {std::pair{37u, 41u}, {1u, 1u}, {512u, 16u}, {3u, 17u}}) {
        const ImageRGBA32F img = makeTestImage(w, h);
        const std::string path = (dir / ("rt" + std::to_string(w) + "x" + std::to_string(h) + ".exr")).string();
        writeExr(path, img);
        expectBitExactRgb(readExr(path), img);
    }
}

TEST(Exr, RoundTripKeepsNonFiniteAndIncompressibleData) {
    // Random bit patterns do not deflate, so the writer stores chunks raw;
    // the reader must tell raw from compressed chunks. NaN payloads and
    // infinities are preserved because samples are copied bit for bit.
    const fs::path dir = scratchDir();
    ImageRGBA32F img = ImageRGBA32F::blank(64, 40);
    std::mt19937 rng(7);
    for (size_t i = 0; i < img.rgba.size(); ++i)
        if (i % 4 != 3) img.rgba[i] = std::bit_cast<float>(uint32_t(rng()));
    img.at(0, 0)[0] = std::numeric_limits<float>::infinity();
    img.at(0, 0)[1] = -std::numeric_limits<float>::infinity();
    img.at(0, 0)[2] = std::numeric_limits<float>::quiet_NaN();
    const std::string path = (dir / "random.exr").string();
    writeExr(path, img);
    expectBitExactRgb(readExr(path), img);
}

TEST(Exr, WriterCreatesParentDirectories) {
    const fs::path dir = scratchDir();
    const std::string path = (dir / "a" / "b" / "c.exr").string();
    writeExr(path, makeTestImage(4, 4));
    EXPECT_TRUE(fs::exists(path));
}

TEST(Exr, OpenImageIOReadsOurFiles) {
    REQUIRE_PYTHON_OIIO();
    const fs::path dir = scratchDir();
    const ImageRGBA32F img = makeTestImage(23, 35);
    const std::string path = (dir / "ours.exr").string();
    writeExr(path, img);
    const PyResult r = runPython(dir, R"(
import sys, OpenImageIO as oiio
i = oiio.ImageInput.open(sys.argv[1])
if i is None: sys.exit("open failed: " + oiio.geterror())
s = i.spec()
print(s.width, s.height, s.nchannels, ",".join(s.channelnames), s.format,
      s.get_string_attribute("compression"))
px = i.read_image(0, 0, 0, s.nchannels, "float")
if px is None: sys.exit("read failed: " + i.geterror())
for v in px.reshape(-1): print(repr(float(v)))
)", {path});
    ASSERT_EQ(r.status, 0) << r.output;
    std::istringstream in(r.output);
    uint32_t w = 0, h = 0, n = 0;
    std::string names, format, compression;
    in >> w >> h >> n >> names >> format >> compression;
    EXPECT_EQ(w, 23u);
    EXPECT_EQ(h, 35u);
    ASSERT_EQ(n, 3u);
    EXPECT_EQ(names, "R,G,B");  // OpenImageIO reorders B,G,R to R,G,B
    EXPECT_EQ(format, "float");
    EXPECT_EQ(compression, "zip");
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                double v = 0;
                ASSERT_TRUE(in >> v) << "short OpenImageIO output";
                ASSERT_EQ(float(v), img.at(x, y)[c]) << "pixel " << x << "," << y << " channel " << c;
            }
}

TEST(Exr, ReadsFilesWrittenByOpenImageIO) {
    REQUIRE_PYTHON_OIIO();
    const fs::path dir = scratchDir();
    const ImageRGBA32F img = makeTestImage(29, 37);
    const std::string src = (dir / "src.exr").string();
    writeExr(src, img);
    // Re-encode our file with every compression/pixel type the reader claims,
    // with an alpha channel and a data window that does not start at 0,0.
    const PyResult r = runPython(dir, R"(
import sys, numpy as np, OpenImageIO as oiio
src, outdir = sys.argv[1], sys.argv[2]
i = oiio.ImageInput.open(src); s = i.spec()
px = np.asarray(i.read_image(0, 0, 0, 3, "float")).reshape(s.height, s.width, 3)
rgba = np.concatenate([px, np.full((s.height, s.width, 1), 0.5, np.float32)], axis=2)
for comp in ("none", "zips", "zip"):
    for fmt in ("float", "half"):
        for alpha in (False, True):
            data = rgba if alpha else px
            spec = oiio.ImageSpec(s.width, s.height, data.shape[2], fmt)
            spec.attribute("compression", comp)
            if alpha: spec.x, spec.y = 3, -2
            name = "%s/%s_%s_%s.exr" % (outdir, comp, fmt, "rgba" if alpha else "rgb")
            o = oiio.ImageOutput.create(name)
            if not o.open(name, spec): sys.exit(o.geterror())
            if not o.write_image(np.ascontiguousarray(data)): sys.exit(o.geterror())
            o.close()
print("ok")
)", {src, dir.string()});
    ASSERT_EQ(r.status, 0) << r.output;
    for (std::string comp : {"none", "zips", "zip"})
        for (std::string fmt : {"float", "half"})
            for (bool alpha : {false, true}) {
                const std::string name = comp + "_" + fmt + (alpha ? "_rgba" : "_rgb");
                SCOPED_TRACE(name);
                const ImageRGBA32F got = readExr((dir / (name + ".exr")).string());
                ASSERT_EQ(got.width, img.width);
                ASSERT_EQ(got.height, img.height);
                for (uint32_t y = 0; y < img.height; ++y)
                    for (uint32_t x = 0; x < img.width; ++x) {
                        for (int c = 0; c < 3; ++c) {
                            const float want = img.at(x, y)[c], v = got.at(x, y)[c];
                            if (fmt == "float") {
                                ASSERT_EQ(v, want) << x << "," << y << "," << c;
                            } else if (std::abs(want) > 65504.0f) {
                                ASSERT_TRUE(std::isinf(v) || std::abs(v) >= 65504.0f) << v;
                            } else {
                                // half: 11 significant bits; tiny values flush to (sub)normals
                                ASSERT_NEAR(v, want, std::abs(want) * 1e-3 + 1e-7) << x << "," << y << "," << c;
                            }
                        }
                        ASSERT_EQ(got.at(x, y)[3], alpha ? 0.5f : 1.0f);
                    }
            }
}

TEST(Exr, ReadsSharedReferenceLikeOpenImageIO) {
    const fs::path refDir = fs::path(DVSGI_SHARED_DIR) / "reference" / "cornell-box";
    const fs::path emissive = refDir / "cornell-emissive.exr";
    if (!fs::exists(emissive)) GTEST_SKIP() << emissive << " not found";
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(refDir))
        if (e.path().extension() == ".exr") files.push_back(e.path());
    std::sort(files.begin(), files.end());

    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        const ImageRGBA32F img = readExr(file.string());
        EXPECT_EQ(img.width, 512u);
        EXPECT_EQ(img.height, 512u);
        double sumY = 0, sumSq = 0;
        for (size_t i = 0; i < img.pixelCount(); ++i) {
            const float* p = &img.rgba[i * 4];
            sumY += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            sumSq += double(p[0]) * p[0] + double(p[1]) * p[1] + double(p[2]) * p[2];
        }
        const double meanY = sumY / double(img.pixelCount());
        if (file == emissive) {
            EXPECT_NEAR(meanY, 0.276, 0.001);  // README value
        }

        if (!havePythonOiio()) continue;
        const fs::path dir = scratchDir();
        const PyResult r = runPython(dir, R"(
import sys, numpy as np, OpenImageIO as oiio
i = oiio.ImageInput.open(sys.argv[1]); s = i.spec()
a = np.asarray(i.read_image(0, 0, 0, 3, "float"), dtype=np.float64).reshape(s.height, s.width, 3)
print(repr(float((a @ np.array([0.2126, 0.7152, 0.0722])).mean())), repr(float((a ** 2).sum())))
for (x, y) in ((0, 0), (255, 10), (100, 400), (511, 511)):
    print(" ".join(repr(float(v)) for v in a[y, x]))
)", {file.string()});
        ASSERT_EQ(r.status, 0) << r.output;
        std::istringstream in(r.output);
        double oiioMeanY = 0, oiioSumSq = 0;
        in >> oiioMeanY >> oiioSumSq;
        EXPECT_NEAR(meanY, oiioMeanY, 1e-12 * oiioMeanY);
        EXPECT_NEAR(sumSq, oiioSumSq, 1e-9 * oiioSumSq);
        for (auto [x, y] : {std::pair{0u, 0u}, {255u, 10u}, {100u, 400u}, {511u, 511u}})
            for (int c = 0; c < 3; ++c) {
                double v = 0;
                ASSERT_TRUE(in >> v);
                EXPECT_EQ(img.at(x, y)[c], float(v)) << x << "," << y << "," << c;
            }
    }
}

TEST(ExrErrors, UnwritablePath) {
    const fs::path dir = scratchDir();
    writeBytes(dir / "plainfile", {1, 2, 3});
    // A regular file where a directory is needed fails for root as well.
    const std::string nested = (dir / "plainfile" / "sub" / "x.exr").string();
    expectIoError(nested, "cannot create directory", [&] { writeExr(nested, makeTestImage(2, 2)); });
    const std::string inFile = (dir / "plainfile" / "x.exr").string();
    expectIoError(inFile, "", [&] { writeExr(inFile, makeTestImage(2, 2)); });
    const std::string isDir = dir.string();
    expectIoError(isDir, "cannot open for writing", [&] { writeExr(isDir, makeTestImage(2, 2)); });
}

TEST(ExrErrors, EmptyImage) {
    const fs::path dir = scratchDir();
    const std::string path = (dir / "empty.exr").string();
    expectIoError(path, "empty image", [&] { writeExr(path, ImageRGBA32F{}); });
}

TEST(ExrErrors, MissingFile) {
    const fs::path dir = scratchDir();
    const std::string path = (dir / "does-not-exist.exr").string();
    expectIoError(path, "No such file or directory", [&] { (void)readExr(path); });
}

TEST(ExrErrors, EveryTruncationIsReported) {
    const fs::path dir = scratchDir();
    const std::string good = (dir / "good.exr").string();
    writeExr(good, makeTestImage(6, 20));  // two chunks, one partial
    const std::vector<uint8_t> bytes = fileBytes(good);
    const std::string cut = (dir / "cut.exr").string();
    for (size_t len = 0; len < bytes.size(); ++len) {
        writeBytes(cut, {bytes.begin(), bytes.begin() + std::ptrdiff_t(len)});
        try {
            (void)readExr(cut);
            ADD_FAILURE() << "truncated to " << len << " of " << bytes.size() << " bytes was accepted";
        } catch (const IoError& e) {
            ASSERT_EQ(std::string(e.what()).rfind(cut + ": ", 0), 0u) << e.what();
        }
    }
}

TEST(ExrErrors, GarbageFiles) {
    const fs::path dir = scratchDir();
    const std::string path = (dir / "garbage.exr").string();
    writeBytes(path, std::vector<uint8_t>(1000, 0x41));
    expectIoError(path, "not an OpenEXR file", [&] { (void)readExr(path); });

    // Valid magic, then noise: must fail cleanly however the noise parses.
    std::mt19937 rng(3);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<uint8_t> b = {0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0};
        const size_t n = rng() % 600;
        for (size_t i = 0; i < n; ++i) b.push_back(uint8_t(rng()));
        writeBytes(path, b);
        expectIoErrorOrSuccess(path);
    }
}

TEST(ExrErrors, CorruptedBytesNeverCrash) {
    const fs::path dir = scratchDir();
    const std::string good = (dir / "good.exr").string();
    writeExr(good, makeTestImage(24, 40));
    const std::vector<uint8_t> bytes = fileBytes(good);
    const std::string path = (dir / "corrupt.exr").string();
    std::mt19937 rng(11);
    for (int trial = 0; trial < 500; ++trial) {
        std::vector<uint8_t> b = bytes;
        const int flips = 1 + int(rng() % 4);
        for (int f = 0; f < flips; ++f) b[rng() % b.size()] = uint8_t(rng());
        writeBytes(path, b);
        expectIoErrorOrSuccess(path);
    }
}

TEST(ExrErrors, UnsupportedFeaturesAreNamed) {
    const fs::path dir = scratchDir();
    const std::string good = (dir / "good.exr").string();
    writeExr(good, makeTestImage(8, 8));
    std::vector<uint8_t> bytes = fileBytes(good);

    const std::string tiled = (dir / "tiled.exr").string();
    std::vector<uint8_t> b = bytes;
    b[5] |= 0x02;  // version flag bit 9: tiled
    writeBytes(tiled, b);
    expectIoError(tiled, "tiled", [&] { (void)readExr(tiled); });

    const std::string version = (dir / "v3.exr").string();
    b = bytes;
    b[4] = 3;
    writeBytes(version, b);
    expectIoError(version, "version 3", [&] { (void)readExr(version); });

    // The compression attribute's value byte follows its name, type and size.
    const std::string piz = (dir / "piz.exr").string();
    b = bytes;
    const char key[] = "compression\0compression";
    auto it = std::search(b.begin(), b.end(), key, key + sizeof key);
    ASSERT_NE(it, b.end());
    *(it + std::ptrdiff_t(sizeof key) + 4) = 4;
    writeBytes(piz, b);
    expectIoError(piz, "unsupported compression PIZ", [&] { (void)readExr(piz); });
}
