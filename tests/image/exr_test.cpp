#include "image/image_io.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
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

// Reading must either succeed or throw IoError naming the path: never crash.
void expectIoErrorOrSuccess(const std::string& path) {
    try {
        (void)readExr(path);
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
    }
}

}  // namespace

TEST(Exr, RoundTripIsBitExact) {
    const fs::path dir = scratchDir();
    // ZIP stores 16 lines per chunk: 41 rows leaves a partial last chunk.
    for (auto [w, h] : {std::pair{37u, 41u}, {1u, 1u}, {512u, 16u}, {3u, 17u}}) {
        const ImageRGBA32F img = makeTestImage(w, h);
        const std::string path = (dir / ("rt" + std::to_string(w) + "x" + std::to_string(h) + ".exr")).string();
        writeExr(path, img);
        expectBitExactRgb(readExr(path), img);
    }
}

TEST(Exr, RoundTripKeepsNonFiniteAndIncompressibleData) {
    // Random bit patterns do not deflate, so ZIP stores the chunks raw (as
    // the format allows); NaN payloads and infinities must survive bit for bit.
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

TEST(Exr, HalfAndAlphaRoundTrip) {
    const fs::path dir = scratchDir();
    ImageRGBA32F img = makeTestImage(19, 21);
    for (size_t i = 0; i < img.pixelCount(); ++i) img.rgba[i * 4 + 3] = float(i % 7) / 6.0f;
    for (PixelType type : {PixelType::Float, PixelType::Half}) {
        const std::string path = (dir / (type == PixelType::Half ? "half.exr" : "float.exr")).string();
        writeExr(path, img, ExrOptions{type, /*alpha=*/true});
        const ImageRGBA32F got = readExr(path);
        ASSERT_EQ(got.width, img.width);
        ASSERT_EQ(got.height, img.height);
        for (size_t i = 0; i < img.rgba.size(); ++i) {
            const float want = img.rgba[i], v = got.rgba[i];
            if (type == PixelType::Float) {
                ASSERT_EQ(v, want) << i;
            } else if (std::abs(want) > 65504.0f) {
                ASSERT_TRUE(std::isinf(v)) << i << ": " << v;  // beyond half's range
            } else {
                // 11 significant bits: relative error <= 2^-11 for normals,
                // absolute 2^-25 below the smallest normal half (2^-14).
                ASSERT_NEAR(v, want, std::abs(want) * 0x1p-11f + 0x1p-25f) << i;
            }
        }
    }
}

TEST(Exr, OpenImageIOReadsOurFiles) {
    REQUIRE_PYTHON_OIIO();
    const fs::path dir = scratchDir();
    const ImageRGBA32F img = makeTestImage(23, 35);
    for (PixelType type : {PixelType::Float, PixelType::Half}) {
        const bool half = type == PixelType::Half;
        SCOPED_TRACE(half ? "half" : "float");
        const std::string path = (dir / (half ? "half.exr" : "float.exr")).string();
        writeExr(path, img, ExrOptions{type});
        const PyResult r = runPython(dir, R"(
import sys, numpy as np, OpenImageIO as oiio
i = oiio.ImageInput.open(sys.argv[1])
if i is None: sys.exit("open failed: " + oiio.geterror())
s = i.spec()
print(s.width, s.height, s.nchannels, ",".join(s.channelnames), s.format,
      s.get_string_attribute("compression"))
px = i.read_image(0, 0, 0, s.nchannels, "float")
if px is None: sys.exit("read failed: " + i.geterror())
# Bit patterns: exact, and inf (a half overflow) stays parseable.
for v in np.asarray(px, dtype=np.float32).reshape(-1).view(np.uint32): print(int(v))
)", {path});
        ASSERT_EQ(r.status, 0) << r.output;
        std::istringstream in(r.output);
        uint32_t w = 0, h = 0, n = 0;
        std::string names, format, compression;
        in >> w >> h >> n >> names >> format >> compression;
        EXPECT_EQ(w, 23u);
        EXPECT_EQ(h, 35u);
        ASSERT_EQ(n, 3u);
        EXPECT_EQ(names, "R,G,B");
        EXPECT_EQ(format, half ? "half" : "float");
        EXPECT_EQ(compression, "zip");
        // What we read back ourselves must be what OpenImageIO sees.
        const ImageRGBA32F ours = readExr(path);
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c) {
                    uint32_t bits = 0;
                    ASSERT_TRUE(in >> bits) << "short OpenImageIO output";
                    ASSERT_EQ(bits, std::bit_cast<uint32_t>(ours.at(x, y)[c]))
                        << "pixel " << x << "," << y << " channel " << c;
                    if (!half) {
                        ASSERT_EQ(bits, std::bit_cast<uint32_t>(img.at(x, y)[c]));
                    }
                }
    }
}

TEST(Exr, ReadsFilesWrittenByOpenImageIO) {
    REQUIRE_PYTHON_OIIO();
    const fs::path dir = scratchDir();
    const ImageRGBA32F img = makeTestImage(29, 37);
    const std::string src = (dir / "src.exr").string();
    writeExr(src, img);
    // Re-encode our file with the lossless compressions and both pixel types,
    // with an alpha channel and a data window that does not start at 0,0.
    const PyResult r = runPython(dir, R"(
import sys, numpy as np, OpenImageIO as oiio
src, outdir = sys.argv[1], sys.argv[2]
i = oiio.ImageInput.open(src); s = i.spec()
px = np.asarray(i.read_image(0, 0, 0, 3, "float")).reshape(s.height, s.width, 3)
rgba = np.concatenate([px, np.full((s.height, s.width, 1), 0.5, np.float32)], axis=2)
for comp in ("none", "rle", "zips", "zip", "piz"):
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
    for (std::string comp : {"none", "rle", "zips", "zip", "piz"})
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
    REQUIRE_PYTHON_OIIO();
    const fs::path refDir = fs::path(DVSGI_SHARED_DIR) / "reference" / "cornell-box";
    const fs::path emissive = refDir / "cornell-emissive.exr";
    REQUIRE_FILE(emissive);
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(refDir))
        if (e.path().extension() == ".exr") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    ASSERT_EQ(files.size(), 3u);

    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        const ImageRGBA32F img = readExr(file.string());
        ASSERT_EQ(img.width, 512u);
        ASSERT_EQ(img.height, 512u);
        if (file == emissive) {
            double sumY = 0;
            for (size_t i = 0; i < img.pixelCount(); ++i) {
                const float* p = &img.rgba[i * 4];
                sumY += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            }
            EXPECT_NEAR(sumY / double(img.pixelCount()), 0.276, 0.001);  // README value
        }
        // Every sample, bit for bit, as OpenImageIO reads it.
        const fs::path dir = scratchDir();
        const fs::path raw = dir / "oiio.f32";
        const PyResult r = runPython(dir, R"(
import sys, numpy as np, OpenImageIO as oiio
i = oiio.ImageInput.open(sys.argv[1]); s = i.spec()
a = np.asarray(i.read_image(0, 0, 0, 3, "float"), dtype=np.float32).reshape(s.height, s.width, 3)
a.tofile(sys.argv[2])
)", {file.string(), raw.string()});
        ASSERT_EQ(r.status, 0) << r.output;
        const std::vector<uint8_t> bytes = fileBytes(raw);
        ASSERT_EQ(bytes.size(), img.pixelCount() * 3 * sizeof(float));
        size_t mismatches = 0;
        for (size_t i = 0; i < img.pixelCount(); ++i)
            for (int c = 0; c < 3; ++c) {
                uint32_t want = 0;
                std::memcpy(&want, bytes.data() + (i * 3 + c) * sizeof(float), sizeof want);
                if (std::bit_cast<uint32_t>(img.rgba[i * 4 + c]) != want) ++mismatches;
            }
        EXPECT_EQ(mismatches, 0u);
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
    // Nothing half-written is left behind.
    std::vector<fs::path> left;
    for (const auto& e : fs::directory_iterator(dir)) left.push_back(e.path().filename());
    EXPECT_EQ(left, std::vector<fs::path>{"plainfile"});
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

TEST(ExrErrors, BadVersionAndFlagsAreNamed) {
    const fs::path dir = scratchDir();
    const std::string good = (dir / "good.exr").string();
    writeExr(good, makeTestImage(8, 8));
    const std::vector<uint8_t> bytes = fileBytes(good);

    // A scanline file claiming to be tiled has no tile description.
    const std::string tiled = (dir / "tiled.exr").string();
    std::vector<uint8_t> b = bytes;
    b[5] |= 0x02;  // version flag bit 9: tiled
    writeBytes(tiled, b);
    expectIoError(tiled, "", [&] { (void)readExr(tiled); });

    const std::string version = (dir / "v3.exr").string();
    b = bytes;
    b[4] = 3;
    writeBytes(version, b);
    expectIoError(version, "version 3", [&] { (void)readExr(version); });

    const std::string deep = (dir / "deep.exr").string();
    b = bytes;
    b[5] |= 0x08;  // version flag bit 11: deep data
    writeBytes(deep, b);
    expectIoError(deep, "deep", [&] { (void)readExr(deep); });
}

TEST(ExrErrors, HugeDataWindowIsRejectedBeforeAllocating) {
    const fs::path dir = scratchDir();
    const std::string good = (dir / "good.exr").string();
    writeExr(good, makeTestImage(8, 8));
    std::vector<uint8_t> bytes = fileBytes(good);
    // The dataWindow attribute: name, type, int32 size 16, then xMin yMin xMax yMax.
    const char key[] = "dataWindow\0box2i";
    auto it = std::search(bytes.begin(), bytes.end(), key, key + sizeof key);
    ASSERT_NE(it, bytes.end());
    const size_t value = size_t(it - bytes.begin()) + sizeof key + 4;
    auto putI32 = [&](size_t at, int32_t v) { std::memcpy(bytes.data() + at, &v, 4); };
    const std::string path = (dir / "huge.exr").string();

    // 10^6 x 10^6 pixels: 16 TB of RGBA floats if anyone believed it.
    putI32(value + 8, 999999);
    putI32(value + 12, 999999);
    writeBytes(path, bytes);
    expectIoError(path, "data window 1000000x1000000 is too large", [&] { (void)readExr(path); });
    expectIoError(path, "data window 1000000x1000000 is too large", [&] { (void)readExrLayers(path); });

    // An inverted window is as corrupt.
    putI32(value + 8, -5);
    writeBytes(path, bytes);
    expectIoError(path, "empty data window", [&] { (void)readExr(path); });
}

TEST(ExrErrors, MissingColourChannelsAreNamed) {
    const fs::path dir = scratchDir();
    const std::string path = (dir / "depth.exr").string();
    writeExrLayers(path, 4, 3, {ExrLayer{"depth", {"Z"}, std::vector<float>(12, 2.0f)}}, PixelType::Float);
    expectIoError(path, "no 'R' channel", [&] { (void)readExr(path); });
}
