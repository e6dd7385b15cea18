// Plain-data scene model that every importer produces and the renderer consumes.
// Units follow docs/UNITS.md: metres, Y up, linear radiometric quantities.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace dvsgi::scene {

struct Vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec2 uv{0.0f};
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};  // xyz tangent, w = bitangent sign
};

// Decoded 8-bit RGBA texels. `srgb` says how the renderer must interpret them:
// base colour and emissive textures are sRGB-encoded, data textures are linear.
struct Texture {
    std::string name;  // file name or "<embedded N>", used in messages
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> rgba8;  // width*height*4, row 0 = top of the image
    bool srgb = true;
};

enum class AlphaMode : uint32_t { Opaque = 0, Mask = 1, Blend = 2 };

struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};
    int baseColorTexture = -1;  // index into Scene::textures, -1 = none
    glm::vec3 emissiveFactor{0.0f};
    float emissiveStrength = 1.0f;  // KHR_materials_emissive_strength
    int emissiveTexture = -1;
    float metallicFactor = 1.0f;  // glTF defaults
    float roughnessFactor = 1.0f;
    int metallicRoughnessTexture = -1;  // glTF: G = roughness, B = metallic, linear
    int normalTexture = -1;
    float normalScale = 1.0f;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
};

// One draw: indexed triangles with a single material.
struct Primitive {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;  // triangle list
    uint32_t material = 0;          // index into Scene::materials
    bool hasTangents = false;       // false: tangent is a placeholder
};

struct Mesh {
    std::string name;
    std::vector<uint32_t> primitives;  // indices into Scene::primitives
};

struct Camera {
    std::string name;
    float yfov = 0.6860478f;  // full vertical field of view, radians
    float aspectRatio = 0.0f; // 0 = follow the image size
    float znear = 0.01f;
    float zfar = 100.0f;
};

enum class LightType : uint32_t { Directional = 0, Point = 1, Spot = 2 };

// KHR_lights_punctual with this project's units: directional intensity is
// irradiance in W/m^2, point/spot intensity is radiant intensity in W/sr.
struct Light {
    std::string name;
    LightType type = LightType::Point;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    float innerConeAngle = 0.0f;            // half-angles from the axis, radians
    float outerConeAngle = 0.78539816f;     // pi/4
};

struct Node {
    std::string name;
    int parent = -1;
    std::vector<int> children;
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // glm order: w, x, y, z
    glm::vec3 scale{1.0f};
    int mesh = -1;
    int camera = -1;
    int light = -1;
    bool dynamic = false;  // animated or marked dynamic on the command line
};

enum class Interpolation : uint32_t { Linear = 0, Step = 1, CubicSpline = 2 };
enum class AnimPath : uint32_t { Translation = 0, Rotation = 1, Scale = 2 };

struct AnimationChannel {
    int node = -1;
    AnimPath path = AnimPath::Translation;
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;       // seconds, ascending
    std::vector<glm::vec4> values;  // xyz (translation/scale) or quaternion xyzw;
                                    // cubic spline: 3 values per key (in, value, out)
};

struct Animation {
    std::string name;
    std::vector<AnimationChannel> channels;
};

struct Scene {
    std::string source;  // file path, or "builtin:cornell"
    std::vector<Primitive> primitives;
    std::vector<Mesh> meshes;
    std::vector<Material> materials;  // never empty after loading (a default is added)
    std::vector<Texture> textures;
    std::vector<Camera> cameras;
    std::vector<Light> lights;
    std::vector<Node> nodes;
    std::vector<int> roots;  // nodes of the default scene
    std::vector<Animation> animations;
    std::vector<std::string> warnings;  // e.g. a missing texture replaced by its factor
};

// ---- Derived, per-frame views of a Scene (scene/transform.cpp) ----

struct Bounds {
    glm::vec3 min{1e30f};
    glm::vec3 max{-1e30f};
    bool valid() const { return min.x <= max.x; }
    // Corner k of the box: bit 0, 1, 2 of k pick max over min in x, y, z.
    glm::vec3 corner(int k) const {
        return {(k & 1) ? max.x : min.x, (k & 2) ? max.y : min.y, (k & 4) ? max.z : min.z};
    }
};

// World matrix of every node (index = node index); nodes not reachable from
// the roots get identity.
std::vector<glm::mat4> worldMatrices(const Scene& scene);

// One mesh primitive placed in the world.
struct DrawItem {
    uint32_t primitive;
    int node;
    glm::mat4 world;
};
std::vector<DrawItem> drawItems(const Scene& scene, const std::vector<glm::mat4>& world);

// A light placed in the world: position from the node's translation, direction
// = the node's -Z axis (normalized).
struct PlacedLight {
    Light light;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
};
std::vector<PlacedLight> placedLights(const Scene& scene, const std::vector<glm::mat4>& world);

struct PlacedCamera {
    Camera camera;
    glm::mat4 world{1.0f};  // camera-to-world; the camera looks down its -Z
};
// Cameras in node order (lowest node index first, as CONVENTIONS.md requires).
std::vector<PlacedCamera> placedCameras(const Scene& scene, const std::vector<glm::mat4>& world);
// The node of the index-th placed camera; -1 when there is none.
int placedCameraNode(const Scene& scene, int index);
// Sets node i's local rotation and translation so that its world matrix
// becomes `world` (a rigid transform), whatever its parents hold.
void setNodeWorld(Scene& scene, int i, const glm::mat4& world);

Bounds worldBounds(const Scene& scene, const std::vector<DrawItem>& items);

// Apply the animations at time t (seconds) to the nodes' local TRS.
void applyAnimations(Scene& scene, float t);

// Appends `src`'s geometry, materials and textures under a new root node
// named `rootName` (cameras and lights of `src` are dropped); returns that node.
int appendScene(Scene& dst, const Scene& src, const std::string& rootName);

// Animates `node` around a horizontal circle (one turn per `period` seconds,
// sampled with `keys` linear keys) and marks it dynamic.
void addCircularPath(Scene& scene, int node, glm::vec3 center, float radius, float period, uint32_t keys = 120);

// Adds the documented defaults when the file has none: a camera looking at the
// bounds from +Z, and a directional "sun" of irradiance 3 W/m^2 (docs/UNITS.md).
void addDefaults(Scene& scene);

// Box-filters every texture wider or taller than `maxDim` down to fit it,
// keeping the aspect ratio (sRGB textures are averaged in linear light). The
// renderer passes the device's maxImageDimension2D. One warning per texture
// that was shrunk is appended to `warnings` when it is not null.
void limitTextureSize(Scene& scene, uint32_t maxDim, std::vector<std::string>* warnings);

}  // namespace dvsgi::scene
