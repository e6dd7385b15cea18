// Inputs that crashed, stalled or blew up a fuzz_exr run (fuzz/fuzz_exr.cpp),
// kept in tests/image/regressions once fixed: an EXR is not a scene, so they
// live here rather than in the scene corpus (docs/RELIABILITY.md).
#include "image/image_io.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

namespace fs = std::filesystem;
using namespace dvsgi::image;
using namespace dvsgi::image::test;

namespace {

std::vector<fs::path> regressionInputs() {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(DVSGI_EXR_REGRESSIONS_DIR))
        if (e.path().extension() == ".exr") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST(ExrFuzzRegressions, EveryInputIsOneIoErrorLine) {
    ASSERT_TRUE(fs::is_directory(DVSGI_EXR_REGRESSIONS_DIR)) << DVSGI_EXR_REGRESSIONS_DIR << " is missing";
    const std::vector<fs::path> inputs = regressionInputs();
    ASSERT_FALSE(inputs.empty()) << "no .exr in " << DVSGI_EXR_REGRESSIONS_DIR;
    for (const fs::path& p : inputs) {
        SCOPED_TRACE(p.string());
        const std::function<void()> readers[] = {[&] { (void)readExr(p.string()); },
                                                 [&] { (void)readExrLayers(p.string()); }};
        for (const auto& read : readers) {
            expectIoError(p.string(), "", read);
            try {
                read();
            } catch (const IoError& e) {
                EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
            }
        }
    }
}

// 119 bytes whose attribute of unknown type claims 1.75 GB: OpenEXR allocated
// the value before finding the file too short.
TEST(ExrFuzzRegressions, AttributeLargerThanTheFileIsRefused) {
    const std::string p = std::string(DVSGI_EXR_REGRESSIONS_DIR) + "/attribute_size_beyond_file.exr";
    expectIoError(p, "corrupt header (attribute 'comprsseion' claims 1751318528 bytes, 12 remain",
                  [&] { (void)readExr(p); });
}

// The same check on a file of our own writer, for a known attribute and for
// a negative size.
TEST(ExrFuzzRegressions, AttributeSizeIsCheckedAgainstTheFile) {
    const fs::path dir = scratchDir();
    const std::string good = (dir / "good.exr").string();
    writeExr(good, ImageRGBA32F::blank(4, 4));
    std::vector<uint8_t> bytes = fileBytes(good);
    const char key[] = "compression\0compression";
    auto it = std::search(bytes.begin(), bytes.end(), key, key + sizeof key);
    ASSERT_NE(it, bytes.end());
    const size_t sizeAt = size_t(it - bytes.begin()) + sizeof key;
    const std::string path = (dir / "bad.exr").string();
    for (int32_t claimed : {0x7fffffff, int32_t(bytes.size()), -1}) {
        std::memcpy(bytes.data() + sizeAt, &claimed, 4);
        writeBytes(path, bytes);
        expectIoError(path, "attribute 'compression' claims " + std::to_string(claimed) + " bytes",
                      [&] { (void)readExr(path); });
        expectIoError(path, "attribute 'compression' claims", [&] { (void)readExrLayers(path); });
    }
}

// OpenEXR reads a channel list to its empty name, not to the attribute's
// size: a list running past its size put OpenEXR's position inside other
// bytes, where an attribute of unknown type then claimed gigabytes.
TEST(ExrFuzzRegressions, ChannelListPastItsSizeIsRefused) {
    const std::string p = std::string(DVSGI_EXR_REGRESSIONS_DIR) + "/chlist_longer_than_its_size.exr";
    expectIoError(p, "attribute 'channels' of type 'chlist': channel list without its end within the attribute",
                  [&] { (void)readExrLayers(p); });
}

// A value of fixed layout whose size field says otherwise would shift every
// later attribute the same way.
TEST(ExrFuzzRegressions, FixedSizeAttributeWithAnotherSizeIsRefused) {
    const fs::path dir = scratchDir();
    const std::string good = (dir / "good.exr").string();
    writeExr(good, ImageRGBA32F::blank(4, 4));
    std::vector<uint8_t> bytes = fileBytes(good);
    const char key[] = "compression\0compression";
    auto it = std::search(bytes.begin(), bytes.end(), key, key + sizeof key);
    ASSERT_NE(it, bytes.end());
    const int32_t two = 2;
    std::memcpy(bytes.data() + (it - bytes.begin()) + sizeof key, &two, 4);
    const std::string path = (dir / "bad.exr").string();
    writeBytes(path, bytes);
    expectIoError(path, "attribute 'compression' of type 'compression': size 2, the type has 1 bytes",
                  [&] { (void)readExr(path); });
}

// 275 bytes, ZIP, claiming a 1965825x1 window: the readers allocated and
// cleared its pixels (and OpenEXR its line buffers) before the data ran out.
TEST(ExrFuzzRegressions, WindowBeyondWhatTheDataHoldsIsRefused) {
    const std::string p = std::string(DVSGI_EXR_REGRESSIONS_DIR) + "/window_beyond_its_data.exr";
    expectIoError(p, "data window 1965825x1 needs ", [&] { (void)readExrLayers(p); });
    expectIoError(p, "-byte file holds with its compression", [&] { (void)readExr(p); });
}

// Uncompressed, the pixels must be in the file: a ZIP file relabelled as
// uncompressed claims more pixel bytes than it has, refused from the header.
TEST(ExrFuzzRegressions, UncompressedWindowMustFitTheFile) {
    const fs::path dir = scratchDir();
    const std::string good = (dir / "good.exr").string();
    writeExr(good, ImageRGBA32F::blank(64, 64));  // ZIP: 49152 bytes of pixels in far fewer
    std::vector<uint8_t> bytes = fileBytes(good);
    const char key[] = "compression\0compression";
    auto it = std::search(bytes.begin(), bytes.end(), key, key + sizeof key);
    ASSERT_NE(it, bytes.end());
    ASSERT_LT(bytes.size(), 64u * 64u * 12u);
    bytes[size_t(it - bytes.begin()) + sizeof key + 4] = 0;  // NO_COMPRESSION
    const std::string path = (dir / "raw.exr").string();
    writeBytes(path, bytes);
    expectIoError(path, "data window 64x64 needs 49152 bytes of pixels, more than a " +
                            std::to_string(bytes.size()) + "-byte file holds",
                  [&] { (void)readExr(path); });
}
