// What a raster pass draws: runs of consecutive triangles of the scene's
// draws, culled against a view's clip volume on the host, so passes that see
// part of the scene (the camera, one face of a point light's cube) rasterize
// only that part. Hopper-class GPUs have few raster units and llvmpipe
// transforms every vertex it is given, so triangles left out are time saved
// on both.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/pipeline.h"

namespace dvsgi::gpuscene {

class SceneGpu;

// Which draws a pass rasterizes.
enum class DrawFilter { All, Static, Dynamic };

// One vkCmdDrawIndexed: consecutive triangles of one draw.
struct DrawRun {
    uint32_t draw;  // index into SceneGpu::draws / ranges
    uint32_t firstIndex;
    uint32_t indexCount;
    int32_t vertexOffset;
    bool baseColorOnly;  // DrawRange::baseColorOnly of its draw
};

struct DrawList {
    std::vector<DrawRun> opaque;       // drawn first, with the pass's no-discard pipeline
    std::vector<DrawRun> alphaTested;  // MASK and BLEND materials, after
    uint64_t triangles() const;
};

// Culling merges at most this many consecutive kept chunks into one run, so
// a draw seen whole stays a few dozen draws, not one per chunk.
constexpr uint32_t kRunChunks = 16;

// The chunks (SceneGpu::kBoundsChunk triangles) of the draws `filter` picks
// whose world bounds reach the clip volume of `viewProj` (Vulkan's, depth
// 0..1, no depth clamp), so every triangle left out is one the rasterizer
// would have clipped away whole. Runs keep the scene's order.
DrawList visibleDraws(const SceneGpu& scene, const glm::mat4& viewProj, DrawFilter filter);

// The pipelines a raster pass draws runs with: `opaque` for opaque materials,
// `alphaTested` for the others, and where given, the `...BaseColorOnly` ones
// for runs whose material samples no texture but the base colour's (a pass
// can leave the other samples out of their shader: llvmpipe takes every
// sample of a shader, branch or not). All share one layout.
struct DrawPipelines {
    const gpu::Pipeline& opaque;
    const gpu::Pipeline& alphaTested;
    const gpu::Pipeline* opaqueBaseColorOnly = nullptr;
    const gpu::Pipeline* alphaTestedBaseColorOnly = nullptr;
};

// Records `list`: opaque runs, then the others, in the scene's order, each
// with its pipeline (descriptors already pushed, geometry bound); each run
// pushes shader::DrawPush {draw index, `view`}.
void recordDraws(VkCommandBuffer cmd, const DrawList& list, const DrawPipelines& pipelines, uint32_t view);

}  // namespace dvsgi::gpuscene
