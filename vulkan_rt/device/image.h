// 2D images in device-local memory (one allocation each), optimal tiling, for shaders to read
// with texelFetch, and their upload through a bounded staging buffer.
#pragma once

#include "vulkan_rt/device/context.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tp {

class Image {
  public:
    Image() = default;
    // A width x height image of `format`, usable as a sampled image and a copy destination,
    // with a view of all of it. Throws RuntimeError (vk_error.h) when the device refuses it.
    Image(const VulkanContext& ctx, uint32_t width, uint32_t height, VkFormat format);
    ~Image();
    Image(Image&& o) noexcept;
    Image& operator=(Image&& o) noexcept;

    VkImage handle() const { return image_; }
    VkImageView view() const { return view_; }
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    VkDeviceSize memory_bytes() const { return memory_bytes_; }

  private:
    void release();
    VkDevice device_ = VK_NULL_HANDLE;
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkImageView view_ = VK_NULL_HANDLE;
    uint32_t width_ = 0, height_ = 0;
    VkDeviceSize memory_bytes_ = 0;
    MemoryTally* tally_ = nullptr;
    VkDeviceSize tallied_ = 0; // memory_bytes_ when it counts as device memory, else 0
};

// An image's texels on the host: rows top to bottom, tightly packed, `texel_bytes` each.
struct ImageTexels {
    const Image* image;
    const void* data;
    uint32_t texel_bytes;
};

// Copies every image's texels into it through one host-visible staging buffer of at most
// `staging_bytes` (whole rows; an image larger than that goes in several submissions), and
// leaves the images in VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, visible to every shader read.
void upload_images(const VulkanContext& ctx, const std::vector<ImageTexels>& images,
                   VkDeviceSize staging_bytes = VkDeviceSize(64) << 20);

} // namespace tp
