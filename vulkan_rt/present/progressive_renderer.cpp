#include "vulkan_rt/present/progressive_renderer.h"

#include "render/sampler.h"
#include "scene/features.h"
#include "util/clock.h"
#include "vulkan_rt/compute_mode/compute_renderer.h"
#include "vulkan_rt/device/barriers.h"
#include "vulkan_rt/pipeline_mode/pipeline_renderer.h"

#include <algorithm>
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
              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                  VK_BUFFER_USAGE_TRANSFER_DST_BIT,
              false),
      display_(ctx, tp_spirv_display, sizeof(tp_spirv_display), DISPLAY_BINDING_COUNT,
               sizeof(DisplayParams), RenderConstants{}, false) {
    display_.bind(DISPLAY_BINDING_ACCUM, session_->accumulators());
    display_.bind(DISPLAY_BINDING_PIXELS, pixels_);
    display_params_ = {
        params_.camera.width, params_.camera.height, 0u, 0u, session_->slots(), 0u, 1.0f};
    restart(params_.camera);
}

void ProgressiveRenderer::restart(const Camera& camera) {
    params_.camera = camera;
    const Buffer& params = mode_.buffers.slots[BINDING_PARAMS];
    // The pixels become what the display pass makes of empty accumulators (opaque black), so
    // that the rows a band has not reached yet show that until it does.
    const uint32_t black = display_pack(uvec3(0u), 0u);
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        record_shader_barrier(cmd, mode_.tracer->shader_stage());
        vkCmdUpdateBuffer(cmd, params.handle(), 0, sizeof(params_), &params_);
        vkCmdFillBuffer(cmd, pixels_.handle(), 0, VK_WHOLE_SIZE, black);
        record_shader_barrier(cmd, mode_.tracer->shader_stage());
    });
    session_->clear();
    const uint32_t w = camera.width, h = camera.height;
    planner_ = std::make_unique<BatchPlanner>(w, h, options_.max_spp, options_.target_seconds,
                                              session_->initial_work(), session_->max_work(),
                                              options_.whole_frame_seconds);
    fixed_done_ = 0;
    started_ = std::chrono::steady_clock::now();
}

bool ProgressiveRenderer::frame() {
    if (spp() >= options_.max_spp) return false;
    const uint32_t h = params_.camera.height;
    const Batch b =
        options_.samples_per_frame > 0
            ? Batch{fixed_done_,
                    std::min(options_.samples_per_frame, options_.max_spp - fixed_done_), 0, h}
            : planner_->next();
    const auto t0 = std::chrono::steady_clock::now();
    const bool cut_short =
        session_->run(b, [&](VkCommandBuffer cmd) { record_display(cmd, b.row_begin, b.row_end); });
    if (options_.samples_per_frame > 0) {
        fixed_done_ += b.sample_count;
    } else {
        // The planner sizes the batch's work; the display pass's time is not the batch's.
        const double seconds = seconds_since(t0) - session_->last_split().after;
        planner_->completed(b, std::max(seconds, 0.0), cut_short);
    }
    return true;
}

uint32_t ProgressiveRenderer::spp() const {
    return options_.samples_per_frame > 0 ? fixed_done_ : planner_->samples_done();
}

double ProgressiveRenderer::pass_fraction() const {
    return options_.samples_per_frame > 0 ? 0.0 : planner_->pass_fraction();
}

uint64_t ProgressiveRenderer::rays() const {
    return session_->counter(COUNTER_CAMERA) + session_->counter(COUNTER_EXTENSION) +
           session_->counter(COUNTER_SHADOW);
}

void ProgressiveRenderer::set_display(bool bgra, float exposure_stops) {
    display_params_.bgra = bgra ? 1u : 0u;
    display_params_.scale = std::exp2(exposure_stops);
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        record_shader_barrier(cmd, mode_.tracer->shader_stage());
        record_display(cmd, 0, params_.camera.height);
    });
}

// After the accumulators' writes are visible to compute shaders; the presenter's copy waits
// for the pixels' (presenter.cpp).
void ProgressiveRenderer::record_display(VkCommandBuffer cmd, uint32_t row_begin,
                                         uint32_t row_end) const {
    DisplayParams p = display_params_;
    p.row_begin = row_begin;
    p.row_end = row_end;
    display_.record_dispatch(cmd, &p, (p.width + 7) / 8, (row_end - row_begin + 7) / 8, 1);
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
        for (int k = 0; k < 3; ++k) rgb[3 * i + k] = px[4 * i + (display_params_.bgra ? 2 - k : k)];
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
    st.upload_time_s = mode_.accel.upload_time_s;
    st.accel_bytes = mode_.accel.bytes;
    count_triangles(st, scene_);
    st.scene_features = analyze_features(scene_).names();
    r.film = session_->read_back(st);
    st.device_memory_peak_bytes = ctx_.memory_tally().peak();
    return r;
}

} // namespace tp
