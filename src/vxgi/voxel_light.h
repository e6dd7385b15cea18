// The voxel light passes (paper sections VI, VII, IX), one class per pass:
//   InjectPass        direct light + emission per occupied voxel -> `direct`
//   AnisoFilterPass   radiance -> six directional volumes with mip chains
//   BouncePass        cones per voxel through the filtered volumes -> radiance
// The Renderer orders them: inject, copy direct -> radiance, filter, then K x
// (bounce, filter).
#pragma once

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "shared/voxel_data.h"

namespace dvsgi::gpu {
class GpuTimers;
}

namespace dvsgi::vxgi {

class VoxelVolumes;

enum class Occlusion : uint32_t {
    ShadowMap = shader::OCCLUSION_SHADOW_MAP,
    RaycastHard = shader::OCCLUSION_RAYCAST_HARD,
    RaycastSoft = shader::OCCLUSION_RAYCAST_SOFT,
    None = shader::OCCLUSION_NONE,
    PerLight = shader::OCCLUSION_PER_LIGHT,
};

struct VoxelLightSettings {
    bool normalWeighted = true;           // eq. 5 (else Lambert N.L, eq. 2)
    Occlusion occlusion = Occlusion::PerLight;  // global override of each light's mode
    float softKappa = 0.5f;               // soft raycast: nu += (1 - nu) * kappa / t
    float shadowNormalOffset = 1.5f;      // texels
    uint32_t bounces = 1;                 // extra bounces per voxel (0 = direct only)
    // beta, min step, max distance, first sample; clearance and surface thickness
    shader::ConeParams bounceCone{glm::vec4(1.0f, 0.5f, 1e30f, 1.0f), glm::vec4(shader::CONE_CLEARANCE_DEFAULT, shader::CONE_SURFACE_VOXELS, 0.0f, 0.0f)};
};

struct ShadowInputs {
    VkBuffer lights;
    uint32_t lightCount;
    VkBuffer views;
    VkImageView shadowMap;
    VkSampler shadowSampler;
    bool shadowsRendered;
};

class InjectPass {
public:
    InjectPass(const gpu::Context& ctx, uint32_t n);
    void record(VkCommandBuffer cmd, const VoxelVolumes& volumes, const ShadowInputs& shadows,
                const VoxelLightSettings& settings, gpu::GpuTimers* timers) const;
    // Copies `direct` into the radiance volume (the start of the bounce iteration).
    void copyToRadiance(VkCommandBuffer cmd, const VoxelVolumes& volumes) const;
    gpu::Image direct;  // RGBA16F N^3: direct light + emission, kept for the bounces

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
};

class AnisoFilterPass {
public:
    explicit AnisoFilterPass(const gpu::Context& ctx);
    void record(VkCommandBuffer cmd, const VoxelVolumes& volumes, gpu::GpuTimers* timers, const char* timerName) const;

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
};

class BouncePass {
public:
    explicit BouncePass(const gpu::Context& ctx);
    void record(VkCommandBuffer cmd, const VoxelVolumes& volumes, const gpu::Image& direct,
                const VoxelLightSettings& settings, gpu::GpuTimers* timers) const;
    const gpu::Sampler& sampler() const { return sampler_; }

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
    gpu::Sampler sampler_;  // trilinear + mips, clamped to the grid's edge
};

}  // namespace dvsgi::vxgi
