#include "gpu/texture_table.h"

#include "gpu/check.h"
#include "gpu/context.h"

namespace dvsgi::gpu {

TextureTable::TextureTable(const Context& ctx, uint32_t capacity, uint32_t binding, VkShaderStageFlags stages)
    : device_(ctx.device), capacity_(capacity), binding_(binding) {
    // Separate images and one sampler: combined samplers are capped at 32 per stage on lavapipe.
    VkDescriptorSetLayoutBinding b[2] = {{binding, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, capacity, stages, nullptr},
                                         {binding + 1, VK_DESCRIPTOR_TYPE_SAMPLER, 1, stages, nullptr}};
    VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    lci.bindingCount = 2;
    lci.pBindings = b;
    VK_CHECK(vkCreateDescriptorSetLayout(device_, &lci, nullptr, &layout_));
    VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, capacity}, {VK_DESCRIPTOR_TYPE_SAMPLER, 1}};
    VkDescriptorPoolCreateInfo pci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pci.maxSets = 1;
    pci.poolSizeCount = 2;
    pci.pPoolSizes = sizes;
    VK_CHECK(vkCreateDescriptorPool(device_, &pci, nullptr, &pool_));
    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = pool_;
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &layout_;
    VK_CHECK(vkAllocateDescriptorSets(device_, &ai, &set_));
}

TextureTable::~TextureTable() {
    vkDestroyDescriptorPool(device_, pool_, nullptr);
    vkDestroyDescriptorSetLayout(device_, layout_, nullptr);
}

void TextureTable::write(const std::vector<VkImageView>& views, VkImageView fallback, VkSampler sampler) {
    std::vector<VkDescriptorImageInfo> infos(capacity_);
    for (uint32_t i = 0; i < capacity_; ++i)
        infos[i] = {VK_NULL_HANDLE, i < views.size() ? views[i] : fallback, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkDescriptorImageInfo samplerInfo{sampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED};
    VkWriteDescriptorSet w[2] = {{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}, {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}};
    w[0].dstSet = set_;
    w[0].dstBinding = binding_;
    w[0].descriptorCount = capacity_;
    w[0].descriptorType = VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    w[0].pImageInfo = infos.data();
    w[1].dstSet = set_;
    w[1].dstBinding = binding_ + 1;
    w[1].descriptorCount = 1;
    w[1].descriptorType = VK_DESCRIPTOR_TYPE_SAMPLER;
    w[1].pImageInfo = &samplerInfo;
    vkUpdateDescriptorSets(device_, 2, w, 0, nullptr);
}

}  // namespace dvsgi::gpu
