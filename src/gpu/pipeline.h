// Shader pipelines. Every pass binds its resources through one push-descriptor
// set (set 0), described by a list of bindings whose numbers come from the
// shared headers in shaders/shared/. An optional second set (set 1) carries
// long-lived tables such as the scene's texture array.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

namespace dvsgi::gpu {

class Context;

using Spirv = std::span<const uint32_t>;

struct BindingDesc {
    uint32_t binding;
    VkDescriptorType type;
    VkShaderStageFlags stages;
    uint32_t count = 1;
};

struct LayoutDesc {
    std::vector<BindingDesc> bindings;               // set 0, push descriptors
    VkDescriptorSetLayout extraSet = VK_NULL_HANDLE; // set 1, not owned
    uint32_t pushConstantBytes = 0;
    VkShaderStageFlags pushConstantStages = 0;
};

struct GraphicsDesc {
    Spirv vertex;
    Spirv geometry;  // optional
    Spirv fragment;  // optional (depth-only passes may omit it)
    std::vector<VkFormat> colorFormats;
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;
    bool depthTest = true;
    bool depthWrite = true;
    VkCullModeFlags cull = VK_CULL_MODE_NONE;
    bool depthBias = false;          // dynamic depth bias (shadow maps)
    bool vertexInput = true;         // scene::Vertex attributes at locations 0..3
    bool conservative = false;       // VK_EXT_conservative_rasterization, overestimate
};

class Pipeline {
public:
    Pipeline() = default;
    Pipeline(const Context& ctx, Spirv compute, const LayoutDesc& layout, const char* name);
    Pipeline(const Context& ctx, const GraphicsDesc& graphics, const LayoutDesc& layout, const char* name);
    ~Pipeline() { reset(); }
    Pipeline(Pipeline&& o) noexcept { *this = std::move(o); }
    Pipeline& operator=(Pipeline&& o) noexcept;
    Pipeline(const Pipeline&) = delete;
    Pipeline& operator=(const Pipeline&) = delete;

    VkPipeline handle() const { return pipeline_; }
    VkPipelineLayout layout() const { return layout_; }
    VkPipelineBindPoint bindPoint() const { return bindPoint_; }
    void reset();

private:
    void createLayout(const LayoutDesc& desc);
    VkDevice device_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout pushSet_ = VK_NULL_HANDLE;
    VkPipelineBindPoint bindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
};

// Collects descriptor writes for one pass and pushes them as set 0.
class Descriptors {
public:
    Descriptors& storageImage(uint32_t binding, VkImageView view);
    Descriptors& sampledImage(uint32_t binding, VkImageView view, VkSampler sampler,
                              VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    Descriptors& storageBuffer(uint32_t binding, VkBuffer buffer, VkDeviceSize offset = 0,
                               VkDeviceSize range = VK_WHOLE_SIZE);
    Descriptors& uniformBuffer(uint32_t binding, VkBuffer buffer, VkDeviceSize offset = 0,
                               VkDeviceSize range = VK_WHOLE_SIZE);
    void push(const Context& ctx, VkCommandBuffer cmd, const Pipeline& pipeline) const;

private:
    struct Entry {
        uint32_t binding;
        VkDescriptorType type;
        std::vector<VkDescriptorImageInfo> images;  // one per array element
        VkDescriptorBufferInfo buffer;
    };
    std::vector<Entry> entries_;
};

void bind(VkCommandBuffer cmd, const Pipeline& pipeline);

template <typename T>
void pushConstants(VkCommandBuffer cmd, const Pipeline& pipeline, VkShaderStageFlags stages, const T& value) {
    vkCmdPushConstants(cmd, pipeline.layout(), stages, 0, sizeof(T), &value);
}

inline uint32_t groupCount(uint32_t n, uint32_t groupSize) { return (n + groupSize - 1) / groupSize; }

}  // namespace dvsgi::gpu
