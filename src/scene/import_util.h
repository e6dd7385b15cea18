// Internal helpers shared by the importers: whole-file reads and stb_image
// decoding into a Texture. Not part of the public scene API.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace dvsgi::scene::detail {

std::optional<std::vector<uint8_t>> readFileBytes(const std::filesystem::path& file);

// Decodes any format stb_image knows into RGBA8 (row 0 = top). On failure
// returns false and sets `error` to stb's reason; `out` is then unspecified.
bool decodeImage(const uint8_t* data, size_t size, Texture& out, std::string& error);
bool decodeImageFile(const std::filesystem::path& file, Texture& out, std::string& error);

// JPEG data (after any 0xFF fill bytes, the start-of-image marker) and its
// decoder, libjpeg-turbo (jpeg_decode.cpp); decodeImage dispatches to it.
bool isJpeg(const uint8_t* data, size_t size);
bool decodeJpeg(const uint8_t* data, size_t size, Texture& out, std::string& error);

// Images with more texels than this are refused before any allocation: 2^28
// RGBA8 texels are already 1 GiB.
constexpr uint64_t kMaxImageTexels = uint64_t(1) << 28;

// Resolves `rel` (already percent-decoded, '/'-separated) against `dir`.
// Unless `allowOutside`, the result must stay inside `dir` after resolving
// symlinks: absolute paths, ".." that climbs out and links pointing outside
// are refused. NUL bytes are refused always. On refusal returns nullopt and
// sets `error` to a reason that can follow the reference in a message.
std::optional<std::filesystem::path> confinedPath(const std::filesystem::path& dir, const std::string& rel,
                                                  bool allowOutside, std::string& error);

std::string lowercase(std::string s);

// `s` with control bytes (newlines, NUL, escape sequences) written as \xNN,
// so a hostile name cannot split or hide an error message.
std::string printable(const std::string& s);

// Splits an affine matrix into the node's T * R * S. Shear cannot be
// represented and is lost (glTF requires decomposable node matrices).
void decomposeMatrix(const glm::mat4& m, Node& n);

}  // namespace dvsgi::scene::detail
