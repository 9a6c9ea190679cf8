#include "vulkan_rt/present/progressive_renderer.h"

#include "render/sampler.h"
#include "scene/features.h"
#include "shaders/display_interface.h"
#include "util/clock.h"
#include "vulkan_rt/compute_mode/compute_renderer.h"
#include "vulkan_rt/device/barriers.h"
#include "vulkan_rt/pipeline_mode/pipeline_renderer.h"

#include <cmath>

// Generated from shaders/display.comp (shaders/spirv.cmake).
#include "display.spv.h"

namespace tp {
namespace {

RenderOptions render_options(const ProgressiveOptions& o) {
    RenderOptions options;
    options.seed = o.seed;
    options.sampler = o.sampler;
    options.all_features = o.all_features;
    return options;
}

ModeSetup prepare(const VulkanContext& ctx, const FlatScene& scene, const ProgressiveOptions& o) {
    const RenderOptions options = render_options(o);
    return ctx.mode() == VkMode::pipeline ? prepare_pipeline(ctx, scene, options)
                                          : prepare_compute(ctx, scene, options, o.bvh);
}

} // namespace

ProgressiveRenderer::ProgressiveRenderer(const VulkanContext& ctx, const FlatScene& scene,
                                         const ProgressiveOptions& options)
    : ctx_(ctx), scene_(scene), options_(options),
      params_(seeded_params(scene, render_options(options))), mode_(prepare(ctx, scene, options)),
      session_(std::make_unique<BatchSession>(ctx, scene, mode_.buffers, *mode_.tracer,
                                              DebugRequest{}, 0, options.sampler)),
      pixels_(ctx,
              VkDeviceSize(scene.params.camera.width) * scene.params.camera.height *
                  sizeof(uint32_t),
              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, false),
      display_(ctx, tp_spirv_display, sizeof(tp_spirv_display), DISPLAY_BINDING_COUNT,
               sizeof(DisplayParams), RenderConstants{}, false) {
    display_.bind(DISPLAY_BINDING_ACCUM, session_->accumulators());
    display_.bind(DISPLAY_BINDING_PIXELS, pixels_);
    restart(params_.camera);
}

void ProgressiveRenderer::restart(const Camera& camera) {
    params_.camera = camera;
    const Buffer& params = mode_.buffers.slots[BINDING_PARAMS];
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        record_shader_barrier(cmd, mode_.tracer->shader_stage());
        vkCmdUpdateBuffer(cmd, params.handle(), 0, sizeof(params_), &params_);
        record_shader_barrier(cmd, mode_.tracer->shader_stage());
    });
    session_->clear();
    const uint32_t w = camera.width, h = camera.height;
    planner_ = std::make_unique<BatchPlanner>(w, h, options_.max_spp, options_.target_seconds,
                                              session_->initial_work(), session_->max_work());
    fixed_done_ = 0;
    started_ = std::chrono::steady_clock::now();
}

bool ProgressiveRenderer::frame() {
    if (spp() >= options_.max_spp) return false;
    if (options_.samples_per_frame > 0) {
        const uint32_t n = std::min(options_.samples_per_frame, options_.max_spp - fixed_done_);
        session_->run({fixed_done_, n, 0, params_.camera.height});
        fixed_done_ += n;
        return true;
    }
    const Batch b = planner_->next();
    const auto t0 = std::chrono::steady_clock::now();
    const bool cut_short = session_->run(b);
    planner_->completed(b, seconds_since(t0), cut_short);
    return true;
}

uint32_t ProgressiveRenderer::spp() const {
    return options_.samples_per_frame > 0 ? fixed_done_ : planner_->samples_done();
}

uint64_t ProgressiveRenderer::rays() const {
    return session_->counter(COUNTER_CAMERA) + session_->counter(COUNTER_EXTENSION) +
           session_->counter(COUNTER_SHADOW);
}

void ProgressiveRenderer::update_display(bool bgra, float exposure_stops) {
    bgra_ = bgra;
    const DisplayParams push{params_.camera.width, params_.camera.height, session_->slots(),
                             bgra ? 1u : 0u, std::exp2(exposure_stops)};
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        record_shader_barrier(cmd, mode_.tracer->shader_stage());
        display_.record_dispatch(cmd, &push, (push.width + 7) / 8, (push.height + 7) / 8, 1);
        record_compute_barrier(cmd);
    });
}

std::vector<uint8_t> ProgressiveRenderer::display_rgb8() const {
    const Buffer host(ctx_, pixels_.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        record_compute_barrier(cmd);
        const VkBufferCopy region{0, 0, pixels_.size()};
        vkCmdCopyBuffer(cmd, pixels_.handle(), host.handle(), 1, &region);
        record_host_read_barrier(cmd);
    });
    const auto* px = static_cast<const uint8_t*>(host.mapped());
    std::vector<uint8_t> rgb(size_t(pixels_.size() / 4) * 3);
    for (size_t i = 0; i < rgb.size() / 3; ++i)
        for (int k = 0; k < 3; ++k) rgb[3 * i + k] = px[4 * i + (bgra_ ? 2 - k : k)];
    return rgb;
}

RenderResult ProgressiveRenderer::result() const {
    RenderResult r;
    RenderStats& st = r.stats;
    st.backend = "vulkan";
    st.mode = vk_mode_name(mode_.tracer->mode());
    st.device = ctx_.info().name;
    st.scene = scene_.name;
    st.seed = options_.seed;
    st.sampler = sampler_name(options_.sampler);
    st.width = params_.camera.width;
    st.height = params_.camera.height;
    st.spp = spp();
    st.wall_time_s = seconds_since(started_);
    st.build_time_s = mode_.accel.build_time_s;
    st.accel_bytes = mode_.accel.bytes;
    count_triangles(st, scene_);
    st.scene_features = analyze_features(scene_).names();
    r.film = session_->read_back(st);
    return r;
}

} // namespace tp
