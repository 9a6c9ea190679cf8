#include "vulkan_rt/compute_mode/compute_renderer.h"

#include "scene/features.h"
#include "util/clock.h"
#include "vulkan_rt/compute_mode/bvh_buffers.h"
#include "vulkan_rt/compute_mode/bvh_builder.h"
#include "vulkan_rt/device/compute_program.h"
#include "vulkan_rt/render_loop/item_schedule.h"
#include "vulkan_rt/render_loop/render_loop.h"
#include "vulkan_rt/render_loop/scene_buffers.h"

#include <chrono>
#include <memory>
#include <utility>

// Generated from shaders/render_compute.comp (shaders/spirv.cmake).
#include "render_compute.spv.h"
#include "render_compute_debug.spv.h"
#include "render_compute_wide.spv.h"
#include "render_compute_wide_debug.spv.h"

namespace tp {
namespace {

// The render shader's SPIR-V for a BVH layout: the module whose trace include traverses it.
struct ComputeModules {
    const uint32_t* spirv;
    size_t bytes;
    const uint32_t* debug_spirv;
    size_t debug_bytes;
};

ComputeModules compute_modules(BvhLayout layout) {
    if (layout == BvhLayout::wide)
        return {tp_spirv_render_compute_wide, sizeof(tp_spirv_render_compute_wide),
                tp_spirv_render_compute_wide_debug, sizeof(tp_spirv_render_compute_wide_debug)};
    return {tp_spirv_render_compute, sizeof(tp_spirv_render_compute), tp_spirv_render_compute_debug,
            sizeof(tp_spirv_render_compute_debug)};
}

// The compute shader over the BVH arrays it owns (slots 13 and 14).
class ComputeTracer : public Tracer {
  public:
    // `buffers`: `bvh` on the device (upload_bvh).
    // `debug`: also build the debug variant (record_debug_launch).
    // `constants`: what the render shader is specialized to (specialization.h).
    ComputeTracer(const VulkanContext& ctx, const BvhBuild& bvh, BvhBuffers buffers, bool debug,
                  const RenderConstants& constants)
        : ComputeTracer(ctx, std::move(buffers), bvh.top_root, debug, constants,
                        compute_modules(bvh.layout)) {}

    ComputeTracer(const VulkanContext& ctx, BvhBuffers buffers, uint32_t top_root, bool debug,
                  const RenderConstants& constants, const ComputeModules& modules)
        : bvh_(std::move(buffers)), top_root_(top_root),
          program_(ctx, modules.spirv, modules.bytes, interface_slots(BINDING_COUNT, true),
                   sizeof(BatchParams), constants, true) {
        if (debug) {
            const std::vector<uint32_t> spirv =
                debug_spirv(modules.debug_spirv, modules.debug_bytes);
            debug_program_ = std::make_unique<ComputeProgram>(
                ctx, spirv.data(), spirv.size() * 4, interface_slots(BINDING_COUNT, true),
                sizeof(BatchParams), constants, false);
        }
        bind(BINDING_BVH_NODES, bvh_.nodes);
        bind(BINDING_BVH_TRIS, bvh_.triangles);
    }

    VkMode mode() const override { return VkMode::compute; }
    const PipelineCacheUse& cache_use() const { return program_.cache_use(); }
    const PipelineReport& report() const { return program_.report(); }
    VkPipelineStageFlags shader_stage() const override {
        return VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    }

    void bind(uint32_t binding, const Buffer& buffer) override {
        program_.bind(binding, buffer);
        if (debug_program_) debug_program_->bind(binding, buffer);
    }
    void bind_images(const std::vector<VkImageView>& views) override {
        program_.bind_images(BINDING_IMAGES, views);
        if (debug_program_) debug_program_->bind_images(BINDING_IMAGES, views);
    }

    void record_launch(VkCommandBuffer cmd, const BatchParams& batch,
                       uint32_t invocations) const override {
        dispatch(program_, cmd, batch, invocations);
    }
    void record_debug_launch(VkCommandBuffer cmd, const BatchParams& batch,
                             uint32_t invocations) const override {
        dispatch(*debug_program_, cmd, batch, invocations);
    }

  private:
    void dispatch(const ComputeProgram& program, VkCommandBuffer cmd, const BatchParams& batch,
                  uint32_t invocations) const {
        BatchParams push = batch;
        push.bvh_top_root = top_root_;
        program.record_dispatch(cmd, &push,
                                (invocations + RENDER_GROUP_SIZE - 1) / RENDER_GROUP_SIZE, 1, 1);
    }

    BvhBuffers bvh_;
    uint32_t top_root_;
    ComputeProgram program_;
    std::unique_ptr<ComputeProgram> debug_program_;
};

} // namespace

ModeSetup prepare_compute(const VulkanContext& ctx, const FlatScene& scene,
                          const RenderOptions& options, BvhLayout layout) {
    // The BVH's shape follows the mask the shader is specialized to: one level without
    // instancing, two with it (bvh_builder.h, trace_bvh.glsl).
    const uint32_t features = render_feature_mask(scene, options.all_features);
    check_scene_images(ctx, scene, features); // before any work: a texture may not fit
    ctx.memory_tally().restart_peak();
    const auto t_build = std::chrono::steady_clock::now();
    const BvhBuild bvh = build_bvh(scene, features, layout);
    ModeSetup m;
    m.accel.build_time_s = seconds_since(t_build);
    m.accel.bytes = bvh.bytes();
    m.accel.extra = bvh_stats(bvh);
    const auto t_upload = std::chrono::steady_clock::now();
    m.buffers =
        upload_scene(ctx, scene, seeded_params(scene, options), bvh.mesh_roots, 0, features);
    BvhBuffers bvh_buffers = upload_bvh(ctx, bvh);
    m.accel.upload_time_s = seconds_since(t_upload);
    auto tracer = std::make_unique<ComputeTracer>(
        ctx, bvh, std::move(bvh_buffers), options.debug.active() || debug_spirv_overridden(),
        RenderConstants{features, render_item_schedule(ctx.info(), options.gpu_invocations),
                        m.buffers.images.count});
    add_cache_stats(tracer->cache_use(), m.accel.extra);
    m.accel.pipeline = tracer->report();
    m.tracer = std::move(tracer);
    return m;
}

RenderResult render_compute(const VulkanContext& ctx, const FlatScene& scene,
                            const RenderOptions& options, BvhLayout layout) {
    ModeSetup m = prepare_compute(ctx, scene, options, layout);
    return render_batches(ctx, scene, options, m);
}

} // namespace tp
