// The viewer's swapchain (VK_KHR_swapchain) on the context's window surface
// (PresentationRequest, context.h). A frame copies the displayed pixels (packed 8-bit, in the
// swapchain's byte order: bgra()) into the next swapchain image, lets the overlay record its
// drawing in a render pass over that image, and presents it; on request it reads the finished
// image back first (the window's content, for --screenshot).
#pragma once

#include "vulkan_rt/device/buffer.h"
#include "vulkan_rt/device/context.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

namespace tp {

class Presenter {
  public:
    // `width` x `height`: the displayed image, which the window's framebuffer matches.
    Presenter(const VulkanContext& ctx, uint32_t width, uint32_t height);
    ~Presenter();
    Presenter(const Presenter&) = delete;
    Presenter& operator=(const Presenter&) = delete;

    bool bgra() const { return bgra_; } // byte order of the swapchain's pixels
    VkRenderPass render_pass() const { return render_pass_; }
    uint32_t image_count() const { return uint32_t(images_.size()); }
    // Columns of a capture: the image's, or the window's if that is narrower.
    uint32_t shown_width() const { return std::min(width_, extent_.width); }

    // Presents `pixels` (width * height packed pixels) with `overlay` recorded inside the render
    // pass. With `capture`, the finished image as RGB8 rows, top down. False when the surface
    // is out of date (the window changed size): the swapchain is made again and the frame
    // skipped.
    bool present(const Buffer& pixels, const std::function<void(VkCommandBuffer)>& overlay,
                 std::vector<uint8_t>* capture = nullptr);

  private:
    void create_swapchain();
    void destroy_swapchain();

    const VulkanContext& ctx_;
    uint32_t width_, height_;
    VkSurfaceFormatKHR format_{};
    bool bgra_ = true;
    VkExtent2D extent_{};
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    std::vector<VkImage> images_;
    std::vector<VkImageView> views_;
    std::vector<VkFramebuffer> framebuffers_;
    VkRenderPass render_pass_ = VK_NULL_HANDLE;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    VkSemaphore acquired_ = VK_NULL_HANDLE, rendered_ = VK_NULL_HANDLE;
    VkFence done_ = VK_NULL_HANDLE;
};

} // namespace tp
