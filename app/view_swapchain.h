// The window's Vulkan swapchain for `dvsgi view`: creation, recreation on
// resize or vsync change, and presenting the renderer's output image: a small
// compute pass scales it by 2^EV and clamps to [0, 1] (shaders/view_present.comp),
// then a blit into an sRGB swapchain image applies the sRGB curve, i.e. the
// PNG preview's encoding.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/pipeline.h"
#include "gpu/resources.h"

namespace dvsgi::gpu {
class Context;
class Image;
}

namespace dvsgi::app {

class Swapchain {
public:
    Swapchain(const gpu::Context& ctx, VkSurfaceKHR surface);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // (Re)creates the swapchain for a framebuffer of width x height; vsync
    // picks FIFO, otherwise MAILBOX or IMMEDIATE when the surface offers them.
    void create(uint32_t width, uint32_t height, bool vsync);

    // Records drawing over the presented image inside renderPass() (the UI panel).
    using Overlay = std::function<void(VkCommandBuffer)>;

    // Acquires an image, copies `output` (RGBA32F, left in gpu::use::ComputeWrite
    // and returned to it) scaled to the swapchain size, runs `overlay` inside the
    // render pass on that image, and presents. Returns false when the swapchain
    // is out of date and must be recreated.
    bool present(const gpu::Image& output, float exposureEV, const Overlay& overlay = {});

    // One colour attachment, the swapchain format, loaded (the blit result) and
    // left in PRESENT_SRC. Created by the first create(); its format never changes.
    VkRenderPass renderPass() const { return renderPass_; }
    uint32_t imageCount() const { return uint32_t(images_.size()); }
    uint32_t minImageCount() const { return minImageCount_; }

    VkExtent2D extent() const { return extent_; }
    VkPresentModeKHR presentMode() const { return mode_; }
    const char* presentModeName() const;

private:
    void destroy();

    const gpu::Context& ctx_;
    VkSurfaceKHR surface_;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    std::vector<VkImage> images_;
    std::vector<VkImageView> views_;
    std::vector<VkFramebuffer> framebuffers_;
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    uint32_t minImageCount_ = 2;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{0, 0};
    VkPresentModeKHR mode_ = VK_PRESENT_MODE_FIFO_KHR;
    VkFence acquireFence_ = VK_NULL_HANDLE;
    gpu::Pipeline toneMap_;
    gpu::Image display_;  // tone-mapped output, RGBA32F, output size
};

}  // namespace dvsgi::app
