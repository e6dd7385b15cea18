// The window's Vulkan swapchain for `dvsgi view`: creation, recreation on
// resize or vsync change, and presenting the renderer's output image by a
// blit into an sRGB swapchain image (the blit clamps to [0, 1] and applies the
// sRGB curve, i.e. the PNG preview's encoding at 0 EV).
#pragma once

#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

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

    // Acquires an image, copies `output` (RGBA32F, left in gpu::use::ComputeWrite
    // and returned to it) scaled to the swapchain size, and presents. Returns
    // false when the swapchain is out of date and must be recreated.
    bool present(const gpu::Image& output);

    VkExtent2D extent() const { return extent_; }
    VkPresentModeKHR presentMode() const { return mode_; }
    const char* presentModeName() const;

private:
    void destroy();

    const gpu::Context& ctx_;
    VkSurfaceKHR surface_;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    std::vector<VkImage> images_;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{0, 0};
    VkPresentModeKHR mode_ = VK_PRESENT_MODE_FIFO_KHR;
    VkFence acquireFence_ = VK_NULL_HANDLE;
};

}  // namespace dvsgi::app
