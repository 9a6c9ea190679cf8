#include "vulkan_rt/device/buffer.h"

#include "vulkan_rt/device/vk_error.h"

#include <cstring>
#include <utility>

namespace tp {

Buffer::Buffer(const VulkanContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage, bool host)
    : device_(ctx.device()), size_(size > 0 ? size : 16) {
    try {
        VkBufferCreateInfo bi{};
        bi.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
        bi.size = size_;
        bi.usage = usage;
        bi.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        vk_check(vkCreateBuffer(device_, &bi, nullptr, &buffer_), "creating a buffer");

        VkMemoryRequirements req;
        vkGetBufferMemoryRequirements(device_, buffer_, &req);
        const VkMemoryPropertyFlags required =
            host ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT : 0;
        const VkMemoryPropertyFlags preferred =
            host ? VK_MEMORY_PROPERTY_HOST_CACHED_BIT : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
        VkMemoryAllocateFlagsInfo flags{};
        flags.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO;
        flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
        VkMemoryAllocateInfo ai{};
        ai.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
        ai.pNext = (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) ? &flags : nullptr;
        ai.allocationSize = req.size;
        ai.memoryTypeIndex = ctx.memory_type(req.memoryTypeBits, required, preferred);
        vk_check(vkAllocateMemory(device_, &ai, nullptr, &memory_), "allocating buffer memory");
        tally_ = &ctx.memory_tally();
        tallied_ = ctx.counts_as_device_memory(ai.memoryTypeIndex) ? req.size : 0;
        tally_->add(tallied_);
        vk_check(vkBindBufferMemory(device_, buffer_, memory_, 0), "binding buffer memory");
        if (host)
            vk_check(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_),
                     "mapping buffer memory");
    } catch (...) {
        release();
        throw;
    }
}

Buffer::~Buffer() {
    release();
}

Buffer::Buffer(Buffer&& o) noexcept {
    *this = std::move(o);
}

Buffer& Buffer::operator=(Buffer&& o) noexcept {
    if (this != &o) {
        release();
        device_ = std::exchange(o.device_, VK_NULL_HANDLE);
        buffer_ = std::exchange(o.buffer_, VK_NULL_HANDLE);
        memory_ = std::exchange(o.memory_, VK_NULL_HANDLE);
        size_ = std::exchange(o.size_, 0);
        mapped_ = std::exchange(o.mapped_, nullptr);
        tally_ = std::exchange(o.tally_, nullptr);
        tallied_ = std::exchange(o.tallied_, 0);
    }
    return *this;
}

void Buffer::release() {
    if (!device_) return;
    if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
    if (memory_) vkFreeMemory(device_, memory_, nullptr); // also unmaps
    if (tally_) tally_->remove(tallied_);
    tally_ = nullptr;
    tallied_ = 0;
    buffer_ = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
    mapped_ = nullptr;
}

VkDeviceAddress Buffer::device_address() const {
    VkBufferDeviceAddressInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO;
    info.buffer = buffer_;
    return vkGetBufferDeviceAddress(device_, &info);
}

Buffer Uploader::add(const void* data, size_t bytes, VkBufferUsageFlags usage) {
    Buffer dst(ctx_, bytes, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false);
    add_to(dst, 0, data, bytes);
    return dst;
}

void Uploader::add_to(const Buffer& dst, VkDeviceSize offset, const void* data, size_t bytes) {
    if (bytes == 0) return;
    Buffer staging(ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
    std::memcpy(staging.mapped(), data, bytes);
    pending_.push_back({std::move(staging), dst.handle(), offset, VkDeviceSize(bytes)});
}

void Uploader::flush() {
    if (pending_.empty()) return;
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        for (const Pending& p : pending_) {
            VkBufferCopy region{0, p.offset, p.bytes};
            vkCmdCopyBuffer(cmd, p.staging.handle(), p.dst, 1, &region);
        }
        // Make the copies visible to every later shader read (acceleration-structure builds
        // read their inputs with VK_ACCESS_SHADER_READ_BIT too).
        VkMemoryBarrier barrier{};
        barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
        barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                             VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &barrier, 0, nullptr, 0,
                             nullptr);
    });
    pending_.clear();
}

} // namespace tp
