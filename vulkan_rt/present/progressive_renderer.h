// The viewer's accumulation (twinpath view): the same scene buffers, tracer and accumulators as
// `render --backend vulkan` (render_loop.h, batch_session.h), kept across frames. Each frame
// adds one batch of samples; a new camera clears the accumulators and starts again (the
// progressive estimate of the thesis, eq. 4.1). The display pass tone-maps the accumulators
// into packed 8-bit pixels exactly as --png does (shaders/display.comp, shared/tonemap.h), in
// the frame's submission after the batch's resolve pass (a frame is one submission and one
// wait), and only the rows the batch changed.
#pragma once

#include "render/render_options.h"
#include "scene/flatten.h"
#include "shaders/display_interface.h"
#include "vulkan_rt/compute_mode/bvh_builder.h"
#include "vulkan_rt/device/buffer.h"
#include "vulkan_rt/device/compute_program.h"
#include "vulkan_rt/device/context.h"
#include "vulkan_rt/render_loop/batch_planner.h"
#include "vulkan_rt/render_loop/batch_session.h"
#include "vulkan_rt/render_loop/render_loop.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

namespace tp {

struct ProgressiveOptions {
    uint32_t seed = 0;
    uint32_t sampler = 0; // SAMPLER_* (shared/rng.h, render/sampler.h)
    bool all_features = false;
    uint32_t max_spp = 1u << 30; // accumulation stops here
    // Samples per pixel in every frame; 0: adapt so that a frame takes about target_seconds,
    // and cover the whole image unless that takes more than whole_frame_seconds (then a frame
    // is a band of rows: batch_planner.h).
    uint32_t samples_per_frame = 0;
    double target_seconds = 1.0 / 60.0;
    double whole_frame_seconds = 0.1;
    BvhLayout bvh = BvhLayout::automatic; // compute mode's BVH layout (bvh_builder.h)
};

class ProgressiveRenderer {
  public:
    // Builds the mode's acceleration structure and pipeline on `ctx` (its mode: compute or
    // pipeline).
    ProgressiveRenderer(const VulkanContext& ctx, const FlatScene& scene,
                        const ProgressiveOptions& options);

    // Clears the accumulation and renders from `camera` (same film size) from now on.
    void restart(const Camera& camera);

    // Traces this frame's batch and tone-maps the accumulation into display_pixels(); false,
    // with nothing done, when the accumulation has reached max_spp.
    bool frame();
    // GPU seconds of the last frame's passes: trace, resolve and display (BatchSplit::after).
    const BatchSplit& frame_split() const { return session_->last_split(); }

    uint32_t spp() const; // samples of every pixel (whole passes)
    // The share of the rows that have one sample more than spp(): a pass under way in bands.
    double pass_fraction() const;
    uint64_t rays() const; // camera, extension and shadow rays since the last restart
    const Camera& camera() const { return params_.camera; }
    VkMode mode() const { return mode_.tracer->mode(); }

    // The display pass's `bgra` byte order (display_interface.h) and radiance scale
    // 2^exposure_stops, for this and every later frame; tone-maps the accumulators into
    // display_pixels() now.
    void set_display(bool bgra, float exposure_stops);
    const Buffer& display_pixels() const { return pixels_; } // uint32 per pixel, rows top down
    // display_pixels() read back as RGB8 rows (a headless screenshot).
    std::vector<uint8_t> display_rgb8() const;

    // The film and statistics of the accumulation so far, as render_vulkan returns them.
    RenderResult result() const;

  private:
    const VulkanContext& ctx_;
    const FlatScene& scene_;
    ProgressiveOptions options_;
    RenderParams params_;
    ModeSetup mode_;
    std::unique_ptr<BatchSession> session_;
    std::unique_ptr<BatchPlanner> planner_;
    uint32_t fixed_done_ = 0; // spp done with a fixed samples_per_frame
    std::chrono::steady_clock::time_point started_;
    Buffer pixels_;
    ComputeProgram display_;
    DisplayParams display_params_{};
    // The display pass over rows [row_begin, row_end).
    void record_display(VkCommandBuffer cmd, uint32_t row_begin, uint32_t row_end) const;
};

} // namespace tp
