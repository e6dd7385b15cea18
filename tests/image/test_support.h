// Helpers for the image tests: a private scratch directory per test and a way
// to run small Python/OpenImageIO scripts as the independent judge of our files.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <functional>
#include <iterator>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "image/image_io.h"

namespace dvsgi::image::test {

inline const char* kPython = "/usr/bin/python3";

// Tests run in parallel under ctest (one process per test), hence the pid.
inline std::filesystem::path scratchRoot() {
    return std::filesystem::temp_directory_path() /
           ("dvsgi_image_tests_" + std::to_string(::getpid()));
}

// Removes the scratch files when every test passed; failures keep them for a look.
class ScratchCleanup : public ::testing::Environment {
public:
    void TearDown() override {
        if (::testing::UnitTest::GetInstance()->Passed()) {
            std::error_code ec;
            std::filesystem::remove_all(scratchRoot(), ec);
        }
    }
};
inline ::testing::Environment* const kScratchCleanup =
    ::testing::AddGlobalTestEnvironment(new ScratchCleanup);

inline std::filesystem::path scratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::filesystem::path dir = scratchRoot() /
                                (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::string shellQuote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

inline std::string readText(const std::filesystem::path& p) {
    std::ifstream f(p);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

inline bool havePythonOiio() {
    static const bool ok =
        std::system((std::string(kPython) +
                     " -c 'import OpenImageIO, numpy' >/dev/null 2>&1").c_str()) == 0;
    return ok;
}

struct PyResult {
    int status = -1;
    std::string output;  // stdout and stderr
};

// Runs `python3 <script file> args...` with the script written to dir.
inline PyResult runPython(const std::filesystem::path& dir, const std::string& script,
                          const std::vector<std::string>& args = {}) {
    const auto scriptPath = dir / "script.py";
    const auto outPath = dir / "script.out";
    std::ofstream(scriptPath) << script;
    std::string cmd = std::string(kPython) + " " + shellQuote(scriptPath.string());
    for (const auto& a : args) cmd += " " + shellQuote(a);
    cmd += " >" + shellQuote(outPath.string()) + " 2>&1";
    PyResult r;
    r.status = std::system(cmd.c_str());
    r.output = readText(outPath);
    return r;
}

inline PyResult runCommand(const std::filesystem::path& dir, const std::string& cmdline) {
    const auto outPath = dir / "command.out";
    PyResult r;
    r.status = std::system((cmdline + " >" + shellQuote(outPath.string()) + " 2>&1").c_str());
    r.output = readText(outPath);
    return r;
}

inline std::vector<uint8_t> fileBytes(const std::filesystem::path& p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

inline void writeBytes(const std::filesystem::path& p, const std::vector<uint8_t>& b) {
    std::ofstream f(p, std::ios::binary);
    f.write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
}

// fn must throw IoError whose message is "<path>: ..." and contains fragment.
inline void expectIoError(const std::string& path, const std::string& fragment,
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

}  // namespace dvsgi::image::test

// A missing judge is a failure, not a skip: a skipped check passes unnoticed.
#define REQUIRE_PYTHON_OIIO()                                                   \
    do {                                                                        \
        if (!::dvsgi::image::test::havePythonOiio())                            \
            FAIL() << "/usr/bin/python3 with OpenImageIO and numpy missing";    \
    } while (0)

// The same for input files (shared reference images and tools).
#define REQUIRE_FILE(path)                                                      \
    do {                                                                        \
        if (!std::filesystem::exists(path)) FAIL() << (path) << " not found";   \
    } while (0)
