#include "json_file.h"

#include <filesystem>
#include <fstream>
#include <system_error>

#include "image/image_io.h"

namespace dvsgi::app {

void writeJsonFile(const std::string& path, const nlohmann::json& j, const std::string& option) {
    const std::filesystem::path p(path);
    std::error_code ec;  // a folder that cannot be made shows up as the open failing
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path(), ec);
    const std::string who = option.empty() ? path : option + ": " + path;
    std::ofstream f(path);
    if (!f) throw image::IoError(who + ": cannot open for writing");
    f << j.dump(2) << "\n";
    if (!f) throw image::IoError(who + ": write failed");
}

}  // namespace dvsgi::app
