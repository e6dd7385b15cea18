// Camera paths: keyframes of time, position, orientation (or a target to look
// at) and vertical field of view, read from JSON (`--camera-path FILE.json`),
// interpolated, and applied to a scene's camera node as an animation would.
//
// {
//   "interpolation": "catmull-rom",          // or "linear"; positions only (orientations slerp)
//   "loop": false,                           // true: time wraps around the last key
//   "keyframes": [
//     {"time": 0.0, "position": [x, y, z], "target": [x, y, z], "yfov_degrees": 40},
//     {"time": 2.5, "position": [x, y, z], "orientation": [x, y, z, w]}
//   ]
// }
// A key gives either "target" (looked at, +Y up) or "orientation" (glTF order
// x, y, z, w: the camera looks down its -Z). "yfov_degrees" is optional; keys
// without it keep the scene camera's field of view.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scene/scene.h"

namespace dvsgi::scene {

struct CameraKey {
    float time = 0.0f;  // seconds
    glm::vec3 position{0.0f};
    glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};
    std::optional<float> yfov;  // radians
};

struct CameraPath {
    std::vector<CameraKey> keys;  // strictly increasing times
    bool catmullRom = true;
    bool loop = false;
    std::string source;  // the file, for messages
    float duration() const { return keys.empty() ? 0.0f : keys.back().time - keys.front().time; }
};

struct CameraPose {
    glm::mat4 world{1.0f};  // camera-to-world
    std::optional<float> yfov;
};

// Parses a path; throws std::runtime_error naming the file (and the key) on
// anything malformed: not JSON, no keys, times not increasing, a key with both
// or neither of target and orientation, a target on the position, a field of
// view outside (0, 180) degrees, a non-finite number.
CameraPath parseCameraPath(const std::string& json, const std::string& source);
CameraPath loadCameraPath(const std::string& file);

// The pose at time t (clamped to the keys, or wrapped when the path loops).
CameraPose sampleCameraPath(const CameraPath& path, float t);

// Puts the scene's index-th placed camera at the path's pose for time t
// (node transform and, when the keys give one, the field of view).
void applyCameraPath(Scene& scene, int cameraIndex, const CameraPath& path, float t);

// Writes a path in the format above (orientation keys), e.g. one the viewer recorded.
std::string cameraPathJson(const CameraPath& path);

}  // namespace dvsgi::scene
