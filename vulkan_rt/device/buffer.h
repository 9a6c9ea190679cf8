// Vulkan buffers with their own memory (one allocation each: a render has ~20 buffers, far
// below maxMemoryAllocationCount), and staged uploads: data goes through a host-visible
// staging buffer into device-local memory with one copy submission for many buffers.
#pragma once

#include "vulkan_rt/device/context.h"

#include <cstddef>
#include <vector>

namespace tp {

class Buffer {
  public:
    Buffer() = default;
    // `host` buffers are host-visible and coherent and stay mapped; the others prefer
    // device-local memory. Size 0 is rounded up to 16 bytes: Vulkan has no empty buffers.
    // With VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT (pipeline mode only: it needs the
    // bufferDeviceAddress feature) the memory is allocated for device addresses.
    Buffer(const VulkanContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage, bool host);
    ~Buffer();
    Buffer(Buffer&& o) noexcept;
    Buffer& operator=(Buffer&& o) noexcept;

    VkBuffer handle() const { return buffer_; }
    VkDeviceSize size() const { return size_; }
    void* mapped() const { return mapped_; }
    // vkGetBufferDeviceAddress; the buffer needs VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT.
    VkDeviceAddress device_address() const;

  private:
    void release();
    VkDevice device_ = VK_NULL_HANDLE;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize size_ = 0;
    void* mapped_ = nullptr;
    MemoryTally* tally_ = nullptr;
    VkDeviceSize tallied_ = 0; // the allocation's bytes in tally_ (0: not device memory)
};

// Collects uploads and performs them with one command buffer on flush().
class Uploader {
  public:
    explicit Uploader(const VulkanContext& ctx) : ctx_(ctx) {}

    // A device-local storage buffer that will hold `bytes` bytes of `data` after flush().
    Buffer add(const void* data, size_t bytes, VkBufferUsageFlags usage);
    template <typename T>
    Buffer add(const std::vector<T>& v, VkBufferUsageFlags usage) {
        return add(v.data(), v.size() * sizeof(T), usage);
    }

    // Writes `bytes` bytes of `data` at `offset` into an existing buffer (with
    // VK_BUFFER_USAGE_TRANSFER_DST_BIT) on flush().
    void add_to(const Buffer& dst, VkDeviceSize offset, const void* data, size_t bytes);

    void flush();

  private:
    struct Pending {
        Buffer staging;
        VkBuffer dst;
        VkDeviceSize offset;
        VkDeviceSize bytes;
    };
    const VulkanContext& ctx_;
    std::vector<Pending> pending_;
};

} // namespace tp
