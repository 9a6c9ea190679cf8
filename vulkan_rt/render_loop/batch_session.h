// The device-side state of one accumulation: the per-pixel accumulators (shaders/interface.h,
// PixelAccum), the sample buffer of one dispatch's work items, the ray counters, the debug and
// AOV buffers and the GPU timer, and the batches run through a Tracer and the resolve pass
// (shaders/resolve.comp) into them. render_batches (render_loop.h) drives one to a fixed spp; the
// viewer (progressive_renderer.h) drives one frame by frame and clears it when the camera moves.
#pragma once

#include "render/render_options.h"
#include "scene/flatten.h"
#include "shaders/interface.h"
#include "vulkan_rt/device/buffer.h"
#include "vulkan_rt/device/compute_program.h"
#include "vulkan_rt/device/context.h"
#include "vulkan_rt/device/gpu_timer.h"
#include "vulkan_rt/render_loop/batch_planner.h"
#include "vulkan_rt/render_loop/render_loop.h"
#include "vulkan_rt/render_loop/scene_buffers.h"

#include <functional>
#include <vector>

namespace tp {

// GPU seconds of one batch's passes, summed over its launches (zeros without timestamps): the
// render invocations, the resolve pass, and the commands recorded after them (BatchSession::run).
struct BatchSplit {
    double trace = 0, resolve = 0, after = 0;
};

class BatchSession {
  public:
    // `sample_offset`: the first sample of the range that batches' sample_begin counts from.
    // `invocations`: render invocations per launch (RenderOptions::gpu_invocations; 0: the
    // device's resident count, render_invocations).
    BatchSession(const VulkanContext& ctx, const FlatScene& scene, const SceneBuffers& sb,
                 Tracer& tracer, const DebugRequest& debug, uint32_t sample_offset,
                 uint32_t sampler, uint32_t invocations = 0);

    double gpu_seconds() const { return timer_.active() ? gpu_seconds_ : -1.0; }
    uint32_t submissions() const { return submissions_; }
    uint32_t repeats() const { return repeats_; }
    // PixelAccum[width * height * slots()]: a pixel's slots are consecutive, one per film batch
    // (render/sampler.h).
    const Buffer& accumulators() const { return accum_; }
    uint32_t slots() const { return slots_; }

    // The first sample of the range that the batches' sample_begin counts from.
    void set_sample_offset(uint32_t first) { sample_offset_ = first; }

    // Zeroes the accumulators and counters: the next batch starts a new image.
    void clear();

    // Traces the batch to completion. Dispatches are repeated while some pixels stopped early
    // (render_items.glsl, loop budget); each repetition traces only the items still untraced and
    // resumes those pixels where they stopped. Returns whether that happened. `after` records
    // commands into each launch's submission once the resolve pass's writes are visible to
    // compute shaders (the viewer's display pass), so that a frame is one submission.
    bool run(const Batch& b, const std::function<void(VkCommandBuffer)>& after = {});
    const BatchSplit& last_split() const { return split_; } // of the last run()

    // Render invocations per launch at most: 65535 compute workgroups (the least
    // maxComputeWorkGroupCount[0] a device may have), also within every device's limit on a
    // ray-tracing launch (maxComputeWorkGroupCount[0] x maxComputeWorkGroupSize[0]).
    static constexpr uint32_t kMaxInvocations = 65535u * RENDER_GROUP_SIZE;
    // The render invocations of a launch of `items` work items on `device`: every item its own
    // invocation, up to what the device keeps resident at once where it says so (then each
    // invocation takes items until none is left) and kMaxInvocations.
    static uint32_t render_invocations(uint64_t items, uint64_t resident);

    // The batch planner's first and largest submissions on this device (pixel-samples): the
    // first fills every resident invocation kFirstLaunchItems times over where the device says
    // how many there are; the largest keeps the sample buffer within 1/kSampleMemoryShare of the
    // device's memory and BatchPlanner::kMaxWork, and on a CPU device (lavapipe, some 10^5
    // samples per 100 ms submission) within kCpuDeviceMaxWork.
    uint64_t initial_work() const;
    // What the render launches keep resident: the count asked for, else the device's (0:
    // unknown, one invocation per item).
    uint64_t resident_invocations() const;
    uint64_t max_work() const;
    static constexpr uint64_t kFirstLaunchItems = 4;
    static constexpr uint64_t kSampleMemoryShare = 16;
    static constexpr uint64_t kCpuDeviceMaxWork = uint64_t(1) << 20;

    // The AOV pass: every pixel's PixelAov (shared/path_log.h).
    std::vector<PixelAov> aovs();

    // The log pass: samples [first, end) of the debug pixel, one dispatch each, every vertex
    // recorded into the debug buffer.
    void path_log(uint32_t first, uint32_t end, uint32_t y, DebugOutput& out);

    // Merges every pixel into a double-precision film and fills the counters of `st`.
    Film read_back(RenderStats& st) const;

    // The counters as they came back with the last launch (COUNTER_* of interface.h).
    uint64_t counter(uint32_t slot) const;

  private:
    static constexpr VkDeviceSize kCounterBytes = COUNTER_WORDS * sizeof(uint32_t);
    static uint32_t debug_capacity(const FlatScene& scene, const DebugRequest& d,
                                   uint32_t sample_offset);
    void set_pass(uint32_t pass);
    void debug_launch(const BatchParams& b);
    void read_buffer(const Buffer& src, void* dst, size_t bytes) const;
    void reserve_samples(uint64_t items);
    // The stages that write the accumulators: the tracer's and the resolve pass's (compute).
    VkPipelineStageFlags stages() const {
        return tracer_.shader_stage() | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    }
    void launch(const std::function<void(VkCommandBuffer)>& after);

    const VulkanContext& ctx_;
    Tracer& tracer_;
    uint32_t sample_offset_;
    uint32_t invocations_; // asked for; 0: the device's
    uint32_t width_, height_;
    uint32_t batches_; // film batches (render/sampler.h)
    uint32_t slots_;   // accumulator slots per pixel: one per batch, at least one
    Buffer accum_, counters_, host_counters_;
    uint32_t debug_capacity_;
    Buffer debug_, aov_;
    Buffer samples_; // vec4 per work item of a batch (BINDING_SAMPLES)
    ComputeProgram resolve_;
    DebugHeader debug_header_{};
    bool debug_render_ = false; // the image itself is rendered by the debug variant
    GpuTimer timer_;
    BatchParams params_{};
    double gpu_seconds_ = 0;
    BatchSplit split_;
    uint32_t submissions_ = 0, repeats_ = 0;
};

} // namespace tp
