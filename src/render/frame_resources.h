// Every image of a frame, owned by the frame rather than by the passes that
// write them: a pass's record function gets the images it reads and writes
// and declares its accesses to the frame's gpu::Tracker. The voxel volumes
// (vxgi::VoxelVolumes) are the frame's other half.
#pragma once

#include <cstdint>

#include "gpu/resources.h"

namespace dvsgi::render {

struct GBuffer {
    static constexpr VkFormat kColorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;  // albedo to better than 0.1 %
    static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
    gpu::Image base;      // base colour + metallic
    gpu::Image normal;    // world normal + roughness
    gpu::Image emission;  // emission + coverage (a = 0: background)
    gpu::Image depth;     // D32
    uint64_t memoryBytes() const;
};

struct FrameSize {
    uint32_t width = 0, height = 0;  // output
    uint32_t supersample = 1;        // internal = k x output
    float traceScale = 1.0f;         // cone-trace resolution / internal resolution
    uint32_t shadowMapSize = 0;
    uint32_t shadowViews = 0;        // layers of the shadow-map array
    bool temporalHistory = false;    // the indirect term's history pairs (with voxels)
    uint32_t internalWidth() const { return width * supersample; }
    uint32_t internalHeight() const { return height * supersample; }
    uint32_t traceWidth() const;   // cone-tracing size: internal x traceScale, at least 1
    uint32_t traceHeight() const;
};

// The history of the temporal accumulation (render/temporal_indirect.h), at
// internal size: two pairs that swap every frame, one holding last frame's
// values, the other receiving this frame's.
struct TemporalHistory {
    gpu::Image color[2];    // RGBA32F accumulated indirect diffuse, a = the pixel's frames in it
    gpu::Image surface[2];  // RGBA16F normal xyz, w = view depth (0: no geometry)
    uint64_t memoryBytes() const;
};

struct FrameTargets {
    GBuffer gbuffer;               // internal size
    gpu::Image shadowMap;          // D32 array, one layer per shadow view (at least 2: always an array)
    gpu::Image shadowGradient;     // RG16F array beside it: each texel's caster's depth gradient (shadow.frag)
    gpu::Image direct;             // RGBA32F internal size: direct light + emission
    gpu::Image visibility;         // R16F internal size: mean visibility of the lights facing each pixel
    gpu::Image diffuse, specular;  // RGBA16F internal size: cone-traced indirect diffuse (+ AO in a), specular
    gpu::Image traceDiffuse, traceSpecular;  // the same at trace size, only when traceScale < 1
    gpu::Image turnedDiffuse;      // RGBA16F trace size: the six cones' diffuse term before its resolve
    gpu::Image output;             // RGBA32F output size: the composited frame, or the voxel view
    TemporalHistory temporal;      // empty without FrameSize::temporalHistory
    uint32_t traceWidth = 0, traceHeight = 0;
    bool reducedTrace() const { return bool(traceDiffuse); }
};

FrameTargets createFrameTargets(const gpu::Context& ctx, const FrameSize& size);
// A G-buffer of width x height; light = a light's view (a reflective shadow
// map for --voxelizer pv), which only changes the images' names.
GBuffer createGBuffer(const gpu::Context& ctx, uint32_t width, uint32_t height, bool light = false);

// Samplers the passes share (immutable, so owned next to the frame).
struct Samplers {
    gpu::Sampler point;   // G-buffer texel fetches; shadow-map gathers (clamped)
    gpu::Sampler volume;  // trilinear + mips, transparent border: outside the grid is empty
};

Samplers createSamplers(const gpu::Context& ctx);

}  // namespace dvsgi::render
