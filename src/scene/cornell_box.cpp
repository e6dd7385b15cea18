// The built-in Cornell box: a copy of shared/scenes/cornell-box/cornell-lights.gltf
// (+ .bin) compiled in, so the renderer and tests have a scene without any file.
// The vertex data below was generated from that file (float32 values printed
// with 9 significant digits, i.e. bit-exact); scene_tests checks that both
// stay identical.
#include <cstddef>
#include <iterator>

#include "scene/load.h"

namespace dvsgi::scene {

namespace {

struct MeshData {
    const char* name;  // node and mesh name
    uint32_t material;
    const float* positions;  // xyz per vertex
    const float* normals;
    size_t vertexCount;
};

// Every mesh of the file is a list of quads: vertices 4q..4q+3 form the
// triangles (0,1,2) and (0,2,3), so the index data is rebuilt, not stored.
constexpr float kShortBlockP[] = {
    -0.146400034f, 0.164999962f, 0.0650001392f, -0.194400042f, 0.164999887f, 0.225000128f, -0.0364000015f,
    0.164999887f, 0.272000164f, 0.0136000104f, 0.164999962f, 0.114000142f, 0.0136000104f, -7.99999995e-08f,
    0.114000022f, 0.0136000104f, 0.164999962f, 0.114000142f, -0.0364000015f, 0.164999887f, 0.272000164f,
    -0.0364000015f, -1.70000007e-07f, 0.272000074f, -0.146400034f, -3.99999998e-08f, 0.0650000125f,
    -0.146400034f, 0.164999962f, 0.0650001392f, 0.0136000104f, 0.164999962f, 0.114000142f, 0.0136000104f,
    -7.99999995e-08f, 0.114000022f, -0.194400042f, -1.50000005e-07f, 0.225000054f, -0.194400042f, 0.164999887f,
    0.225000128f, -0.146400034f, 0.164999962f, 0.0650001392f, -0.146400034f, -3.99999998e-08f, 0.0650000125f,
    -0.0364000015f, -1.70000007e-07f, 0.272000074f, -0.0364000015f, 0.164999887f, 0.272000164f, -0.194400042f,
    0.164999887f, 0.225000128f, -0.194400042f, -1.50000005e-07f, 0.225000054f};
constexpr float kShortBlockN[] = {
    -6.74065319e-08f, 1.0f, 4.28705647e-07f, -6.74065319e-08f, 1.0f, 4.28705647e-07f, -6.74065319e-08f, 1.0f,
    4.28705647e-07f, -6.74065319e-08f, 1.0f, 4.28705647e-07f, 0.953400135f, -1.70295849e-07f, 0.301708877f,
    0.953400135f, -1.70295849e-07f, 0.301708877f, 0.953400135f, -1.70295849e-07f, 0.301708877f, 0.953400135f,
    -1.70295849e-07f, 0.301708877f, 0.292825699f, 7.42082022e-07f, -0.95616585f, 0.292825699f, 7.42082022e-07f,
    -0.95616585f, 0.292825699f, 7.42082022e-07f, -0.95616585f, 0.292825699f, 7.42082022e-07f, -0.95616585f,
    -0.957826316f, 1.52053119e-07f, -0.287347764f, -0.957826316f, 1.52053119e-07f, -0.287347764f, -0.957826316f,
    1.52053119e-07f, -0.287347764f, -0.957826316f, 1.52053119e-07f, -0.287347764f, -0.285120994f,
    -5.47856871e-07f, 0.958491504f, -0.285120994f, -5.47856871e-07f, 0.958491504f, -0.285120994f,
    -5.47856871e-07f, 0.958491504f, -0.285120994f, -5.47856871e-07f, 0.958491504f};
constexpr float kRedWallP[] = {
    0.276400059f, 0.0f, 0.0f, 0.273200065f, -3.60000001e-07f, 0.559200108f, 0.279600084f, 0.548799813f,
    0.559200466f, 0.279600084f, 0.548800111f, 3.60000001e-07f};
constexpr float kRedWallN[] = {
    -0.999957681f, 0.00874602422f, -0.00286108139f, -0.999957681f, 0.00874602422f, -0.00286108139f,
    -0.999957681f, 0.00874602422f, -0.00286108139f, -0.999957681f, 0.00874602422f, -0.00286108139f};
constexpr float kLightP[] = {
    0.0666000172f, 0.547999978f, 0.22700043f, 0.0666000172f, 0.547999978f, 0.332000405f, -0.0634000078f,
    0.547999978f, 0.332000405f, -0.0634000078f, 0.547999978f, 0.22700043f};
constexpr float kLightN[] = {
    0.0f, -1.0f, -0.0f, 0.0f, -1.0f, -0.0f, 0.0f, -1.0f, -0.0f, 0.0f, -1.0f, -0.0f};
constexpr float kTallBlockP[] = {
    0.146600038f, 0.329999924f, 0.247000292f, -0.0114000002f, 0.329999894f, 0.296000302f, 0.0376000106f,
    0.329999775f, 0.456000298f, 0.195600048f, 0.329999775f, 0.406000286f, 0.146600038f, -1.59999999e-07f,
    0.247000054f, 0.146600038f, 0.329999924f, 0.247000292f, 0.195600048f, 0.329999775f, 0.406000286f,
    0.195600048f, -2.69999987e-07f, 0.406000108f, 0.195600048f, -2.69999987e-07f, 0.406000108f, 0.195600048f,
    0.329999775f, 0.406000286f, 0.0376000106f, 0.329999775f, 0.456000298f, 0.0376000106f, -2.90000003e-07f,
    0.45600009f, 0.0376000106f, -2.90000003e-07f, 0.45600009f, 0.0376000106f, 0.329999775f, 0.456000298f,
    -0.0114000002f, 0.329999894f, 0.296000302f, -0.0114000002f, -2.00000002e-07f, 0.296000063f, -0.0114000002f,
    -2.00000002e-07f, 0.296000063f, -0.0114000002f, 0.329999894f, 0.296000302f, 0.146600038f, 0.329999924f,
    0.247000292f, 0.146600038f, -1.59999999e-07f, 0.247000054f};
constexpr float kTallBlockN[] = {
    1.34844782e-07f, 1.0f, 7.93426921e-07f, 1.34844782e-07f, 1.0f, 7.93426921e-07f, 1.34844782e-07f, 1.0f,
    7.93426921e-07f, 1.34844782e-07f, 1.0f, 7.93426921e-07f, 0.955648959f, 2.03548794e-07f, -0.294508159f,
    0.955648959f, 2.03548794e-07f, -0.294508159f, 0.955648959f, 2.03548794e-07f, -0.294508159f, 0.955648959f,
    2.03548794e-07f, -0.294508159f, 0.301708817f, -5.44946829e-07f, 0.953400075f, 0.301708817f,
    -5.44946829e-07f, 0.953400075f, 0.301708817f, -5.44946829e-07f, 0.953400075f, 0.301708817f,
    -5.44946829e-07f, 0.953400075f, -0.956165791f, -1.68655006e-07f, 0.292825818f, -0.956165791f,
    -1.68655006e-07f, 0.292825818f, -0.956165791f, -1.68655006e-07f, 0.292825818f, -0.956165791f,
    -1.68655006e-07f, 0.292825818f, -0.296209067f, 6.82414452e-07f, -0.955123127f, -0.296209067f,
    6.82414452e-07f, -0.955123127f, -0.296209067f, 6.82414452e-07f, -0.955123127f, -0.296209067f,
    6.82414452e-07f, -0.955123127f};
constexpr float kCeilingP[] = {
    0.279600084f, 0.548800111f, 3.60000001e-07f, 0.279600084f, 0.548799813f, 0.559200466f, -0.276400059f,
    0.548799813f, 0.559200466f, -0.276400059f, 0.548800111f, 3.60000001e-07f};
constexpr float kCeilingN[] = {
    0.0f, -1.0f, -5.32945592e-07f, 0.0f, -1.0f, -5.32945592e-07f, 0.0f, -1.0f, -5.32945592e-07f, 0.0f, -1.0f,
    -5.32945592e-07f};
constexpr float kBackWallP[] = {
    0.273200065f, -3.60000001e-07f, 0.559200108f, -0.276400059f, -3.60000001e-07f, 0.559200108f, -0.276400059f,
    0.548799813f, 0.559200466f, 0.279600084f, 0.548799813f, 0.559200466f};
constexpr float kBackWallN[] = {
    0.0f, 5.89412025e-07f, -1.0f, 0.0f, 5.89412025e-07f, -1.0f, 0.0f, 5.89412025e-07f, -1.0f, 0.0f,
    5.89412025e-07f, -1.0f};
constexpr float kFloorP[] = {
    0.276400059f, 0.0f, 0.0f, -0.276400059f, 0.0f, 0.0f, -0.276400059f, -3.60000001e-07f, 0.559200108f,
    0.273200065f, -3.60000001e-07f, 0.559200108f, 0.0136000104f, -7.99999995e-08f, 0.114000022f, -0.0364000015f,
    -1.70000007e-07f, 0.272000074f, -0.194400042f, -1.50000005e-07f, 0.225000054f, -0.146400034f,
    -3.99999998e-08f, 0.0650000125f, 0.195600048f, -2.69999987e-07f, 0.406000108f, 0.0376000106f,
    -2.90000003e-07f, 0.45600009f, -0.0114000002f, -2.00000002e-07f, 0.296000063f, 0.146600038f,
    -1.59999999e-07f, 0.247000054f};
constexpr float kFloorN[] = {
    0.0f, 1.0f, 6.4377673e-07f, 0.0f, 1.0f, 6.4377673e-07f, 0.0f, 1.0f, 6.4377673e-07f, 0.0f, 1.0f,
    6.4377673e-07f, 1.08575449e-09f, -1.0f, -6.28596126e-07f, 1.08575449e-09f, -1.0f, -6.28596126e-07f,
    1.08575449e-09f, -1.0f, -6.28596126e-07f, 1.08575449e-09f, -1.0f, -6.28596126e-07f, -5.97237992e-09f, -1.0f,
    -6.25124414e-07f, -5.97237992e-09f, -1.0f, -6.25124414e-07f, -5.97237992e-09f, -1.0f, -6.25124414e-07f,
    -5.97237992e-09f, -1.0f, -6.25124414e-07f};
constexpr float kGreenWallP[] = {
    -0.276400059f, -3.60000001e-07f, 0.559200108f, -0.276400059f, 0.0f, 0.0f, -0.276400059f, 0.548800111f,
    3.60000001e-07f, -0.276400059f, 0.548799813f, 0.559200466f};
constexpr float kGreenWallN[] = {
    1.0f, 0.0f, -2.29181421e-08f, 1.0f, 0.0f, -2.29181421e-08f, 1.0f, 0.0f, -2.29181421e-08f, 1.0f, 0.0f,
    -2.29181421e-08f};

constexpr MeshData kMeshes[] = {
    {"short_block", 0, kShortBlockP, kShortBlockN, std::size(kShortBlockP) / 3},
    {"red_wall", 1, kRedWallP, kRedWallN, std::size(kRedWallP) / 3},
    {"light", 2, kLightP, kLightN, std::size(kLightP) / 3},
    {"tall_block", 0, kTallBlockP, kTallBlockN, std::size(kTallBlockP) / 3},
    {"ceiling", 0, kCeilingP, kCeilingN, std::size(kCeilingP) / 3},
    {"back_wall", 0, kBackWallP, kBackWallN, std::size(kBackWallP) / 3},
    {"floor", 0, kFloorP, kFloorN, std::size(kFloorP) / 3},
    {"green_wall", 3, kGreenWallP, kGreenWallN, std::size(kGreenWallP) / 3},
};

Material lambert(const char* name, glm::vec3 color) {
    Material m;
    m.name = name;
    m.baseColorFactor = glm::vec4(color, 1.0f);
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 1.0f;
    m.doubleSided = false;
    return m;
}

}  // namespace

Scene builtinCornellBox() {
    Scene s;
    s.source = "builtin:cornell";
    s.materials = {lambert("white", {1, 1, 1}), lambert("red", {1, 0, 0}), lambert("light", {1, 1, 1}),
                   lambert("green", {0, 1, 0})};

    for (const MeshData& md : kMeshes) {
        Primitive p;
        p.material = md.material;
        p.vertices.resize(md.vertexCount);
        for (size_t v = 0; v < md.vertexCount; ++v) {
            p.vertices[v].position = glm::vec3(md.positions[3 * v], md.positions[3 * v + 1], md.positions[3 * v + 2]);
            p.vertices[v].normal = glm::vec3(md.normals[3 * v], md.normals[3 * v + 1], md.normals[3 * v + 2]);
        }
        for (uint32_t q = 0; q < md.vertexCount / 4; ++q)
            for (uint32_t o : {0u, 1u, 2u, 0u, 2u, 3u}) p.indices.push_back(4 * q + o);
        Mesh mesh;
        mesh.name = md.name;
        mesh.primitives.push_back(static_cast<uint32_t>(s.primitives.size()));
        s.primitives.push_back(std::move(p));
        Node n;
        n.name = md.name;
        n.mesh = static_cast<int>(s.meshes.size());
        s.meshes.push_back(std::move(mesh));
        s.nodes.push_back(std::move(n));
    }

    Camera cam;
    cam.name = "camera";
    cam.yfov = 0.6860478808414068f;  // 2 atan(12.5 / 35): 35 mm lens on 25 mm film
    cam.aspectRatio = 1.0f;
    cam.znear = 0.01f;
    cam.zfar = 10.0f;
    s.cameras.push_back(cam);
    Node camNode;
    camNode.name = "camera";
    camNode.camera = 0;
    camNode.translation = glm::vec3(0.0016f, 0.2744f, -0.763f);
    camNode.rotation = glm::quat(0.0f, 0.0f, 1.0f, 0.0f);  // w,x,y,z: half turn about Y, looks along +Z
    s.nodes.push_back(camNode);

    Light point;
    point.name = "point_light";
    point.type = LightType::Point;
    point.color = glm::vec3(1.0f, 0.9f, 0.8f);
    point.intensity = 0.06f;  // W/sr
    s.lights.push_back(point);
    Node pointNode;
    pointNode.name = "point_light";
    pointNode.light = 0;
    pointNode.translation = glm::vec3(0.0016f, 0.45f, 0.2795f);
    s.nodes.push_back(pointNode);

    Light sun;
    sun.name = "front_sun";
    sun.type = LightType::Directional;
    sun.color = glm::vec3(0.8f, 0.9f, 1.0f);
    sun.intensity = 0.5f;  // W/m^2
    s.lights.push_back(sun);
    Node sunNode;
    sunNode.name = "front_sun";
    sunNode.light = 1;
    sunNode.translation = glm::vec3(0.0f, 1.0f, -1.0f);
    // File order x,y,z,w = (-0.846680760383606, 0.46994104981422424, 0, 0.2495734840631485).
    sunNode.rotation = glm::quat(0.2495734840631485f, -0.846680760383606f, 0.46994104981422424f, 0.0f);
    s.nodes.push_back(sunNode);

    for (int i = 0; i < static_cast<int>(s.nodes.size()); ++i) s.roots.push_back(i);
    return s;
}

}  // namespace dvsgi::scene
