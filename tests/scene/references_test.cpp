// glTF buffer and image URIs stay inside the scene's folder unless the caller
// allows more; textures are bounded in size and shrink to a device limit.
#include <gtest/gtest.h>

#include "scene/import_util.h"
#include "scene/load.h"
#include "test_support.h"

using namespace dvsgi::scene;
using namespace scene_test;

namespace {

// A scene in dir/scene whose buffer 0 has URI `uri`; the buffer's bytes are
// written to dir/<binFile> (relative to dir, not to the scene).
std::string sceneWithBufferUri(const TempDir& dir, const std::string& uri, const std::string& binFile) {
    fs::create_directories(dir.path() / "scene");
    GltfBuilder b = triangleScene();
    b.writeGltfExternal(dir, "tmp.gltf", binFile);
    b.doc["buffers"][0]["uri"] = uri;
    std::string path = dir.file("scene/a.gltf");
    writeText(path, b.doc.dump());
    return path;
}

}  // namespace

TEST(GltfReferences, AbsoluteBufferUriRejected) {
    TempDir dir;
    std::string path = sceneWithBufferUri(dir, dir.file("outside.bin"), "outside.bin");
    expectError(path, "buffer 0: URI '" + dir.file("outside.bin") + "' is an absolute path");
}

TEST(GltfReferences, DotDotEscapeRejectedUnlessAllowed) {
    TempDir dir;
    std::string path = sceneWithBufferUri(dir, "../outside.bin", "outside.bin");
    expectError(path, "points outside the scene's folder");
    LoadOptions o;
    o.allowOutsideReferences = true;
    EXPECT_EQ(loadScene(path, o).primitives.size(), 1u);
}

TEST(GltfReferences, DotDotThatStaysInsideAccepted) {
    TempDir dir;
    fs::create_directories(dir.path() / "scene/sub");
    std::string path = sceneWithBufferUri(dir, "sub/../in.bin", "scene/in.bin");
    EXPECT_EQ(loadScene(path).primitives.size(), 1u);
}

TEST(GltfReferences, SymlinkPointingOutsideRejected) {
    TempDir dir;
    std::string path = sceneWithBufferUri(dir, "link.bin", "outside.bin");
    fs::create_symlink(dir.path() / "outside.bin", dir.path() / "scene/link.bin");
    expectError(path, "points outside the scene's folder");
}

TEST(GltfReferences, PercentTricksRejected) {
    TempDir dir;
    expectError(sceneWithBufferUri(dir, "in.bin%00.png", "scene/in.bin"), "contains a NUL byte");
    expectError(sceneWithBufferUri(dir, "in%2", "scene/in.bin"), "malformed percent escape");
    expectError(sceneWithBufferUri(dir, "in%zz.bin", "scene/in.bin"), "malformed percent escape");
    expectError(sceneWithBufferUri(dir, "%2e%2e/outside.bin", "outside.bin"), "points outside");
    expectError(sceneWithBufferUri(dir, "file:///etc/passwd", "scene/in.bin"), "unsupported scheme");
    // A NUL even the option does not allow: it would cut the name.
    LoadOptions o;
    o.allowOutsideReferences = true;
    std::string msg = loadError(sceneWithBufferUri(dir, "in.bin%00x", "scene/in.bin"), o);
    EXPECT_NE(msg.find("NUL"), std::string::npos) << msg;
    // Encoded characters that are fine in file names still work.
    EXPECT_EQ(loadScene(sceneWithBufferUri(dir, "in%20b.bin", "scene/in b.bin")).primitives.size(), 1u);
}

TEST(GltfReferences, ImageOutsideTheFolderIsAnError) {
    TempDir dir;
    fs::create_directories(dir.path() / "scene");
    writePng(dir.file("secret.png"), 1, 1, {9, 9, 9, 255});
    GltfBuilder b = triangleScene();
    b.doc["images"] = json::array({{{"uri", "../secret.png"}}});
    b.doc["textures"] = json::array({{{"source", 0}}});
    b.doc["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    std::string path = b.writeGltfDataUri(dir, "scene/a.gltf");
    expectError(path, "image 0: URI '../secret.png' points outside");
}

TEST(Textures, AbsurdDecodedSizeRefusedBeforeAllocating) {
    TempDir dir;
    // A 1x1 PNG whose header is edited to claim a 20000 x 20000 grey image:
    // stb's own check counts one byte per grey texel and lets it through,
    // then expands to RGBA, which would allocate 1.6 GB.
    auto png = pngBytes(1, 1, {1, 2, 3, 255});
    const uint8_t big[8] = {0, 0, 0x4E, 0x20, 0, 0, 0x4E, 0x20};
    std::copy(big, big + 8, png.begin() + 16);
    png[25] = 0;  // colour type: greyscale
    GltfBuilder b = triangleScene();
    b.doc["images"] = json::array({{{"uri", "data:image/png;base64," + base64(png)}}});
    b.doc["textures"] = json::array({{{"source", 0}}});
    b.doc["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    Scene s = loadScene(b.writeGltfDataUri(dir, "a.gltf"));
    EXPECT_TRUE(s.textures.empty());
    bool named = false;
    for (const std::string& w : s.warnings)
        named = named || w.find("image size 20000x20000 exceeds the limit") != std::string::npos;
    EXPECT_TRUE(named) << (s.warnings.empty() ? std::string("no warnings") : s.warnings[0]);
}

// Found by fuzz_image: stb_image 2.27 wrote past its Huffman size table when
// a DHT segment declared more than 256 codes. JPEG now goes to libjpeg-turbo,
// which must refuse it with a message.
TEST(Textures, JpegHuffmanTableOverflowRefused) {
    std::vector<uint8_t> jpg = {0xFF, 0xD8, 0xFF, 0xC4, 0x00, 0x13, 0x00};
    for (int i = 0; i < 16; ++i) jpg.push_back(0xFF);  // 16 x 255 codes
    jpg.insert(jpg.end(), {0xFF, 0xD9});
    Texture t;
    std::string error;
    EXPECT_FALSE(detail::decodeImage(jpg.data(), jpg.size(), t, error));
    EXPECT_NE(error.find("corrupt JPEG (Bogus Huffman table definition)"), std::string::npos) << error;
    // stb also read the table behind 0xFF fill bytes before the start marker
    // (the second input the fuzzer found); libjpeg refuses such data.
    jpg.insert(jpg.begin(), {0xFF, 0xFF});
    error.clear();
    EXPECT_FALSE(detail::decodeImage(jpg.data(), jpg.size(), t, error));
    EXPECT_NE(error.find("corrupt JPEG"), std::string::npos) << error;
}

// Found by fuzz_image: a zero-length IDAT before the data made stb copy
// through a null pointer. Such chunks hold nothing; the image decodes as if
// they were absent.
TEST(Textures, PngWithEmptyFirstIdatDecodes) {
    TempDir dir;
    const std::vector<uint8_t> texels = {10, 20, 30, 255, 40, 50, 60, 255, 70, 80, 90, 255, 1, 2, 3, 4};
    auto png = pngBytes(2, 2, texels);
    const std::vector<uint8_t> emptyIdat = {0, 0, 0, 0, 'I', 'D', 'A', 'T', 0x35, 0xAF, 0x06, 0x1E};
    png.insert(png.begin() + 33, emptyIdat.begin(), emptyIdat.end());  // after the signature and IHDR
    GltfBuilder b = triangleScene();
    b.doc["images"] = json::array({{{"uri", "data:image/png;base64," + base64(png)}}});
    b.doc["textures"] = json::array({{{"source", 0}}});
    b.doc["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    Scene s = loadScene(b.writeGltfDataUri(dir, "a.gltf"));
    ASSERT_EQ(s.textures.size(), 1u) << (s.warnings.empty() ? "" : s.warnings[0]);
    EXPECT_EQ(s.textures[0].rgba8, texels);
}

// Found by fuzz_image: a 64-byte TGA header claiming 11055 x 20034 texels
// made stb allocate 900 MB and decode zeros for ten seconds.
TEST(Textures, HeadersClaimingMoreThanTheDataHoldsRefused) {
    std::vector<uint8_t> tga(64, 8);
    const uint8_t header[18] = {0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x2F, 0x2B, 0x42, 0x4E, 8, 8};
    std::copy(header, header + 18, tga.begin());
    Texture t;
    std::string error;
    EXPECT_FALSE(detail::decodeImage(tga.data(), tga.size(), t, error));
    EXPECT_NE(error.find("claims 11055x20034 texels, more than 64 bytes"), std::string::npos) << error;
    // An uncompressed 4x4 TGA with two of its four rows.
    std::vector<uint8_t> small(18 + 4 * 2 * 3, 7);
    const uint8_t smallHeader[18] = {0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 4, 0, 4, 0, 24, 0};
    std::copy(smallHeader, smallHeader + 18, small.begin());
    EXPECT_FALSE(detail::decodeImage(small.data(), small.size(), t, error));
    EXPECT_NE(error.find("truncated (42 of 66 bytes)"), std::string::npos) << error;
    small.resize(66, 7);
    EXPECT_TRUE(detail::decodeImage(small.data(), small.size(), t, error)) << error;
    EXPECT_EQ(t.width, 4u);
    // Run-length TGA (type 10): one run packet covers at most 128 texels, so
    // 13 KB cannot describe 4112 x 4103 (the fuzzer's third input: 10 s).
    std::vector<uint8_t> rle(13329, 0);
    const uint8_t rleHeader[18] = {0, 0, 10, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x10, 0x10, 0x07, 0x10, 16, 0};
    std::copy(rleHeader, rleHeader + 18, rle.begin());
    EXPECT_FALSE(detail::decodeImage(rle.data(), rle.size(), t, error));
    EXPECT_NE(error.find("claims 4112x4103 texels, more than 13329 bytes"), std::string::npos) << error;
}

TEST(Textures, LimitTextureSizeBoxFiltersKeepingAspect) {
    Scene s;
    Texture wide;
    wide.name = "strip";
    wide.width = 70000;
    wide.height = 1;
    wide.srgb = false;
    wide.rgba8.resize(size_t(70000) * 4);
    for (size_t i = 0; i < 70000; ++i) wide.rgba8[i * 4] = i % 2 ? 255 : 0;  // alternating texels
    s.textures.push_back(wide);
    Texture small;
    small.width = small.height = 2;
    small.rgba8.assign(16, 7);
    s.textures.push_back(small);
    std::vector<std::string> warnings;
    limitTextureSize(s, 4096, &warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("'strip' is 70000x1"), std::string::npos) << warnings[0];
    EXPECT_EQ(s.textures[0].width, 4096u);
    EXPECT_EQ(s.textures[0].height, 1u);
    ASSERT_EQ(s.textures[0].rgba8.size(), 4096u * 4);
    // Linear data: the box mean of alternating 0/255 is about half.
    for (uint32_t x = 0; x < 4096; x += 511) EXPECT_NEAR(s.textures[0].rgba8[x * 4], 128, 8) << x;
    EXPECT_EQ(s.textures[1].width, 2u);  // within the limit: untouched
    EXPECT_EQ(s.textures[1].rgba8, std::vector<uint8_t>(16, 7));
}

TEST(Textures, LimitTextureSizeAveragesSrgbInLinearLight) {
    Scene s;
    Texture t;
    t.width = 4;
    t.height = 2;
    t.srgb = true;
    // Each 2x2 block: two black and two white texels, alpha 255.
    for (int i = 0; i < 8; ++i) {
        uint8_t v = (i % 2) ? 255 : 0;
        t.rgba8.insert(t.rgba8.end(), {v, v, v, 255});
    }
    s.textures.push_back(t);
    limitTextureSize(s, 2, nullptr);
    ASSERT_EQ(s.textures[0].width, 2u);
    ASSERT_EQ(s.textures[0].height, 1u);
    // Half the light is sRGB 188, not the encoded mean 128.
    EXPECT_NEAR(s.textures[0].rgba8[0], 188, 1);
    EXPECT_EQ(s.textures[0].rgba8[3], 255);
}
