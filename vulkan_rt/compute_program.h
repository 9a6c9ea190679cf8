// A compute pipeline from embedded SPIR-V whose descriptor set 0 is `binding_count` storage
// buffers (bindings 0..n-1) and whose push constants are one block of `push_bytes` bytes.
#pragma once

#include "vulkan_rt/context.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tp {

class ComputeProgram {
  public:
    ComputeProgram(const VulkanContext& ctx, const uint32_t* spirv, size_t spirv_bytes,
                   uint32_t binding_count, uint32_t push_bytes);
    ~ComputeProgram();
    ComputeProgram(const ComputeProgram&) = delete;
    ComputeProgram& operator=(const ComputeProgram&) = delete;

    // Points binding i at the whole of buffers[i].
    void bind(const std::vector<VkBuffer>& buffers);

    // Binds the pipeline and the set, pushes the constants and dispatches.
    void record_dispatch(VkCommandBuffer cmd, const void* push, uint32_t groups_x,
                         uint32_t groups_y, uint32_t groups_z) const;

  private:
    VkDevice device_;
    uint32_t binding_count_;
    uint32_t push_bytes_;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    void release();
};

// Makes every shader write before it visible to every shader read or write after it, and to
// transfers (the read-back copy).
void record_compute_barrier(VkCommandBuffer cmd);

// Makes transfer writes (a read-back copy) visible to the host once the submission completes.
void record_host_read_barrier(VkCommandBuffer cmd);

} // namespace tp
