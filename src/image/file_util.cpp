#include "image/file_util.h"

#include "image/image_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <system_error>

namespace dvsgi::image::detail {

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

std::string errnoText(int err) { return std::strerror(err); }

}  // namespace

void fail(const std::string& path, const std::string& what) { throw IoError(path + ": " + what); }

void writeFileBytes(const std::string& path, const std::vector<uint8_t>& bytes) {
    namespace fs = std::filesystem;
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty()) {
        std::error_code ec;
        fs::create_directories(parent, ec);
        // create_directories reports "exists" errors for a file in the way; a
        // later fopen failure then explains it better, so only report here when
        // the directory really is not there.
        if (ec && !fs::is_directory(parent))
            fail(path, "cannot create directory '" + parent.string() + "': " + ec.message());
    }
    FilePtr f(std::fopen(path.c_str(), "wb"));
    if (!f) fail(path, "cannot open for writing: " + errnoText(errno));
    if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), f.get()) != bytes.size())
        fail(path, "write failed: " + errnoText(errno));
    // fclose flushes; a full disk may only show up here.
    std::FILE* raw = f.release();
    if (std::fclose(raw) != 0) fail(path, "write failed: " + errnoText(errno));
}

std::vector<uint8_t> readFileBytes(const std::string& path) {
    FilePtr f(std::fopen(path.c_str(), "rb"));
    if (!f) fail(path, "cannot open for reading: " + errnoText(errno));
    std::vector<uint8_t> bytes;
    uint8_t buf[1 << 16];
    for (;;) {
        const size_t n = std::fread(buf, 1, sizeof buf, f.get());
        bytes.insert(bytes.end(), buf, buf + n);
        if (n < sizeof buf) {
            if (std::ferror(f.get())) fail(path, "read failed: " + errnoText(errno));
            break;
        }
    }
    return bytes;
}

}  // namespace dvsgi::image::detail
