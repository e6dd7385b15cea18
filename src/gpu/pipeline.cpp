#include "gpu/pipeline.h"

#include "gpu/check.h"
#include "gpu/context.h"
#include "scene/scene.h"

namespace dvsgi::gpu {

namespace {

VkShaderModule makeModule(VkDevice device, Spirv code) {
    VkShaderModuleCreateInfo ci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    ci.codeSize = code.size_bytes();
    ci.pCode = code.data();
    VkShaderModule m;
    VK_CHECK(vkCreateShaderModule(device, &ci, nullptr, &m));
    return m;
}

VkPipelineShaderStageCreateInfo stage(VkShaderStageFlagBits s, VkShaderModule m) {
    VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage = s;
    info.module = m;
    info.pName = "main";
    return info;
}

}  // namespace

void Pipeline::createLayout(const LayoutDesc& desc) {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (const BindingDesc& b : desc.bindings)
        bindings.push_back({b.binding, b.type, b.count, b.stages, nullptr});
    VkDescriptorSetLayoutCreateInfo sci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    sci.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
    sci.bindingCount = uint32_t(bindings.size());
    sci.pBindings = bindings.data();
    VK_CHECK(vkCreateDescriptorSetLayout(device_, &sci, nullptr, &pushSet_));

    VkDescriptorSetLayout sets[2] = {pushSet_, desc.extraSet};
    VkPushConstantRange range{desc.pushConstantStages, 0, desc.pushConstantBytes};
    VkPipelineLayoutCreateInfo lci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    lci.setLayoutCount = desc.extraSet ? 2 : 1;
    lci.pSetLayouts = sets;
    lci.pushConstantRangeCount = desc.pushConstantBytes ? 1 : 0;
    lci.pPushConstantRanges = &range;
    VK_CHECK(vkCreatePipelineLayout(device_, &lci, nullptr, &layout_));
}

Pipeline::Pipeline(const Context& ctx, Spirv compute, const LayoutDesc& layout, const char*)
    : device_(ctx.device), bindPoint_(VK_PIPELINE_BIND_POINT_COMPUTE) {
    createLayout(layout);
    VkShaderModule module = makeModule(device_, compute);
    VkComputePipelineCreateInfo ci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    ci.stage = stage(VK_SHADER_STAGE_COMPUTE_BIT, module);
    ci.layout = layout_;
    VkResult r = vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &ci, nullptr, &pipeline_);
    vkDestroyShaderModule(device_, module, nullptr);
    VK_CHECK(r);
}

Pipeline::Pipeline(const Context& ctx, const GraphicsDesc& g, const LayoutDesc& layout, const char*)
    : device_(ctx.device), bindPoint_(VK_PIPELINE_BIND_POINT_GRAPHICS) {
    createLayout(layout);
    std::vector<VkShaderModule> modules;
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    auto add = [&](VkShaderStageFlagBits s, Spirv code) {
        if (code.empty()) return;
        modules.push_back(makeModule(device_, code));
        stages.push_back(stage(s, modules.back()));
    };
    add(VK_SHADER_STAGE_VERTEX_BIT, g.vertex);
    add(VK_SHADER_STAGE_GEOMETRY_BIT, g.geometry);
    add(VK_SHADER_STAGE_FRAGMENT_BIT, g.fragment);

    // scene::Vertex: position, normal, uv, tangent.
    VkVertexInputBindingDescription vb{0, sizeof(scene::Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
    VkVertexInputAttributeDescription va[4] = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, position)},
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, normal)},
        {2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv)},
        {3, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(scene::Vertex, tangent)},
    };
    VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    if (g.vertexInput) {
        vi.vertexBindingDescriptionCount = 1;
        vi.pVertexBindingDescriptions = &vb;
        vi.vertexAttributeDescriptionCount = 4;
        vi.pVertexAttributeDescriptions = va;
    }
    VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    vp.viewportCount = 1;
    vp.scissorCount = 1;

    VkPipelineRasterizationConservativeStateCreateInfoEXT cons{
        VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_CONSERVATIVE_STATE_CREATE_INFO_EXT};
    cons.conservativeRasterizationMode = VK_CONSERVATIVE_RASTERIZATION_MODE_OVERESTIMATE_EXT;
    VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    if (g.conservative) rs.pNext = &cons;
    rs.polygonMode = VK_POLYGON_MODE_FILL;
    rs.cullMode = g.cull;
    // glTF front faces are counter-clockwise; projections flip Y so this holds on screen.
    rs.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    rs.depthBiasEnable = g.depthBias;
    rs.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    ds.depthTestEnable = g.depthTest;
    ds.depthWriteEnable = g.depthWrite;
    ds.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    std::vector<VkPipelineColorBlendAttachmentState> blends(g.colorFormats.size());
    for (auto& b : blends) b.colorWriteMask = 0xF;
    VkPipelineColorBlendStateCreateInfo cb{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    cb.attachmentCount = uint32_t(blends.size());
    cb.pAttachments = blends.data();
    std::vector<VkDynamicState> dyn = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    if (g.depthBias) dyn.push_back(VK_DYNAMIC_STATE_DEPTH_BIAS);
    VkPipelineDynamicStateCreateInfo dy{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dy.dynamicStateCount = uint32_t(dyn.size());
    dy.pDynamicStates = dyn.data();
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = uint32_t(g.colorFormats.size());
    rendering.pColorAttachmentFormats = g.colorFormats.data();
    rendering.depthAttachmentFormat = g.depthFormat;

    VkGraphicsPipelineCreateInfo ci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    ci.pNext = &rendering;
    ci.stageCount = uint32_t(stages.size());
    ci.pStages = stages.data();
    ci.pVertexInputState = &vi;
    ci.pInputAssemblyState = &ia;
    ci.pViewportState = &vp;
    ci.pRasterizationState = &rs;
    ci.pMultisampleState = &ms;
    ci.pDepthStencilState = &ds;
    ci.pColorBlendState = &cb;
    ci.pDynamicState = &dy;
    ci.layout = layout_;
    VkResult r = vkCreateGraphicsPipelines(device_, VK_NULL_HANDLE, 1, &ci, nullptr, &pipeline_);
    for (VkShaderModule m : modules) vkDestroyShaderModule(device_, m, nullptr);
    VK_CHECK(r);
}

Pipeline& Pipeline::operator=(Pipeline&& o) noexcept {
    if (this != &o) {
        reset();
        device_ = std::exchange(o.device_, VK_NULL_HANDLE);
        pipeline_ = std::exchange(o.pipeline_, VK_NULL_HANDLE);
        layout_ = std::exchange(o.layout_, VK_NULL_HANDLE);
        pushSet_ = std::exchange(o.pushSet_, VK_NULL_HANDLE);
        bindPoint_ = o.bindPoint_;
    }
    return *this;
}

void Pipeline::reset() {
    if (!device_) return;
    if (pipeline_) vkDestroyPipeline(device_, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(device_, layout_, nullptr);
    if (pushSet_) vkDestroyDescriptorSetLayout(device_, pushSet_, nullptr);
    pipeline_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
    pushSet_ = VK_NULL_HANDLE;
}

Descriptors& Descriptors::storageImage(uint32_t binding, VkImageView view) {
    entries_.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, {{VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL}}, {}});
    return *this;
}

Descriptors& Descriptors::sampledImage(uint32_t binding, VkImageView view, VkSampler sampler, VkImageLayout layout) {
    entries_.push_back({binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, {{sampler, view, layout}}, {}});
    return *this;
}

Descriptors& Descriptors::storageBuffer(uint32_t binding, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range) {
    entries_.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, {}, {buffer, offset, range}});
    return *this;
}

Descriptors& Descriptors::uniformBuffer(uint32_t binding, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range) {
    entries_.push_back({binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, {}, {buffer, offset, range}});
    return *this;
}

void Descriptors::push(const Context& ctx, VkCommandBuffer cmd, const Pipeline& pipeline) const {
    std::vector<VkWriteDescriptorSet> writes;
    writes.reserve(entries_.size());
    for (const Entry& e : entries_) {
        VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstBinding = e.binding;
        w.descriptorType = e.type;
        const bool isBuffer =
            e.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER || e.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        w.descriptorCount = isBuffer ? 1 : uint32_t(e.images.size());
        if (isBuffer)
            w.pBufferInfo = &e.buffer;
        else
            w.pImageInfo = e.images.data();
        writes.push_back(w);
    }
    ctx.cmdPushDescriptorSet(cmd, pipeline.bindPoint(), pipeline.layout(), 0, uint32_t(writes.size()), writes.data());
}

void bind(VkCommandBuffer cmd, const Pipeline& pipeline) {
    vkCmdBindPipeline(cmd, pipeline.bindPoint(), pipeline.handle());
}

}  // namespace dvsgi::gpu
