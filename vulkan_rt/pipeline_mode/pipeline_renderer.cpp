#include "vulkan_rt/pipeline_mode/pipeline_renderer.h"

#include "scene/features.h"
#include "util/clock.h"
#include "util/error.h"
#include "vulkan_rt/pipeline_mode/accel_structures.h"
#include "vulkan_rt/pipeline_mode/rt_functions.h"
#include "vulkan_rt/pipeline_mode/rt_program.h"
#include "vulkan_rt/render_loop/item_schedule.h"
#include "vulkan_rt/render_loop/render_loop.h"

#include <chrono>
#include <memory>
#include <string>
#include <vector>

// Generated from shaders/render_pipeline.rgen with TP_DEBUG_SHADER (shaders/spirv.cmake).
#include "render_pipeline_debug.spv.h"

namespace tp {
namespace {

// The ray-tracing pipeline over the TLAS it binds to slot 16; it keeps the acceleration
// structures and the extension's functions alive.
class PipelineTracer : public Tracer {
  public:
    // `debug`: also build the pipeline with the debug ray-generation shader.
    PipelineTracer(const VulkanContext& ctx, std::unique_ptr<RtFunctions> rt_functions,
                   std::unique_ptr<AccelStructures> accel, bool debug,
                   const RenderConstants& constants)
        : rt_(std::move(rt_functions)), as_(std::move(accel)),
          program_(ctx, *rt_, sizeof(BatchParams), nullptr, 0, constants, as_->exact_count() > 0) {
        const RtFunctions& rt = *rt_;
        const AccelStructures& as = *as_;
        program_.bind_tlas(as.tlas());
        if (debug) {
            debug_spirv_ =
                debug_spirv(tp_spirv_render_pipeline_debug, sizeof(tp_spirv_render_pipeline_debug));
            debug_program_ = std::make_unique<RtProgram>(
                ctx, rt, sizeof(BatchParams), debug_spirv_.data(), debug_spirv_.size() * 4,
                constants, as.exact_count() > 0);
            debug_program_->bind_tlas(as.tlas());
        }
    }

    VkMode mode() const override { return VkMode::pipeline; }
    const PipelineCacheUse& cache_use() const { return program_.cache_use(); }
    const PipelineReport& report() const { return program_.report(); }
    VkPipelineStageFlags shader_stage() const override {
        return VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR;
    }
    void bind(uint32_t binding, const Buffer& buffer) override {
        program_.bind(binding, buffer);
        if (debug_program_) debug_program_->bind(binding, buffer);
    }
    void bind_images(const std::vector<VkImageView>& views) override {
        program_.bind_images(views);
        if (debug_program_) debug_program_->bind_images(views);
    }
    void record_launch(VkCommandBuffer cmd, const BatchParams& batch,
                       uint32_t invocations) const override {
        program_.record_trace(cmd, &batch, invocations, 1);
    }
    void record_debug_launch(VkCommandBuffer cmd, const BatchParams& batch,
                             uint32_t invocations) const override {
        debug_program_->record_trace(cmd, &batch, invocations, 1);
    }

  private:
    std::unique_ptr<RtFunctions> rt_;
    std::unique_ptr<AccelStructures> as_;
    RtProgram program_;
    std::vector<uint32_t> debug_spirv_;
    std::unique_ptr<RtProgram> debug_program_;
};

} // namespace

ModeSetup prepare_pipeline(const VulkanContext& ctx, const FlatScene& scene,
                           const RenderOptions& options) {
    if (options.debug.integrator == INTEGRATOR_COST)
        input_error("--integrator cost counts BVH nodes and triangles of the software traversal: "
                    "use --vk-mode compute (the hardware traversal of pipeline mode exposes no "
                    "counts; docs/debugging.md)");
    const uint32_t features = render_feature_mask(scene, options.all_features);
    check_scene_images(ctx, scene, features); // before any work: a texture may not fit
    auto rt = std::make_unique<RtFunctions>(ctx.device());
    ctx.memory_tally().restart_peak();
    ModeSetup m;
    const auto t_upload = std::chrono::steady_clock::now();
    m.buffers =
        upload_scene(ctx, scene, seeded_params(scene, options), {}, kAccelInputUsage, features);
    m.accel.upload_time_s = seconds_since(t_upload);
    const auto t_build = std::chrono::steady_clock::now();
    auto as = std::make_unique<AccelStructures>(ctx, *rt, scene, m.buffers);
    m.accel.build_time_s = seconds_since(t_build);
    m.accel.bytes = as->bytes();
    m.accel.extra["blas_count"] = std::to_string(as->blas_count());
    m.accel.extra["blas_bytes_uncompacted"] = std::to_string(as->uncompacted_blas_bytes());
    m.accel.extra["exact_meshes"] = std::to_string(as->exact_count());
    auto tracer = std::make_unique<PipelineTracer>(
        ctx, std::move(rt), std::move(as), options.debug.active() || debug_spirv_overridden(),
        RenderConstants{features, render_item_schedule(ctx.info(), options.gpu_invocations),
                        m.buffers.images.count});
    add_cache_stats(tracer->cache_use(), m.accel.extra);
    m.accel.pipeline = tracer->report();
    m.tracer = std::move(tracer);
    return m;
}

RenderResult render_pipeline(const VulkanContext& ctx, const FlatScene& scene,
                             const RenderOptions& options) {
    ModeSetup m = prepare_pipeline(ctx, scene, options);
    return render_batches(ctx, scene, options, m);
}

} // namespace tp
