// The render loop both Vulkan modes share (compute_renderer.cpp, pipeline_renderer.cpp): the
// per-pixel accumulators and ray counters, progressive batches (batch_planner.h) with
// checkpoints and --time-limit, repeated dispatches after a cut-short one, the read-back into
// the double-precision Film and the statistics. The modes differ only in their Tracer: the
// pipeline that runs a batch and the acceleration structure it binds.
#pragma once

#include "render/render_options.h"
#include "scene/flatten.h"
#include "shaders/interface.h"
#include "vulkan_rt/device/buffer.h"
#include "vulkan_rt/device/context.h"
#include "vulkan_rt/device/vk_mode.h"
#include "vulkan_rt/render_loop/scene_buffers.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace tp {

class Tracer {
  public:
    virtual ~Tracer() = default;
    virtual VkMode mode() const = 0;
    // The stage of the shader that writes the accumulators (barriers).
    virtual VkPipelineStageFlags shader_stage() const = 0;
    // Points slot `binding` (interface.h: scene, accumulator and counter slots) at `buffer`.
    virtual void bind(uint32_t binding, const Buffer& buffer) = 0;
    // Points BINDING_IMAGES at the scene's images (scene_images.h: IMAGE_SLOTS views).
    virtual void bind_images(const std::vector<VkImageView>& views) = 0;
    // Records `invocations` render invocations (a one-dimensional launch) with `batch` as push
    // constants. In the render pass they share the batch's work items (render_items.glsl); in
    // the debug variant's other passes invocation i is pixel (i % width, row_begin + i / width).
    virtual void record_launch(VkCommandBuffer cmd, const BatchParams& batch,
                               uint32_t invocations) const = 0;
    // The same with the debug variant of the shader (TP_DEBUG_SHADER: path logs, AOVs, debug
    // views; shaders/debug.glsl), which the tracer builds when the render's DebugRequest is
    // active. What it does is in the debug buffer's header (shared/path_log.h).
    virtual void record_debug_launch(VkCommandBuffer cmd, const BatchParams& batch,
                                     uint32_t invocations) const = 0;
};

// The SPIR-V of a debug variant: the embedded one, or the file TWINPATH_DEBUG_SPIRV names (a
// test hook: tests/gpu/debug_workflow_test.cpp renders with shaders that carry planted bugs).
// With the override the debug variant also renders the image itself (render_batches).
std::vector<uint32_t> debug_spirv(const uint32_t* embedded, size_t bytes);
bool debug_spirv_overridden();

// What the mode built before rendering, for the statistics.
struct AccelStats {
    double build_time_s = 0;
    double upload_time_s = 0; // RenderStats::upload_time_s
    uint64_t bytes = 0;       // RenderStats::accel_bytes
    std::map<std::string, std::string> extra;
    PipelineReport pipeline; // the render pipeline's (RenderStats::pipeline)
};

// The scene's RenderParams with the render's seed (uploaded to BINDING_PARAMS).
RenderParams seeded_params(const FlatScene& scene, const RenderOptions& options);

// What a mode builds before its first batch (prepare_compute, prepare_pipeline): the scene on
// the device, the tracer over the mode's acceleration structure, and what building them cost.
// The tracer is declared last so that it goes before the buffers it binds.
struct ModeSetup {
    SceneBuffers buffers;
    AccelStats accel;
    std::unique_ptr<Tracer> tracer;
};

// Renders options' spp of the scene with a prepared mode (compute_renderer.h,
// pipeline_renderer.h).
RenderResult render_batches(const VulkanContext& ctx, const FlatScene& scene,
                            const RenderOptions& options, ModeSetup& mode);

} // namespace tp
