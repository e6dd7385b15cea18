// The scene as the GPU sees it: merged vertex and index buffers, one GpuDraw
// per placed primitive, the material table and the texture table.
#pragma once

#include <memory>
#include <vector>

#include "gpu/resources.h"
#include "gpu/texture_table.h"
#include "scene/scene.h"

namespace dvsgi::gpuscene {

struct DrawRange {
    uint32_t firstIndex;
    uint32_t indexCount;
    int32_t vertexOffset;
    bool alphaTested;  // MASK or BLEND material: needs a fragment shader even for depth
    bool dynamic;      // its node or an ancestor is dynamic: re-voxelized every frame
    bool baseColorOnly = false;  // its material samples no texture but (maybe) the base colour's
};

class SceneGpu {
public:
    // `maxAnisotropy`: the textures' sampler's (1: none; the device caps it).
    SceneGpu(const gpu::Context& ctx, const scene::Scene& scene, float maxAnisotropy);

    // Binds what every pass that rasterizes the scene needs: the texture table
    // (set 1 of `layout`), the vertex and the index buffer.
    void bindGeometry(VkCommandBuffer cmd, VkPipelineLayout layout) const;

    // Re-uploads the per-draw transforms (after animation). Blocks.
    void updateDraws(const gpu::Context& ctx, const scene::Scene& scene, const std::vector<scene::DrawItem>& items);

    gpu::Buffer vertices, indices, draws, materials;
    std::vector<DrawRange> ranges;  // per draw (index into `draws`)
    std::vector<gpu::Image> textures;
    gpu::Image fallbackTexture;
    gpu::Sampler sampler;
    std::unique_ptr<gpu::TextureTable> textureTable;
    bool emissiveTextures = false;  // some material has an emissive texture (the compute voxelizer samples it)
    scene::Bounds bounds;
    uint64_t triangleCount = 0;

    // Host copies for culling on the CPU (draw lists per view, the compute
    // voxelizer after a clipmap scroll): each primitive's bounds, local, per run of
    // kBoundsChunk consecutive triangles, and each draw's primitive and world
    // matrix (updateDraws keeps them current).
    static constexpr uint32_t kBoundsChunk = 64;
    std::vector<std::vector<scene::Bounds>> primitiveChunks;
    std::vector<uint32_t> drawPrimitive;
    std::vector<glm::mat4> drawWorld;

private:
    std::vector<DrawRange> primitiveRanges_;  // per scene primitive
};

}  // namespace dvsgi::gpuscene
