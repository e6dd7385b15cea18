// Writing the JSON files of render --metrics, bench and soak.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace dvsgi::app {

// Writes `j` (indented) to `path`, creating its folder; throws image::IoError
// naming the path (and `option`, the flag that named it, when given).
void writeJsonFile(const std::string& path, const nlohmann::json& j, const std::string& option = "");

}  // namespace dvsgi::app
