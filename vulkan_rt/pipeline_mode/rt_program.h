// Pipeline mode's ray-tracing pipeline: the ray-generation shader (shaders/render_pipeline.rgen,
// the path loop), the two miss shaders and the hit groups of shaders/rt_interface.h; its
// shader binding table (sbt_layout.h) in device memory; descriptor set 0 of interface.h with the
// TLAS in slot 16 and the scene's images in slot 15; and the vkCmdTraceRaysKHR of a batch.
#pragma once

#include "render/stats.h"
#include "shaders/interface.h"
#include "vulkan_rt/device/buffer.h"
#include "vulkan_rt/device/context.h"
#include "vulkan_rt/device/pipeline_bindings.h"
#include "vulkan_rt/device/pipeline_cache.h"
#include "vulkan_rt/device/specialization.h"
#include "vulkan_rt/pipeline_mode/rt_functions.h"

namespace tp {

class RtProgram {
  public:
    // `raygen`/`raygen_bytes`: another ray-generation module in place of render_pipeline.rgen
    // (its debug variant); null: the normal one. `exact`: the TLAS has instances of exact
    // meshes (AccelStructures::exact_count), which need the procedural hit group.
    RtProgram(const VulkanContext& ctx, const RtFunctions& rt, uint32_t push_bytes,
              const uint32_t* raygen = nullptr, size_t raygen_bytes = 0,
              const RenderConstants& constants = {}, bool exact = false);
    ~RtProgram();
    RtProgram(const RtProgram&) = delete;
    RtProgram& operator=(const RtProgram&) = delete;

    // Points storage-buffer slot `binding` at the whole of `buffer`.
    void bind(uint32_t binding, const Buffer& buffer) { bindings_.write_buffer(binding, buffer); }
    void bind_tlas(VkAccelerationStructureKHR tlas);
    // Points BINDING_IMAGES at the scene's images (render_loop/scene_images.h).
    void bind_images(const std::vector<VkImageView>& views) {
        bindings_.write_images(BINDING_IMAGES, views);
    }

    // Binds the pipeline and the set, pushes the constants and launches width x height
    // ray-generation invocations.
    void record_trace(VkCommandBuffer cmd, const void* push, uint32_t width, uint32_t height) const;

    // The pipeline cache's part in creating the pipeline (pipeline_cache.h).
    const PipelineCacheUse& cache_use() const { return cache_use_; }
    // What the driver said about creating it (pipeline_report.h).
    const PipelineReport& report() const { return report_; }

  private:
    void create_pipeline();
    void create_binding_table();

    const VulkanContext& ctx_;
    const RtFunctions& rt_;
    const uint32_t* raygen_spirv_;
    size_t raygen_bytes_;
    RenderConstants constants_; // the ray-generation shader's specialization
    uint32_t hit_groups_;       // 1, or 2 with the procedural hit group
    bool alpha_;                // the scene has alpha: the hit groups' any-hit alpha test
    PipelineCacheUse cache_use_;
    PipelineReport report_;
    PipelineBindings bindings_;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    Buffer sbt_;
    VkStridedDeviceAddressRegionKHR raygen_{}, miss_{}, hit_{}, callable_{};
};

} // namespace tp
