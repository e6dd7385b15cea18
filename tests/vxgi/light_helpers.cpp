#include "light_helpers.h"

#include <algorithm>
#include <cstring>

#include <glm/gtc/packing.hpp>
#include <glm/gtx/quaternion.hpp>

#include "gpu/barriers.h"
#include "gpu/context.h"
#include "gpu/tracker.h"
#include "gpu/transfer.h"
#include "vxgi/voxel_list.h"
#include "gpu_fixture.h"

namespace dvsgi::test {

float toHalf(float v) { return glm::unpackHalf1x16(glm::packHalf1x16(v)); }

glm::vec4 toHalf(glm::vec4 v) { return {toHalf(v.x), toHalf(v.y), toHalf(v.z), toHalf(v.w)}; }

namespace {

// One RGBA16F texel of a readback.
glm::vec4 halfTexel(const uint8_t* bytes) {
    uint16_t h[4];
    std::memcpy(h, bytes, 8);
    return {glm::unpackHalf1x16(h[0]), glm::unpackHalf1x16(h[1]), glm::unpackHalf1x16(h[2]), glm::unpackHalf1x16(h[3])};
}

}  // namespace

Rgba16Volume readRgba16(const gpu::Image& image, uint32_t mip) {
    const std::vector<uint8_t> bytes = gpu::readbackImage(context(), image, gpu::use::ComputeReadWrite, mip);
    Rgba16Volume v;
    v.n = std::max(image.desc().extent.width >> mip, 1u);
    v.texels.resize(size_t(v.n) * v.n * v.n);
    EXPECT_EQ(bytes.size(), v.texels.size() * 8);
    for (size_t i = 0; i < v.texels.size(); ++i) v.texels[i] = halfTexel(bytes.data() + i * 8);
    return v;
}

Rgba16Volume filterDirectionalLevel(const Rgba16Volume& src, int dir) {
    Rgba16Volume out;
    out.n = std::max(src.n / 2, 1u);
    out.texels.assign(size_t(out.n) * out.n * out.n, glm::vec4(0.0f));
    const int axis = kAxis[dir];
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    for (int z = 0; z < int(out.n); ++z)
        for (int y = 0; y < int(out.n); ++y)
            for (int x = 0; x < int(out.n); ++x) {
                const glm::ivec3 base = glm::ivec3(x, y, z) * 2;
                glm::vec4 sum(0.0f);
                for (int a = 0; a < 2; ++a)
                    for (int b = 0; b < 2; ++b) {
                        glm::ivec3 lo = base, hi = base;
                        lo[u] += a, lo[w] += b, hi[u] += a, hi[w] += b;
                        hi[axis] += 1;
                        // Travelling +axis enters the low child first.
                        const glm::ivec3 front = kSign[dir] > 0 ? lo : hi, back = kSign[dir] > 0 ? hi : lo;
                        const glm::vec4 f = src.at(front.x, front.y, front.z), k = src.at(back.x, back.y, back.z);
                        sum += f + k * (1.0f - f.a);
                    }
                out.at(x, y, z) = sum * 0.25f;
            }
    return out;
}

Rgba16Volume readDirectional(const vxgi::VoxelVolumes& volumes, uint32_t dir, uint32_t mip) {
    const gpu::Image& atlas = volumes.directional;
    const std::vector<uint8_t> bytes = gpu::readbackImage(context(), atlas, gpu::use::ComputeReadWrite, mip);
    Rgba16Volume v;
    v.n = std::max(atlas.desc().extent.height >> mip, 1u);
    v.texels.resize(size_t(v.n) * v.n * v.n);
    EXPECT_EQ(bytes.size(), v.texels.size() * 8 * shader::DIRECTIONAL_VOLUMES);
    for (int z = 0; z < int(v.n); ++z)
        for (int y = 0; y < int(v.n); ++y)
            for (int x = 0; x < int(v.n); ++x) {
                const glm::ivec3 t = shader::directionalTexel(dir, glm::ivec3(x, y, z), int(v.n));
                const size_t at = (size_t(t.z) * v.n + size_t(t.y)) * v.n * shader::DIRECTIONAL_VOLUMES + size_t(t.x);
                v.at(x, y, z) = halfTexel(bytes.data() + at * 8);
            }
    return v;
}

void uploadRgba16(const gpu::Image& image, const Rgba16Volume& volume) {
    std::vector<uint16_t> halves(volume.texels.size() * 4);
    for (size_t i = 0; i < volume.texels.size(); ++i)
        for (int c = 0; c < 4; ++c) halves[i * 4 + size_t(c)] = glm::packHalf1x16(volume.texels[i][c]);
    gpu::uploadImage(context(), image, halves.data(), halves.size() * sizeof(uint16_t), gpu::use::ComputeReadWrite);
}

void uploadAccum(const vxgi::VoxelVolumes& volumes, const AccumVolume& accum) {
    // Slots, index and the occupied-voxel list the per-voxel passes run over.
    vxgi::uploadAttributes(context(), volumes, accum);
}

AccumVolume readAccum(const vxgi::VoxelVolumes& volumes) { return vxgi::readAttributes(context(), volumes); }

Rgba16Volume readDirect(const vxgi::VoxelVolumes& volumes) {
    Rgba16Volume out;
    out.n = volumes.grid.n;
    out.texels = vxgi::readDirectLight(context(), volumes);
    return out;
}

UnusedShadowMap::UnusedShadowMap() {
    gpu::ImageDesc d;
    d.format = VK_FORMAT_D32_SFLOAT;
    d.extent = {4, 4, 1};
    d.layers = 2;  // the shader declares a sampler2DArray, so the view must be an array
    d.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    d.name = "unused shadow map";
    map = gpu::Image(context(), d);
    d.format = VK_FORMAT_R16G16_SFLOAT;
    d.usage = VK_IMAGE_USAGE_SAMPLED_BIT;
    d.name = "unused shadow gradients";
    gradient = gpu::Image(context(), d);
    gpu::SamplerDesc sd;
    sd.filter = VK_FILTER_NEAREST;
    sd.mipmap = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sd.address = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sampler = gpu::Sampler(context(), sd);
    context().submitAndWait([&](VkCommandBuffer cmd) {
        gpu::transition(cmd, map, gpu::use::Undefined, gpu::use::ShaderRead);
        gpu::transition(cmd, gradient, gpu::use::Undefined, gpu::use::ShaderRead);
    });
}

void addInwardBox(scene::Scene& s, int material, glm::vec3 center, float h, bool openTop) {
    const glm::vec3 up(0, 1, 0);
    const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const glm::vec3& n : normals) {
        if (openTop && n.y < -0.5f) continue;
        // A face with inward normal n sits on the side -n of the centre.
        const glm::quat r = n.y < -0.5f ? glm::angleAxis(glm::pi<float>(), glm::vec3(1, 0, 0)) : glm::rotation(up, n);
        addQuad(s, material, center - n * h, h, r);
    }
}

render::RenderSettings unitBoxGridSettings(uint32_t n, uint32_t shadowMapSize) {
    render::RenderSettings rs;
    rs.width = rs.height = 8;
    rs.shadowMapSize = shadowMapSize;
    rs.voxels = n;
    rs.hasVoxelBox = true;
    rs.voxelBoxMin = glm::vec3(-1.0f);
    rs.voxelBoxMax = glm::vec3(1.0f);
    // The furnace walls emit: keep their emission in the voxels, where the
    // bounces under test carry it, instead of lighting them as area lights.
    rs.emitterLights = false;
    return rs;
}

}  // namespace dvsgi::test
