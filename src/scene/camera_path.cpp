#include "scene/camera_path.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/quaternion.hpp>
#include <nlohmann/json.hpp>

namespace dvsgi::scene {

namespace {

using json = nlohmann::json;

[[noreturn]] void fail(const std::string& source, const std::string& what) {
    throw std::runtime_error(source + ": camera path: " + what);
}

float number(const json& j, const std::string& source, const std::string& what) {
    if (!j.is_number()) fail(source, what + " is not a number");
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(source, what + " is not finite");
    return float(v);
}

template <int N>
glm::vec<N, float> vector(const json& j, const std::string& source, const std::string& what) {
    if (!j.is_array() || j.size() != N) fail(source, what + " must be an array of " + std::to_string(N) + " numbers");
    glm::vec<N, float> v;
    for (int i = 0; i < N; ++i) v[i] = number(j[size_t(i)], source, what);
    return v;
}

// The orientation of a camera (looking down -Z, +Y up) at `position` looking at `target`.
glm::quat lookAtOrientation(glm::vec3 position, glm::vec3 target) {
    const glm::vec3 f = glm::normalize(target - position);
    // Straight up or down: any horizontal reference for "up" works.
    const glm::vec3 up = std::abs(f.y) > 0.9999f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
    const glm::mat4 view = glm::lookAt(position, target, up);
    return glm::quat_cast(glm::inverse(view));
}

CameraKey parseKey(const json& k, const std::string& source, size_t index) {
    const std::string at = "keyframe " + std::to_string(index);
    if (!k.is_object()) fail(source, at + " is not an object");
    for (const auto& [name, value] : k.items())
        if (name != "time" && name != "position" && name != "target" && name != "orientation" &&
            name != "yfov_degrees")
            fail(source, at + " has an unknown field '" + name + "'");
    if (!k.contains("time")) fail(source, at + " has no 'time'");
    if (!k.contains("position")) fail(source, at + " has no 'position'");
    CameraKey key;
    key.time = number(k["time"], source, at + " 'time'");
    key.position = vector<3>(k["position"], source, at + " 'position'");
    const bool target = k.contains("target"), orientation = k.contains("orientation");
    if (target == orientation) fail(source, at + " needs exactly one of 'target' and 'orientation'");
    if (target) {
        const glm::vec3 t = vector<3>(k["target"], source, at + " 'target'");
        if (glm::length(t - key.position) < 1e-6f) fail(source, at + " 'target' is on 'position'");
        key.orientation = lookAtOrientation(key.position, t);
    } else {
        const glm::vec4 q = vector<4>(k["orientation"], source, at + " 'orientation'");
        if (glm::length(q) < 1e-6f) fail(source, at + " 'orientation' is not a rotation (zero quaternion)");
        key.orientation = glm::normalize(glm::quat(q.w, q.x, q.y, q.z));
    }
    if (k.contains("yfov_degrees")) {
        const float deg = number(k["yfov_degrees"], source, at + " 'yfov_degrees'");
        if (!(deg > 0.0f && deg < 180.0f)) fail(source, at + " 'yfov_degrees' must be in (0, 180)");
        key.yfov = glm::radians(deg);
    }
    return key;
}

// Uniform Catmull-Rom through p1..p2 (p0, p3 the neighbours), u in [0, 1].
glm::vec3 catmullRom(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3, float u) {
    const float u2 = u * u, u3 = u2 * u;
    return 0.5f * ((2.0f * p1) + (-p0 + p2) * u + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * u2 +
                   (-p0 + 3.0f * p1 - 3.0f * p2 + p3) * u3);
}

}  // namespace

CameraPath parseCameraPath(const std::string& text, const std::string& source) {
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        fail(source, std::string("not valid JSON (") + e.what() + ")");
    }
    if (!j.is_object()) fail(source, "the top level must be an object");
    for (const auto& [name, value] : j.items())
        if (name != "keyframes" && name != "interpolation" && name != "loop")
            fail(source, "unknown field '" + name + "'");
    CameraPath path;
    path.source = source;
    if (j.contains("interpolation")) {
        const json& i = j["interpolation"];
        if (i == "catmull-rom")
            path.catmullRom = true;
        else if (i == "linear")
            path.catmullRom = false;
        else
            fail(source, "'interpolation' must be \"catmull-rom\" or \"linear\"");
    }
    if (j.contains("loop")) {
        if (!j["loop"].is_boolean()) fail(source, "'loop' must be true or false");
        path.loop = j["loop"].get<bool>();
    }
    if (!j.contains("keyframes") || !j["keyframes"].is_array() || j["keyframes"].empty())
        fail(source, "'keyframes' must be a non-empty array");
    const json& keys = j["keyframes"];
    for (size_t i = 0; i < keys.size(); ++i) {
        path.keys.push_back(parseKey(keys[i], source, i));
        if (i > 0 && !(path.keys[i].time > path.keys[i - 1].time))
            fail(source, "keyframe " + std::to_string(i) + " 'time' does not increase");
    }
    return path;
}

CameraPath loadCameraPath(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error(file + ": cannot open the camera path");
    std::ostringstream text;
    text << in.rdbuf();
    return parseCameraPath(text.str(), file);
}

CameraPose sampleCameraPath(const CameraPath& path, float t) {
    const std::vector<CameraKey>& k = path.keys;
    if (k.empty()) return {};
    const float start = k.front().time, length = path.duration();
    if (path.loop && length > 0.0f) t = start + std::fmod(std::fmod(t - start, length) + length, length);
    size_t i = 0;
    while (i + 1 < k.size() && t >= k[i + 1].time) ++i;
    CameraPose pose;
    if (t <= start || i + 1 >= k.size()) {
        const CameraKey& e = t <= start ? k.front() : k.back();
        pose.world = glm::translate(glm::mat4(1.0f), e.position) * glm::mat4_cast(e.orientation);
        pose.yfov = e.yfov;
        return pose;
    }
    const CameraKey& a = k[i];
    const CameraKey& b = k[i + 1];
    const float u = (t - a.time) / (b.time - a.time);
    glm::vec3 p = glm::mix(a.position, b.position, u);
    if (path.catmullRom) {
        // End segments mirror their outer neighbour so the curve still passes the end keys.
        const glm::vec3 p0 = i > 0 ? k[i - 1].position : 2.0f * a.position - b.position;
        const glm::vec3 p3 = i + 2 < k.size() ? k[i + 2].position : 2.0f * b.position - a.position;
        p = catmullRom(p0, a.position, b.position, p3, u);
    }
    pose.world = glm::translate(glm::mat4(1.0f), p) * glm::mat4_cast(glm::slerp(a.orientation, b.orientation, u));
    if (a.yfov && b.yfov)
        pose.yfov = glm::mix(*a.yfov, *b.yfov, u);
    else
        pose.yfov = u < 0.5f ? a.yfov : b.yfov;
    return pose;
}

void applyCameraPath(Scene& scene, int cameraIndex, const CameraPath& path, float t) {
    const int node = placedCameraNode(scene, cameraIndex);
    if (node < 0)
        throw std::runtime_error(path.source + ": camera path: the scene has no camera " + std::to_string(cameraIndex));
    const CameraPose pose = sampleCameraPath(path, t);
    setNodeWorld(scene, node, pose.world);
    if (pose.yfov) scene.cameras[size_t(scene.nodes[size_t(node)].camera)].yfov = *pose.yfov;
}

std::string cameraPathJson(const CameraPath& path) {
    json keys = json::array();
    for (const CameraKey& k : path.keys) {
        json key = {{"time", k.time},
                    {"position", {k.position.x, k.position.y, k.position.z}},
                    {"orientation", {k.orientation.x, k.orientation.y, k.orientation.z, k.orientation.w}}};
        if (k.yfov) key["yfov_degrees"] = glm::degrees(*k.yfov);
        keys.push_back(key);
    }
    const json j = {{"interpolation", path.catmullRom ? "catmull-rom" : "linear"}, {"loop", path.loop},
                    {"keyframes", keys}};
    return j.dump(2) + "\n";
}

}  // namespace dvsgi::scene
