// Whole-file I/O shared by the EXR and PNG code; errors become IoError with the path.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace dvsgi::image::detail {

[[noreturn]] void fail(const std::string& path, const std::string& what);

// Creates the missing parent directories, then writes the bytes (replacing the file).
void writeFileBytes(const std::string& path, const std::vector<uint8_t>& bytes);

std::vector<uint8_t> readFileBytes(const std::string& path);

}  // namespace dvsgi::image::detail
