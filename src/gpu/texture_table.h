// A long-lived descriptor set holding a fixed-size array of sampled images
// (the scene's textures) at `binding` and one sampler at `binding + 1`. Unused slots point at a fallback image,
// since lavapipe offers neither runtime arrays nor partially bound sets.
#pragma once

#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

namespace dvsgi::gpu {

class Context;

class TextureTable {
public:
    TextureTable(const Context& ctx, uint32_t capacity, uint32_t binding, VkShaderStageFlags stages);
    ~TextureTable();
    TextureTable(const TextureTable&) = delete;
    TextureTable& operator=(const TextureTable&) = delete;

    // views.size() <= capacity; the rest of the table gets `fallback`.
    void write(const std::vector<VkImageView>& views, VkImageView fallback, VkSampler sampler);
    VkDescriptorSetLayout layout() const { return layout_; }
    VkDescriptorSet set() const { return set_; }
    uint32_t capacity() const { return capacity_; }

private:
    VkDevice device_;
    uint32_t capacity_, binding_;
    VkDescriptorSetLayout layout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace dvsgi::gpu
