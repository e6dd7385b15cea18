#include "view_swapchain.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "gpu/barriers.h"
#include "gpu/check.h"
#include "gpu/fault.h"
#include "gpu/context.h"
#include "gpu/resources.h"
#include "shared/present_pass.h"

namespace {
const uint32_t kPresentComp[] = {
#include "shaders/view_present.comp.inc"
};
}

namespace dvsgi::app {
namespace sh = dvsgi::shader;

namespace {

// Swapchain images: one colour mip and layer.
constexpr VkImageSubresourceRange kColour{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};

bool canBlit(VkPhysicalDevice pd, VkFormat f, VkFormatFeatureFlags need) {
    VkFormatProperties p;
    vkGetPhysicalDeviceFormatProperties(pd, f, &p);
    return (p.optimalTilingFeatures & need) == need;
}

}  // namespace

Swapchain::Swapchain(const gpu::Context& ctx, VkSurfaceKHR surface) : ctx_(ctx), surface_(surface) {
    VkBool32 supported = VK_FALSE;
    VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(ctx.physical, ctx.queueFamily, surface, &supported));
    if (!supported)
        throw gpu::GpuError(ctx.deviceName + " cannot present to this window from its queue",
                            VK_ERROR_FEATURE_NOT_PRESENT);
    if (!canBlit(ctx.physical, VK_FORMAT_R32G32B32A32_SFLOAT, VK_FORMAT_FEATURE_BLIT_SRC_BIT))
        throw gpu::GpuError(ctx.deviceName + " cannot blit from RGBA32F images", VK_ERROR_FORMAT_NOT_SUPPORTED);
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_PRESENT_RADIANCE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT},
                       {sh::BIND_PRESENT_DISPLAY, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT}};
    layout.pushConstantBytes = sizeof(sh::PresentPush);
    layout.pushConstantStages = VK_SHADER_STAGE_COMPUTE_BIT;
    toneMap_ = gpu::Pipeline(ctx, gpu::Spirv(kPresentComp), layout, "view tone map");
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(ctx.device, &fi, nullptr, &acquireFence_));
}

Swapchain::~Swapchain() {
    vkDeviceWaitIdle(ctx_.device);
    destroy();
    if (swapchain_) vkDestroySwapchainKHR(ctx_.device, swapchain_, nullptr);
    if (renderPass_) vkDestroyRenderPass(ctx_.device, renderPass_, nullptr);
    if (acquireFence_) vkDestroyFence(ctx_.device, acquireFence_, nullptr);
}

// The per-image objects; the swapchain itself is retired by create().
void Swapchain::destroy() {
    for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(ctx_.device, f, nullptr);
    for (VkImageView v : views_) vkDestroyImageView(ctx_.device, v, nullptr);
    framebuffers_.clear();
    views_.clear();
    images_.clear();
}

const char* Swapchain::presentModeName() const {
    switch (mode_) {
        case VK_PRESENT_MODE_FIFO_KHR: return "fifo (vsync)";
        case VK_PRESENT_MODE_MAILBOX_KHR: return "mailbox";
        case VK_PRESENT_MODE_IMMEDIATE_KHR: return "immediate";
        default: return "other";
    }
}

void Swapchain::create(uint32_t width, uint32_t height, bool vsync) {
    vkDeviceWaitIdle(ctx_.device);
    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_.physical, surface_, &caps));

    uint32_t n = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(ctx_.physical, surface_, &n, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(n);
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(ctx_.physical, surface_, &n, formats.data()));
    // An sRGB format lets the blit apply the sRGB curve; UNORM would show
    // linear values (too dark), so it is only the last resort.
    const VkFormat preferred[] = {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_A8B8G8R8_SRGB_PACK32};
    VkSurfaceFormatKHR chosen{VK_FORMAT_UNDEFINED, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR};
    for (VkFormat want : preferred)
        for (const VkSurfaceFormatKHR& f : formats)
            if (chosen.format == VK_FORMAT_UNDEFINED && f.format == want &&
                f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR &&
                canBlit(ctx_.physical, f.format, VK_FORMAT_FEATURE_BLIT_DST_BIT))
                chosen = f;
    if (chosen.format == VK_FORMAT_UNDEFINED) {
        for (const VkSurfaceFormatKHR& f : formats)
            if (chosen.format == VK_FORMAT_UNDEFINED &&
                canBlit(ctx_.physical, f.format, VK_FORMAT_FEATURE_BLIT_DST_BIT))
                chosen = f;
    }
    if (chosen.format == VK_FORMAT_UNDEFINED)
        throw gpu::GpuError("the window offers no swapchain format dvsgi can blit to", VK_ERROR_FORMAT_NOT_SUPPORTED);
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw gpu::GpuError("the window's swapchain images cannot be transfer destinations",
                            VK_ERROR_FEATURE_NOT_PRESENT);

    std::vector<VkPresentModeKHR> modes;
    VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(ctx_.physical, surface_, &n, nullptr));
    modes.resize(n);
    VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(ctx_.physical, surface_, &n, modes.data()));
    mode_ = VK_PRESENT_MODE_FIFO_KHR;  // always available
    if (!vsync) {
        for (VkPresentModeKHR m : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
            if (mode_ == VK_PRESENT_MODE_FIFO_KHR && std::find(modes.begin(), modes.end(), m) != modes.end())
                mode_ = m;
    }

    if (caps.currentExtent.width != UINT32_MAX) {
        extent_ = caps.currentExtent;
    } else {
        extent_.width = std::clamp(width, caps.minImageExtent.width, caps.maxImageExtent.width);
        extent_.height = std::clamp(height, caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    // A minimized window has a zero extent, for which no swapchain may be
    // created: keep the old one; present() skips frames until the next resize.
    if (extent_.width == 0 || extent_.height == 0) return;
    if (renderPass_ && format_ != chosen.format)
        throw gpu::GpuError("the window's swapchain format changed", VK_ERROR_FORMAT_NOT_SUPPORTED);
    uint32_t count = std::max(caps.minImageCount + 1, 2u);
    if (caps.maxImageCount > 0) count = std::min(count, caps.maxImageCount);

    VkSwapchainCreateInfoKHR ci{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    ci.surface = surface_;
    ci.minImageCount = count;
    ci.imageFormat = chosen.format;
    ci.imageColorSpace = chosen.colorSpace;
    ci.imageExtent = extent_;
    ci.imageArrayLayers = 1;
    ci.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    ci.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    ci.preTransform = (caps.supportedTransforms & VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR)
                          ? VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR
                          : caps.currentTransform;
    ci.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                            ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                            : VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);
    ci.presentMode = mode_;
    ci.clipped = VK_TRUE;
    ci.oldSwapchain = swapchain_;
    VkSwapchainKHR fresh = VK_NULL_HANDLE;
    VkResult r = gpu::fault::swapchain();
    if (r == VK_SUCCESS) r = vkCreateSwapchainKHR(ctx_.device, &ci, nullptr, &fresh);
    if (r != VK_SUCCESS)
        throw gpu::GpuError("--width " + std::to_string(width) + " --height " + std::to_string(height) +
                                ": the window's swapchain (" + std::to_string(extent_.width) + "x" +
                                std::to_string(extent_.height) + ", " + std::to_string(count) + " images, " +
                                presentModeName() + ") could not be created on " + ctx_.deviceName + ": " +
                                gpu::resultName(r),
                            r);
    destroy();
    if (swapchain_) vkDestroySwapchainKHR(ctx_.device, swapchain_, nullptr);
    swapchain_ = fresh;
    minImageCount_ = std::max(caps.minImageCount, 2u);
    format_ = chosen.format;
    VK_CHECK(vkGetSwapchainImagesKHR(ctx_.device, swapchain_, &n, nullptr));
    images_.resize(n);
    VK_CHECK(vkGetSwapchainImagesKHR(ctx_.device, swapchain_, &n, images_.data()));

    if (!renderPass_) {
        VkAttachmentDescription a{};
        a.format = format_;
        a.samples = VK_SAMPLE_COUNT_1_BIT;
        a.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        a.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        a.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
        VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
        VkSubpassDescription sub{};
        sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
        sub.colorAttachmentCount = 1;
        sub.pColorAttachments = &ref;
        VkSubpassDependency dep{};
        dep.srcSubpass = VK_SUBPASS_EXTERNAL;
        dep.dstSubpass = 0;
        dep.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
        dep.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
        dep.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
        dep.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
        VkRenderPassCreateInfo rp{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
        rp.attachmentCount = 1;
        rp.pAttachments = &a;
        rp.subpassCount = 1;
        rp.pSubpasses = &sub;
        rp.dependencyCount = 1;
        rp.pDependencies = &dep;
        VK_CHECK(vkCreateRenderPass(ctx_.device, &rp, nullptr, &renderPass_));
    }
    for (VkImage image : images_) {
        VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        vi.image = image;
        vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
        vi.format = format_;
        vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView view = VK_NULL_HANDLE;
        VK_CHECK(vkCreateImageView(ctx_.device, &vi, nullptr, &view));
        views_.push_back(view);
        VkFramebufferCreateInfo fi{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        fi.renderPass = renderPass_;
        fi.attachmentCount = 1;
        fi.pAttachments = &view;
        fi.width = extent_.width;
        fi.height = extent_.height;
        fi.layers = 1;
        VkFramebuffer fb = VK_NULL_HANDLE;
        VK_CHECK(vkCreateFramebuffer(ctx_.device, &fi, nullptr, &fb));
        framebuffers_.push_back(fb);
    }
}

bool Swapchain::present(const gpu::Image& output, float exposureEV, const Overlay& overlay) {
    if (extent_.width == 0 || extent_.height == 0) return true;  // minimized
    uint32_t index = 0;
    // Acquire with a fence and wait for it: the copy below is then ordered
    // after the presentation engine released the image without semaphores.
    VkResult r = vkAcquireNextImageKHR(ctx_.device, swapchain_, UINT64_MAX, VK_NULL_HANDLE, acquireFence_, &index);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) return false;
    if (r != VK_SUCCESS && r != VK_SUBOPTIMAL_KHR) gpu::throwVkError("vkAcquireNextImageKHR", r);
    VK_CHECK(vkWaitForFences(ctx_.device, 1, &acquireFence_, VK_TRUE, UINT64_MAX));
    VK_CHECK(vkResetFences(ctx_.device, 1, &acquireFence_));
    const bool suboptimal = r == VK_SUBOPTIMAL_KHR;

    const VkImage target = images_[index];
    const VkExtent3D src = output.desc().extent;
    if (!display_ || display_.desc().extent.width != src.width || display_.desc().extent.height != src.height) {
        gpu::ImageDesc d;
        d.format = VK_FORMAT_R32G32B32A32_SFLOAT;
        d.extent = {src.width, src.height, 1};
        d.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        d.name = "view display";
        display_ = gpu::Image(ctx_, d);
    }
    ctx_.submitAndWait([&](VkCommandBuffer cmd) {
        // The renderer's compute writes to `output` are complete (its frame
        // was waited for); read it in place, GENERAL layout, as storage.
        gpu::storageWritesVisible(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
        gpu::transition(cmd, display_, gpu::use::Undefined, gpu::use::ComputeWrite);
        gpu::bind(cmd, toneMap_);
        gpu::Descriptors().storageImage(sh::BIND_PRESENT_RADIANCE, output.view())
            .storageImage(sh::BIND_PRESENT_DISPLAY, display_.view())
            .push(ctx_, cmd, toneMap_);
        const sh::PresentPush push{glm::vec4(float(src.width), float(src.height), std::exp2(exposureEV), 0.0f)};
        gpu::pushConstants(cmd, toneMap_, VK_SHADER_STAGE_COMPUTE_BIT, push);
        vkCmdDispatch(cmd, gpu::groupCount(src.width, shader::PRESENT_GROUP), gpu::groupCount(src.height, shader::PRESENT_GROUP), 1);
        gpu::transition(cmd, display_, gpu::use::ComputeWrite, gpu::use::TransferSrc);
        gpu::transition(cmd, target, kColour, gpu::use::Undefined, gpu::use::TransferDst);
        VkImageBlit blit{};
        blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        blit.srcOffsets[1] = {int32_t(src.width), int32_t(src.height), 1};
        blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        blit.dstOffsets[1] = {int32_t(extent_.width), int32_t(extent_.height), 1};
        vkCmdBlitImage(cmd, display_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_NEAREST);
        gpu::transition(cmd, target, kColour, gpu::use::TransferDst, gpu::use::ColorAttachment);
        // The render pass leaves the image in PRESENT_SRC, with or without an overlay.
        VkRenderPassBeginInfo rb{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        rb.renderPass = renderPass_;
        rb.framebuffer = framebuffers_[index];
        rb.renderArea.extent = extent_;
        vkCmdBeginRenderPass(cmd, &rb, VK_SUBPASS_CONTENTS_INLINE);
        if (overlay) overlay(cmd);
        vkCmdEndRenderPass(cmd);
    });

    VkPresentInfoKHR pi{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    pi.swapchainCount = 1;
    pi.pSwapchains = &swapchain_;
    pi.pImageIndices = &index;
    r = vkQueuePresentKHR(ctx_.queue, &pi);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) return false;
    if (r != VK_SUCCESS && r != VK_SUBOPTIMAL_KHR) gpu::throwVkError("vkQueuePresentKHR", r);
    return !(suboptimal || r == VK_SUBOPTIMAL_KHR);
}

}  // namespace dvsgi::app
