#include "gpuscene/scene_gpu.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "gpu/context.h"
#include "gpu/transfer.h"
#include "shared/geometry_pass.h"
#include "shared/scene_data.h"

namespace dvsgi::gpuscene {

namespace {

namespace sh = dvsgi::shader;

glm::ivec2 textureSize(const std::vector<scene::Texture>& textures, int index) {
    if (index < 0 || size_t(index) >= textures.size()) return glm::ivec2(0);
    return glm::ivec2(int(textures[size_t(index)].width), int(textures[size_t(index)].height));
}

sh::GpuMaterial toGpu(const scene::Material& m, const std::vector<scene::Texture>& textures) {
    sh::GpuMaterial g{};
    g.baseColor = m.baseColorFactor;
    g.emission = glm::vec4(m.emissiveFactor * m.emissiveStrength, 0.0f);
    g.params = glm::vec4(m.metallicFactor, m.roughnessFactor, m.alphaCutoff, m.normalScale);
    g.textures = glm::ivec4(m.baseColorTexture, m.emissiveTexture, m.metallicRoughnessTexture, m.normalTexture);
    g.flags = glm::uvec4(uint32_t(m.alphaMode), m.doubleSided ? 1u : 0u, 0u, 0u);
    g.textureSizes = glm::ivec4(textureSize(textures, m.baseColorTexture), textureSize(textures, m.emissiveTexture));
    return g;
}

std::vector<sh::GpuDraw> toGpu(const scene::Scene& scene, const std::vector<scene::DrawItem>& items) {
    std::vector<sh::GpuDraw> out;
    out.reserve(items.size());
    for (const scene::DrawItem& it : items) {
        sh::GpuDraw d{};
        d.model = it.world;
        d.normalMatrix = glm::mat4(glm::transpose(glm::inverse(glm::mat3(it.world))));
        d.info = glm::uvec4(scene.primitives[it.primitive].material, uint32_t(std::max(it.node, 0)), 0u, 0u);
        out.push_back(d);
    }
    return out;
}

bool isDynamicNode(const scene::Scene& scene, int node) {
    for (int n = node; n >= 0 && size_t(n) < scene.nodes.size(); n = scene.nodes[size_t(n)].parent)
        if (scene.nodes[size_t(n)].dynamic) return true;
    return false;
}

uint32_t mipCount(uint32_t w, uint32_t h) {
    return uint32_t(std::floor(std::log2(double(std::max(w, h))))) + 1;
}

}  // namespace

SceneGpu::SceneGpu(const gpu::Context& ctx, const scene::Scene& scene, float maxAnisotropy) {
    std::vector<scene::Vertex> allVertices;
    std::vector<uint32_t> allIndices;
    for (const scene::Primitive& p : scene.primitives) {
        const bool known = p.material < scene.materials.size();
        const bool alphaTested = known && scene.materials[p.material].alphaMode != scene::AlphaMode::Opaque;
        const bool baseColorOnly = known && scene.materials[p.material].emissiveTexture < 0 &&
                                   scene.materials[p.material].metallicRoughnessTexture < 0;
        primitiveRanges_.push_back({uint32_t(allIndices.size()), uint32_t(p.indices.size()),
                                    int32_t(allVertices.size()), alphaTested, false, baseColorOnly});
        allVertices.insert(allVertices.end(), p.vertices.begin(), p.vertices.end());
        allIndices.insert(allIndices.end(), p.indices.begin(), p.indices.end());
        std::vector<scene::Bounds>& chunks = primitiveChunks.emplace_back();
        const size_t used = p.indices.size() / 3 * 3;  // whole triangles
        for (size_t i = 0; i < used; ++i) {
            if (i % (3 * kBoundsChunk) == 0) chunks.emplace_back();
            const uint32_t v = p.indices[i];
            if (v >= p.vertices.size()) continue;  // the loader rejects these; stay in bounds regardless
            chunks.back().min = glm::min(chunks.back().min, p.vertices[v].position);
            chunks.back().max = glm::max(chunks.back().max, p.vertices[v].position);
        }
    }
    vertices = gpu::createBuffer(ctx, allVertices.data(), allVertices.size() * sizeof(scene::Vertex),
                                 VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "vertices");
    indices = gpu::createBuffer(ctx, allIndices.data(), allIndices.size() * sizeof(uint32_t),
                                VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "indices");

    std::vector<sh::GpuMaterial> mats;
    for (const scene::Material& m : scene.materials) {
        mats.push_back(toGpu(m, scene.textures));
        emissiveTextures = emissiveTextures || m.emissiveTexture >= 0;
    }
    if (mats.empty()) mats.push_back(toGpu(scene::Material{}, scene.textures));
    materials = gpu::createBuffer(ctx, mats.data(), mats.size() * sizeof(sh::GpuMaterial),
                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "materials");

    if (scene.textures.size() > sh::MAX_TEXTURES)
        throw std::runtime_error(scene.source + ": " + std::to_string(scene.textures.size()) +
                                 " textures, more than the supported " + std::to_string(sh::MAX_TEXTURES));
    std::vector<VkImageView> views;
    for (const scene::Texture& t : scene.textures) {
        gpu::ImageDesc d;
        d.format = t.srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
        d.extent = {t.width, t.height, 1};
        d.mipLevels = mipCount(t.width, t.height);
        d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        d.name = "texture";
        textures.emplace_back(ctx, d);
        gpu::uploadImage(ctx, textures.back(), t.rgba8.data(), t.rgba8.size(), gpu::use::ShaderRead);
        views.push_back(textures.back().view());
    }
    gpu::ImageDesc fd;
    fd.format = VK_FORMAT_R8G8B8A8_UNORM;
    fd.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    fd.name = "fallback texture";
    fallbackTexture = gpu::Image(ctx, fd);
    const uint8_t white[4] = {255, 255, 255, 255};
    gpu::uploadImage(ctx, fallbackTexture, white, 4, gpu::use::ShaderRead);

    gpu::SamplerDesc sd;
    sd.maxAnisotropy = maxAnisotropy;
    sampler = gpu::Sampler(ctx, sd);
    textureTable = std::make_unique<gpu::TextureTable>(
        ctx, sh::MAX_TEXTURES, sh::BIND_TEXTURES,
        VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_GEOMETRY_BIT | VK_SHADER_STAGE_COMPUTE_BIT);
    textureTable->write(views, fallbackTexture.view(), sampler.handle());

    const std::vector<glm::mat4> world = scene::worldMatrices(scene);
    const std::vector<scene::DrawItem> items = scene::drawItems(scene, world);
    bounds = scene::worldBounds(scene, items);
    for (const scene::DrawItem& it : items) triangleCount += scene.primitives[it.primitive].indices.size() / 3;
    ranges.clear();
    for (const scene::DrawItem& it : items) {
        ranges.push_back(primitiveRanges_[it.primitive]);
        ranges.back().dynamic = isDynamicNode(scene, it.node);
        drawPrimitive.push_back(it.primitive);
        drawWorld.push_back(it.world);
    }
    std::vector<sh::GpuDraw> gpuDraws = toGpu(scene, items);
    draws = gpu::createBuffer(ctx, gpuDraws.data(), gpuDraws.size() * sizeof(sh::GpuDraw),
                              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "draws");
}

void SceneGpu::bindGeometry(VkCommandBuffer cmd, VkPipelineLayout layout) const {
    VkDescriptorSet set = textureTable->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, sh::SET_TEXTURES, 1, &set, 0, nullptr);
    VkDeviceSize offset = 0;
    VkBuffer vb = vertices.handle();
    vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
    vkCmdBindIndexBuffer(cmd, indices.handle(), 0, VK_INDEX_TYPE_UINT32);
}

void SceneGpu::updateDraws(const gpu::Context& ctx, const scene::Scene& scene,
                           const std::vector<scene::DrawItem>& items) {
    // Animation moves nodes but never adds or removes draws.
    if (items.size() != ranges.size())
        throw std::logic_error("SceneGpu::updateDraws: the number of draws changed");
    std::vector<sh::GpuDraw> gpuDraws = toGpu(scene, items);
    gpu::uploadBuffer(ctx, draws, gpuDraws.data(), gpuDraws.size() * sizeof(sh::GpuDraw));
    bounds = scene::worldBounds(scene, items);
    for (size_t i = 0; i < items.size(); ++i) drawWorld[i] = items[i].world;
}

}  // namespace dvsgi::gpuscene
