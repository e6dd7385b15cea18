#include "image/file_util.h"

#include "image/image_io.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace dvsgi::image::detail {

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

std::string errnoText(int err) { return std::strerror(err); }

void createParentDirectories(const std::string& path) {
    namespace fs = std::filesystem;
    const fs::path parent = fs::path(path).parent_path();
    if (parent.empty()) return;
    std::error_code ec;
    fs::create_directories(parent, ec);
    // create_directories reports "exists" errors for a file in the way; a later
    // open failure then explains it better, so only report here when the
    // directory really is not there.
    if (ec && !fs::is_directory(parent))
        fail(path, "cannot create directory '" + parent.string() + "': " + ec.message());
}

}  // namespace

void fail(const std::string& path, const std::string& what) { throw IoError(path + ": " + what); }

AtomicFile::AtomicFile(const std::string& path) : path_(path) {
    namespace fs = std::filesystem;
    const fs::path p(path);
    // The rename in commit() would fail on a directory only after all the work.
    std::error_code ec;
    if (fs::is_directory(p, ec)) fail(path, "cannot open for writing: " + errnoText(EISDIR));
    if (p.filename().empty()) fail(path, "cannot open for writing: not a file name");
    createParentDirectories(path);

    // Hidden, and named after the target and this process, so a leftover from a
    // killed run is recognisable; O_EXCL never reuses someone else's file.
    static std::atomic<unsigned> counter{0};
    for (int attempt = 0;; ++attempt) {
        temp_ = (p.parent_path() / ("." + p.filename().string() + ".tmp-" +
                                    std::to_string(::getpid()) + "-" +
                                    std::to_string(counter++)))
                    .string();
        const int fd = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            file_ = ::fdopen(fd, "wb");
            if (!file_) {
                const int err = errno;
                ::close(fd);
                ::unlink(temp_.c_str());
                fail(path, "cannot open for writing: " + errnoText(err));
            }
            return;
        }
        if (errno != EEXIST || attempt >= 100)
            fail(path, "cannot open for writing (temporary file '" + temp_ + "'): " + errnoText(errno));
    }
}

AtomicFile::~AtomicFile() {
    if (file_) std::fclose(file_);
    if (!committed_) ::unlink(temp_.c_str());
}

void AtomicFile::commit() {
    // Writers report their own failed writes with errno; this catches any that
    // went unreported, and fflush/fclose report what buffering hid (a full disk).
    if (std::ferror(file_)) fail(path_, "write failed");
    int err = 0;
    if (std::fflush(file_) != 0) err = errno;
    std::FILE* f = file_;
    file_ = nullptr;
    if (std::fclose(f) != 0 && !err) err = errno;
    if (err) fail(path_, "write failed: " + errnoText(err));
    if (std::rename(temp_.c_str(), path_.c_str()) != 0)
        fail(path_, "cannot replace the file: " + errnoText(errno));
    committed_ = true;
}

void writeFileBytes(const std::string& path, const std::vector<uint8_t>& bytes) {
    AtomicFile out(path);
    if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), out.file()) != bytes.size())
        fail(path, "write failed: " + errnoText(errno));
    out.commit();
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
