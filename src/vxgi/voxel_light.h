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
#include "vxgi/cone_settings.h"

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

// How the voxel bounces are iterated.
enum class BounceMode {
    Fixed,     // exactly `bounces` bounces every frame (the paper: 1)
    Converge,  // the first frame iterates until the relative change of voxel radiance
               // falls below `convergence` (at most `maxBounces`), later frames feed back
    Feedback,  // one bounce per frame reading the previous frame's filtered radiance
};

struct VoxelLightSettings {
    bool normalWeighted = true;           // eq. 5 (else Lambert N.L, eq. 2)
    Occlusion occlusion = Occlusion::PerLight;  // global override of each light's mode
    float softKappa = 0.5f;               // soft raycast: nu += (1 - nu) * kappa / t
    float shadowNormalOffset = 1.5f;      // texels
    bool emissionInRadiance = true;       // false when emitters are lit as area lights (no double counting)
    BounceMode bounceMode = BounceMode::Converge;
    uint32_t bounces = 1;                 // Fixed: bounces per frame (0 = direct only)
    float convergence = 0.005f;           // Converge: stop when sum|dY| / sum Y over voxels is below this
    uint32_t maxBounces = 64;             // Converge: give up (and say so) after this many
    // The bounce's cones march with the shared settings but this step factor
    // (bounceCones()): beta = 1 costs half of 0.5 and changes the converged
    // indirect light by 1.8 % (docs/quality.md).
    float bounceStepFactor = 1.0f;
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
    // `stats` (optional, statsFloats(N) floats, host-visible): per-workgroup
    // sums of |luminance change| and luminance over occupied voxels.
    void record(VkCommandBuffer cmd, const VoxelVolumes& volumes, const gpu::Image& direct,
                const ConeSettings& cone, const gpu::Buffer* stats, gpu::GpuTimers* timers) const;
    const gpu::Sampler& sampler() const { return sampler_; }
    static uint32_t statsFloats(uint32_t n);

private:
    const gpu::Context& ctx_;
    gpu::Pipeline pipeline_;
    gpu::Sampler sampler_;  // trilinear + mips, clamped to the grid's edge
    gpu::Buffer noStats_;
};

}  // namespace dvsgi::vxgi
