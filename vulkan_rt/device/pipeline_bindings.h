// Descriptor set 0 and the push constants of one pipeline, compute or ray tracing: the set
// layout, the pipeline layout, a pool and the one set, and the binding of it all before a
// dispatch or a trace.
#pragma once

#include "vulkan_rt/device/buffer.h"
#include "vulkan_rt/device/context.h"

#include <cstdint>
#include <vector>

namespace tp {

struct BindingSlot {
    uint32_t binding;
    VkDescriptorType type; // storage buffer, sampled image or acceleration structure
    uint32_t count = 1;    // descriptors: an array of sampled images has several
};

// Slots 0 .. count - 1, all storage buffers.
std::vector<BindingSlot> storage_slots(uint32_t count);

class PipelineBindings {
  public:
    // Every slot is visible to `stages`, and so are `push_bytes` bytes of push constants.
    PipelineBindings(const VulkanContext& ctx, const std::vector<BindingSlot>& slots,
                     VkShaderStageFlags stages, uint32_t push_bytes);
    ~PipelineBindings();
    PipelineBindings(const PipelineBindings&) = delete;
    PipelineBindings& operator=(const PipelineBindings&) = delete;

    VkPipelineLayout layout() const { return layout_; }

    // Points a storage-buffer slot at the whole of `buffer`; RuntimeError when that exceeds the
    // device's maxStorageBufferRange.
    void write_buffer(uint32_t binding, const Buffer& buffer);
    void write_acceleration_structure(uint32_t binding, VkAccelerationStructureKHR tlas);
    // Points the sampled images of slot `binding`, from its first, at `views` (in
    // VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL).
    void write_images(uint32_t binding, const std::vector<VkImageView>& views);

    // Binds the set at `bind_point` and pushes the constants.
    void record_bind(VkCommandBuffer cmd, VkPipelineBindPoint bind_point, const void* push) const;

  private:
    void release();
    const VulkanContext& ctx_;
    VkShaderStageFlags stages_;
    uint32_t push_bytes_;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
};

} // namespace tp
