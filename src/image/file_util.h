// Whole-file I/O shared by the EXR and PNG code; errors become IoError with the path.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace dvsgi::image::detail {

[[noreturn]] void fail(const std::string& path, const std::string& what);

// Writes `path` through a temporary file in the same directory that is renamed
// over `path` only by commit(). A failed or abandoned write therefore never
// leaves a partial file under the final name, and an older file of that name
// survives it (rename within one directory replaces atomically). The
// constructor creates missing parent directories.
class AtomicFile {
public:
    explicit AtomicFile(const std::string& path);
    ~AtomicFile();  // removes the temporary file unless committed
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    std::FILE* file() const { return file_; }
    // Flushes, closes and renames; throws IoError if any write failed.
    void commit();

private:
    std::string path_, temp_;
    std::FILE* file_ = nullptr;
    bool committed_ = false;
};

// Writes the bytes through an AtomicFile (replacing the file).
void writeFileBytes(const std::string& path, const std::vector<uint8_t>& bytes);

std::vector<uint8_t> readFileBytes(const std::string& path);

}  // namespace dvsgi::image::detail
