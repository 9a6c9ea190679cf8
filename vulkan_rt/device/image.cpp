#include "vulkan_rt/device/image.h"

#include "vulkan_rt/device/buffer.h"
#include "vulkan_rt/device/vk_error.h"

#include <algorithm>
#include <cstring>
#include <utility>

namespace tp {

Image::Image(const VulkanContext& ctx, uint32_t width, uint32_t height, VkFormat format)
    : device_(ctx.device()), width_(width), height_(height) {
    try {
        VkImageCreateInfo ii{};
        ii.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
        ii.imageType = VK_IMAGE_TYPE_2D;
        ii.format = format;
        ii.extent = {width, height, 1};
        ii.mipLevels = 1;
        ii.arrayLayers = 1;
        ii.samples = VK_SAMPLE_COUNT_1_BIT;
        ii.tiling = VK_IMAGE_TILING_OPTIMAL;
        ii.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        ii.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        ii.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        vk_check(vkCreateImage(device_, &ii, nullptr, &image_), "creating an image");

        VkMemoryRequirements req;
        vkGetImageMemoryRequirements(device_, image_, &req);
        memory_bytes_ = req.size;
        VkMemoryAllocateInfo ai{};
        ai.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
        ai.allocationSize = req.size;
        ai.memoryTypeIndex =
            ctx.memory_type(req.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        vk_check(vkAllocateMemory(device_, &ai, nullptr, &memory_), "allocating image memory");
        tally_ = &ctx.memory_tally();
        tallied_ = ctx.counts_as_device_memory(ai.memoryTypeIndex) ? req.size : 0;
        tally_->add(tallied_);
        vk_check(vkBindImageMemory(device_, image_, memory_, 0), "binding image memory");

        VkImageViewCreateInfo vi{};
        vi.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
        vi.image = image_;
        vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
        vi.format = format;
        vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vk_check(vkCreateImageView(device_, &vi, nullptr, &view_), "creating an image view");
    } catch (...) {
        release();
        throw;
    }
}

Image::~Image() {
    release();
}

Image::Image(Image&& o) noexcept {
    *this = std::move(o);
}

Image& Image::operator=(Image&& o) noexcept {
    if (this != &o) {
        release();
        device_ = std::exchange(o.device_, VK_NULL_HANDLE);
        image_ = std::exchange(o.image_, VK_NULL_HANDLE);
        memory_ = std::exchange(o.memory_, VK_NULL_HANDLE);
        view_ = std::exchange(o.view_, VK_NULL_HANDLE);
        width_ = std::exchange(o.width_, 0);
        height_ = std::exchange(o.height_, 0);
        memory_bytes_ = std::exchange(o.memory_bytes_, 0);
        tally_ = std::exchange(o.tally_, nullptr);
        tallied_ = std::exchange(o.tallied_, 0);
    }
    return *this;
}

void Image::release() {
    if (!device_) return;
    if (view_) vkDestroyImageView(device_, view_, nullptr);
    if (image_) vkDestroyImage(device_, image_, nullptr);
    if (memory_) vkFreeMemory(device_, memory_, nullptr);
    if (tally_) tally_->remove(tallied_);
    tally_ = nullptr;
    tallied_ = 0;
    view_ = VK_NULL_HANDLE;
    image_ = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
}

namespace {

// Layout transitions of every image: to a copy destination before the first copy, to shader
// reads after the last.
void record_layouts(VkCommandBuffer cmd, const std::vector<ImageTexels>& images, bool to_shaders) {
    std::vector<VkImageMemoryBarrier> barriers;
    for (const ImageTexels& t : images) {
        VkImageMemoryBarrier b{};
        b.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
        b.srcAccessMask = to_shaders ? VK_ACCESS_TRANSFER_WRITE_BIT : 0;
        b.dstAccessMask = to_shaders ? VK_ACCESS_SHADER_READ_BIT : VK_ACCESS_TRANSFER_WRITE_BIT;
        b.oldLayout = to_shaders ? VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED;
        b.newLayout = to_shaders ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL
                                 : VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = t.image->handle();
        b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        barriers.push_back(b);
    }
    vkCmdPipelineBarrier(
        cmd, to_shaders ? VK_PIPELINE_STAGE_TRANSFER_BIT : VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
        to_shaders ? VK_PIPELINE_STAGE_ALL_COMMANDS_BIT : VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
        nullptr, 0, nullptr, uint32_t(barriers.size()), barriers.data());
}

} // namespace

void upload_images(const VulkanContext& ctx, const std::vector<ImageTexels>& images,
                   VkDeviceSize staging_bytes) {
    if (images.empty()) return;
    // Rows start at multiples of 16 bytes in the staging buffer (a multiple of every texel
    // size, as vkCmdCopyBufferToImage requires of bufferOffset).
    const auto aligned = [](VkDeviceSize n) { return (n + 15) & ~VkDeviceSize(15); };
    VkDeviceSize total = 0, widest = 0;
    for (const ImageTexels& t : images) {
        const VkDeviceSize row = VkDeviceSize(t.image->width()) * t.texel_bytes;
        total += aligned(row * t.image->height());
        widest = std::max(widest, aligned(row));
    }
    const Buffer staging(ctx, std::max(std::min(total, staging_bytes), widest),
                         VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
    struct Copy {
        VkImage image;
        VkBufferImageCopy region;
    };
    std::vector<Copy> copies;
    VkDeviceSize used = 0;
    bool first = true;
    // Submits the copies gathered in the staging buffer; the last submission also makes the
    // images readable by shaders.
    const auto submit = [&](bool last) {
        ctx.submit_and_wait([&](VkCommandBuffer cmd) {
            if (first) record_layouts(cmd, images, false);
            for (const Copy& c : copies)
                vkCmdCopyBufferToImage(cmd, staging.handle(), c.image,
                                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &c.region);
            if (last) record_layouts(cmd, images, true);
        });
        first = false;
        copies.clear();
        used = 0;
    };
    for (const ImageTexels& t : images) {
        const VkDeviceSize row = VkDeviceSize(t.image->width()) * t.texel_bytes;
        for (uint32_t y = 0; y < t.image->height();) {
            if (staging.size() - used < row) submit(false);
            const uint32_t rows = uint32_t(std::min<VkDeviceSize>(
                (staging.size() - used) / row, VkDeviceSize(t.image->height() - y)));
            std::memcpy(static_cast<uint8_t*>(staging.mapped()) + used,
                        static_cast<const uint8_t*>(t.data) + VkDeviceSize(y) * row, rows * row);
            VkBufferImageCopy region{};
            region.bufferOffset = used;
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageOffset = {0, int32_t(y), 0};
            region.imageExtent = {t.image->width(), rows, 1};
            copies.push_back({t.image->handle(), region});
            used = std::min(staging.size(), aligned(used + rows * row));
            y += rows;
        }
    }
    submit(true);
}

} // namespace tp
