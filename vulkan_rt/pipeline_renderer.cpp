#include "vulkan_rt/pipeline_renderer.h"

#include "scene/features.h"
#include "vulkan_rt/accel_structures.h"
#include "vulkan_rt/render_loop.h"
#include "vulkan_rt/rt_functions.h"
#include "vulkan_rt/rt_program.h"

#include <chrono>
#include <string>

namespace tp {
namespace {

// The ray-tracing pipeline over the TLAS it binds to slot 13.
class PipelineTracer : public Tracer {
  public:
    PipelineTracer(const VulkanContext& ctx, const RtFunctions& rt, VkAccelerationStructureKHR tlas,
                   uint32_t features)
        : program_(ctx, rt, sizeof(BatchParams), features) {
        program_.bind_tlas(tlas);
    }

    const char* mode() const override { return "pipeline"; }
    const PipelineCacheUse& cache_use() const { return program_.cache_use(); }
    VkPipelineStageFlags shader_stage() const override {
        return VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR;
    }
    void bind(uint32_t binding, const Buffer& buffer) override { program_.bind(binding, buffer); }
    void record_launch(VkCommandBuffer cmd, const BatchParams& batch,
                       uint32_t width) const override {
        program_.record_trace(cmd, &batch, width, batch.row_end - batch.row_begin);
    }

  private:
    RtProgram program_;
};

} // namespace

RenderResult render_pipeline(const VulkanContext& ctx, const FlatScene& scene,
                             const RenderOptions& options) {
    const RtFunctions rt(ctx.device());
    const SceneBuffers sb =
        upload_scene(ctx, scene, seeded_params(scene, options.seed), {}, kAccelInputUsage,
                     render_feature_mask(scene, options.all_features));
    const auto t_build = std::chrono::steady_clock::now();
    const AccelStructures as(ctx, rt, scene, sb);
    AccelStats accel;
    accel.build_time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t_build).count();
    accel.bytes = as.bytes();
    accel.extra["blas_count"] = std::to_string(as.blas_count());
    accel.extra["blas_bytes_uncompacted"] = std::to_string(as.uncompacted_blas_bytes());
    PipelineTracer tracer(ctx, rt, as.tlas(), render_feature_mask(scene, options.all_features));
    add_cache_stats(tracer.cache_use(), accel.extra);
    return render_batches(ctx, scene, options, sb, tracer, accel);
}

} // namespace tp
