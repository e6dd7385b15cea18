// Shared pieces of the voxel light tests: fp16 rounding, volume upload and
// read-back, a stand-in shadow map, and programmatic scenes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/resources.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "shared/voxel_data.h"
#include "vxgi/volumes.h"
#include "vxgi/voxel_storage_io.h"

namespace dvsgi::test {

// lib/voxel_attributes.glsl's voxelPlaneShare in double, from the mean normal
// weights per sign and the mean normal: 1 for one plane, 0 for faces along the axes.
inline double planeShareOf(const glm::dvec3& pos, const glm::dvec3& neg, const glm::dvec3& first) {
    const double lp = glm::length(glm::sqrt(pos) - glm::sqrt(neg)), la = glm::length(pos - neg),
                 lm = glm::length(first);
    return lp - la > 1e-3 ? glm::clamp((lm - la) / (lp - la), 0.0, 1.0) : 1.0;
}

// What a value becomes once stored in an RGBA16F texel (round to nearest even).
float toHalf(float v);
glm::vec4 toHalf(glm::vec4 v);

inline size_t voxelIndex(uint32_t n, int x, int y, int z) {
    return (size_t(z) * n + size_t(y)) * n + size_t(x);
}

// An RGBA16F 3D volume on the host, x fastest.
struct Rgba16Volume {
    uint32_t n = 0;
    std::vector<glm::vec4> texels;
    const glm::vec4& at(int x, int y, int z) const { return texels[voxelIndex(n, x, y, z)]; }
    glm::vec4& at(int x, int y, int z) { return texels[voxelIndex(n, x, y, z)]; }
};

// Reads one mip of an RGBA16F 3D image kept in GENERAL (all voxel volumes).
Rgba16Volume readRgba16(const gpu::Image& image, uint32_t mip = 0);
// Reads one mip of directional volume `dir` (order -X +X -Y +Y -Z +Z) out of the atlas.
Rgba16Volume readDirectional(const vxgi::VoxelVolumes& volumes, uint32_t dir, uint32_t mip = 0);
// Writes mip 0 of an RGBA16F 3D image (values rounded to fp16), leaving it in GENERAL.
void uploadRgba16(const gpu::Image& image, const Rgba16Volume& volume);

// The attribute sums on the host in the dense grid layout: slab c of N^3
// floats at z + c*N (vxgi/voxel_storage_io.h converts to and from slots).
using AccumVolume = vxgi::DenseAttributes;

// Gives every voxel with a count a static slot (and list entry) and uploads its sums.
void uploadAccum(const vxgi::VoxelVolumes& volumes, const AccumVolume& accum);
AccumVolume readAccum(const vxgi::VoxelVolumes& volumes);
// The per-slot direct light per grid voxel (empty voxels zero).
Rgba16Volume readDirect(const vxgi::VoxelVolumes& volumes);

// Directions in volume order: the axis and the sign of travel.
constexpr int kAxis[6] = {0, 0, 1, 1, 2, 2};
constexpr int kSign[6] = {-1, 1, -1, 1, -1, 1};

// One level of direction `dir` from its source (the radiance volume, or the
// same direction's previous level): per target voxel, the four child columns
// along the axis of travel, each composited front (the child a ray travelling
// that way enters first) over back, averaged.
Rgba16Volume filterDirectionalLevel(const Rgba16Volume& src, int dir);

// Inject's shadow-map binding must be valid even when no light samples it.
struct UnusedShadowMap {
    UnusedShadowMap();
    gpu::Image map;    // D32, 2 layers, in SHADER_READ_ONLY_OPTIMAL
    gpu::Image gradient;  // RG16F beside it, likewise
    gpu::Sampler sampler;
};

// Calls f(glm::ivec3) for each voxel of a box's six walls, which lie in voxel
// layers `low` and `high` of their axis, within innerLo..innerHi on the other
// two axes (so edges and corners, which mix two walls, can be left out).
template <typename F>
void forEachWallVoxel(int low, int high, int innerLo, int innerHi, F&& f) {
    for (int axis = 0; axis < 3; ++axis)
        for (int layer : {low, high})
            for (int a = innerLo; a <= innerHi; ++a)
                for (int b = innerLo; b <= innerHi; ++b) {
                    glm::ivec3 v;
                    v[axis] = layer;
                    v[(axis + 1) % 3] = a;
                    v[(axis + 2) % 3] = b;
                    f(v);
                }
}

// An 8x8 image over an N^3 grid on the box [-1, 1]^3 (the furnace tests).
render::RenderSettings unitBoxGridSettings(uint32_t n, uint32_t shadowMapSize = 64);

// Six inward-facing quads (addQuad) of half-size h around `center`; with
// `openTop` the face at +y (inward normal -y) is left out.
void addInwardBox(scene::Scene& s, int material, glm::vec3 center, float h, bool openTop = false);

}  // namespace dvsgi::test
