// A compute pipeline from embedded SPIR-V whose descriptor set 0 has the given slots (or
// `binding_count` storage buffers, bindings 0..n-1) and whose push constants are one block of
// `push_bytes` bytes.
// Render shaders get their specialization constants (specialization.h) and
// are compiled through the on-disk pipeline cache (pipeline_cache.h). The driver's report on the
// pipeline (creation feedback, statistics on request) is kept (pipeline_report.h).
#pragma once

#include "render/stats.h"
#include "vulkan_rt/device/barriers.h"
#include "vulkan_rt/device/buffer.h"
#include "vulkan_rt/device/context.h"
#include "vulkan_rt/device/pipeline_bindings.h"
#include "vulkan_rt/device/pipeline_cache.h"
#include "vulkan_rt/device/specialization.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tp {

class ComputeProgram {
  public:
    // Specialized to `constants` (specialization.h; a shader without them ignores them) and,
    // when `cached` (the render shaders), compiled through the pipeline cache on disk.
    ComputeProgram(const VulkanContext& ctx, const uint32_t* spirv, size_t spirv_bytes,
                   const std::vector<BindingSlot>& slots, uint32_t push_bytes,
                   const RenderConstants& constants, bool cached);
    ComputeProgram(const VulkanContext& ctx, const uint32_t* spirv, size_t spirv_bytes,
                   uint32_t binding_count, uint32_t push_bytes, const RenderConstants& constants,
                   bool cached)
        : ComputeProgram(ctx, spirv, spirv_bytes, storage_slots(binding_count), push_bytes,
                         constants, cached) {}
    ~ComputeProgram();
    ComputeProgram(const ComputeProgram&) = delete;
    ComputeProgram& operator=(const ComputeProgram&) = delete;

    // Points storage-buffer slot `binding` at the whole of `buffer`.
    void bind(uint32_t binding, const Buffer& buffer) { bindings_.write_buffer(binding, buffer); }
    // Points the sampled images of slot `binding` at `views`.
    void bind_images(uint32_t binding, const std::vector<VkImageView>& views) {
        bindings_.write_images(binding, views);
    }

    // Binds the pipeline and the set, pushes the constants and dispatches.
    void record_dispatch(VkCommandBuffer cmd, const void* push, uint32_t groups_x,
                         uint32_t groups_y, uint32_t groups_z) const;

    // The pipeline cache's part in creating this pipeline (empty file: not cached).
    const PipelineCacheUse& cache_use() const { return cache_use_; }
    // What the driver said about creating it (pipeline_report.h).
    const PipelineReport& report() const { return report_; }

  private:
    VkDevice device_;
    PipelineBindings bindings_;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    PipelineCacheUse cache_use_;
    PipelineReport report_;
};

} // namespace tp
