#include "vulkan_rt/render_loop/batch_session.h"

#include "render/sampler.h"
#include "util/error.h"
#include "vulkan_rt/device/barriers.h"
#include "vulkan_rt/render_loop/item_schedule.h"

#include <algorithm>
#include <cstring>

// Generated from shaders/resolve.comp (shaders/spirv.cmake).
#include "resolve.spv.h"

namespace tp {
namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                        VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                        VK_BUFFER_USAGE_TRANSFER_DST_BIT;

// A work item's estimate and tag in the sample buffer (interface.h, BINDING_SAMPLES).
constexpr VkDeviceSize kSampleBytes = 4 * sizeof(float);

// A launch's timestamps: before the render invocations, after them, after the resolve pass,
// after the commands that follow it (BatchSplit).
constexpr uint32_t kTimerMarks = 4;

} // namespace

uint32_t BatchSession::render_invocations(uint64_t items, uint64_t resident) {
    uint64_t n = resident > 0 ? std::min(items, resident) : items;
    return uint32_t(std::clamp<uint64_t>(n, 1, kMaxInvocations));
}

BatchSession::BatchSession(const VulkanContext& ctx, const FlatScene& scene, const SceneBuffers& sb,
                           Tracer& tracer, const DebugRequest& debug, uint32_t sample_offset,
                           uint32_t sampler, uint32_t invocations)
    : ctx_(ctx), tracer_(tracer), sample_offset_(sample_offset), invocations_(invocations),
      width_(scene.params.camera.width), height_(scene.params.camera.height),
      batches_(film_batches(sampler)), slots_(accum_slots(sampler)),
      accum_(ctx, VkDeviceSize(width_) * height_ * slots_ * sizeof(PixelAccum), kStorage, false),
      counters_(ctx, kCounterBytes, kStorage, false),
      host_counters_(ctx, kCounterBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true),
      debug_capacity_(debug_capacity(scene, debug, sample_offset)),
      debug_(ctx, sizeof(DebugHeader) + VkDeviceSize(debug_capacity_) * sizeof(PathVertex),
             kStorage, false),
      aov_(ctx, debug.aov ? VkDeviceSize(width_) * height_ * sizeof(PixelAov) : sizeof(PixelAov),
           kStorage, false),
      samples_(ctx, kSampleBytes, kStorage, false),
      resolve_(ctx, tp_spirv_resolve, sizeof(tp_spirv_resolve),
               interface_slots(BINDING_COUNT, false), sizeof(BatchParams), RenderConstants{},
               false),
      timer_(ctx, kTimerMarks) {
    for (uint32_t slot = 0; slot < sb.slots.size(); ++slot) {
        tracer.bind(slot, sb.slots[slot]);
        resolve_.bind(slot, sb.slots[slot]);
    }
    tracer.bind_images(sb.images.views);
    tracer.bind(BINDING_ACCUM, accum_);
    tracer.bind(BINDING_COUNTERS, counters_);
    tracer.bind(BINDING_DEBUG, debug_);
    tracer.bind(BINDING_AOV, aov_);
    tracer.bind(BINDING_SAMPLES, samples_);
    resolve_.bind(BINDING_ACCUM, accum_);
    resolve_.bind(BINDING_COUNTERS, counters_);
    resolve_.bind(BINDING_DEBUG, debug_);
    resolve_.bind(BINDING_AOV, aov_);
    resolve_.bind(BINDING_SAMPLES, samples_);
    const uint32_t pass = std::min(scene.spp, BatchPlanner::kMaxSamplesPerBatch);
    reserve_samples(std::min(max_work(), uint64_t(batch_tiled_pixels(width_, 0, height_)) * pass));
    std::memset(host_counters_.mapped(), 0, kCounterBytes);
    debug_header_.capacity = debug_capacity_;
    debug_header_.integrator = debug.integrator;
    debug_header_.pixel_x = debug.pixel_x;
    debug_header_.pixel_y = debug.pixel_y;
    debug_render_ = debug.integrator != INTEGRATOR_PATH || debug_spirv_overridden();
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
        vkCmdFillBuffer(cmd, accum_.handle(), 0, VK_WHOLE_SIZE, 0);
        vkCmdFillBuffer(cmd, counters_.handle(), 0, VK_WHOLE_SIZE, 0);
        vkCmdFillBuffer(cmd, debug_.handle(), 0, VK_WHOLE_SIZE, 0);
        vkCmdFillBuffer(cmd, aov_.handle(), 0, VK_WHOLE_SIZE, 0);
        record_shader_barrier(cmd, stages());
        vkCmdUpdateBuffer(cmd, debug_.handle(), 0, sizeof(DebugHeader), &debug_header_);
    });
    params_.env_table_size = uint32_t(scene.env_table.size());
    params_.probe_iterations = LOOP_PROBE_ITERATIONS;
}

void BatchSession::clear() {
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        record_shader_barrier(cmd, stages());
        vkCmdFillBuffer(cmd, accum_.handle(), 0, VK_WHOLE_SIZE, 0);
        vkCmdFillBuffer(cmd, counters_.handle(), 0, VK_WHOLE_SIZE, 0);
        record_shader_barrier(cmd, stages());
    });
    std::memset(host_counters_.mapped(), 0, kCounterBytes);
}

bool BatchSession::run(const Batch& b, const std::function<void(VkCommandBuffer)>& after) {
    params_.sample_begin = sample_offset_ + b.sample_begin;
    params_.sample_count = b.sample_count;
    params_.row_begin = b.row_begin;
    params_.row_end = b.row_end;
    params_.item_count = batch_item_count(width_, b.row_begin, b.row_end, b.sample_count);
    ++params_.sample_tag;
    reserve_samples(params_.item_count);
    split_ = {};
    bool cut_short = false;
    for (uint64_t camera = counter(COUNTER_CAMERA);; camera = counter(COUNTER_CAMERA)) {
        launch(after);
        if (counter(COUNTER_TRUNCATED) == 0) return cut_short;
        if (counter(COUNTER_CAMERA) == camera)
            runtime_error("the Vulkan device ends shader loops before one path is traced "
                          "(lavapipe allows 65535 loop iterations per invocation); lower "
                          "--max-depth");
        cut_short = true;
        ++repeats_;
    }
}

// The AOV pass: every pixel's PixelAov (shared/path_log.h).
std::vector<PixelAov> BatchSession::aovs() {
    set_pass(DEBUG_PASS_AOV);
    BatchParams b = params_;
    b.row_begin = 0;
    b.row_end = height_;
    b.sample_begin = 0;
    b.sample_count = 0;
    debug_launch(b);
    std::vector<PixelAov> out(size_t(width_) * height_);
    read_buffer(aov_, out.data(), out.size() * sizeof(PixelAov));
    return out;
}

// The log pass: samples [first, end) of the debug pixel, one dispatch each, every vertex
// recorded into the debug buffer.
void BatchSession::path_log(uint32_t first, uint32_t end, uint32_t y, DebugOutput& out) {
    set_pass(DEBUG_PASS_LOG);
    for (uint32_t s = first; s < end; ++s) {
        BatchParams b = params_;
        b.row_begin = y;
        b.row_end = y + 1;
        b.sample_begin = s;
        b.sample_count = 1;
        debug_launch(b);
    }
    DebugHeader h{};
    read_buffer(debug_, &h, sizeof(h));
    const uint32_t n = std::min(h.count, h.capacity);
    out.dropped = h.count - n;
    std::vector<uint8_t> bytes(sizeof(DebugHeader) + size_t(n) * sizeof(PathVertex));
    read_buffer(debug_, bytes.data(), bytes.size());
    out.records.resize(n);
    std::memcpy(out.records.data(), bytes.data() + sizeof(DebugHeader),
                size_t(n) * sizeof(PathVertex));
}

// Merges every pixel into a double-precision film and fills the counters of `st`.
Film BatchSession::read_back(RenderStats& st) const {
    const Buffer host(ctx_, accum_.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        record_shader_barrier(cmd, stages());
        const VkBufferCopy region{0, 0, accum_.size()};
        vkCmdCopyBuffer(cmd, accum_.handle(), host.handle(), 1, &region);
        record_host_read_barrier(cmd);
    });
    const auto* slots = static_cast<const PixelAccum*>(host.mapped());
    Film film(width_, height_, batches_);
    for (uint32_t p = 0; p < width_ * height_; ++p)
        for (uint32_t b = 0; b < slots_; ++b) {
            const PixelAccum& a = slots[size_t(p) * slots_ + b];
            film.add_batch(p, a.count, a.sum, a.sum_sq, b);
            st.samples += a.count;
        }
    // The counters came back with the last launch.
    st.rays.camera = counter(COUNTER_CAMERA);
    st.rays.extension = counter(COUNTER_EXTENSION);
    st.rays.shadow = counter(COUNTER_SHADOW);
    st.nan_samples = counter(COUNTER_NAN);
    return film;
}

uint32_t BatchSession::debug_capacity(const FlatScene& scene, const DebugRequest& d,
                                      uint32_t sample_offset) {
    if (!d.log) return 1;
    const uint64_t n =
        uint64_t(d.end_sample(sample_offset, scene.spp) - d.first_sample(sample_offset)) *
        path_log_records_per_sample(scene.params.max_depth);
    return uint32_t(std::clamp<uint64_t>(n, 1, 1u << 16));
}

void BatchSession::set_pass(uint32_t pass) {
    debug_header_.pass = pass;
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        record_shader_barrier(cmd, stages());
        vkCmdUpdateBuffer(cmd, debug_.handle(), 0, sizeof(DebugHeader), &debug_header_);
    });
}

// A pass of the debug variant other than rendering: one invocation per pixel of the rows, in
// launches of at most kMaxInvocations.
void BatchSession::debug_launch(const BatchParams& b) {
    const uint32_t rows_per_launch = std::max(1u, kMaxInvocations / width_);
    for (uint32_t row = b.row_begin; row < b.row_end; row += rows_per_launch) {
        BatchParams part = b;
        part.row_begin = row;
        part.row_end = std::min(b.row_end, row + rows_per_launch);
        ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
            record_shader_barrier(cmd, stages());
            tracer_.record_debug_launch(cmd, part, width_ * (part.row_end - part.row_begin));
            record_shader_barrier(cmd, stages());
        });
    }
}

// Grows the sample buffer to hold `items` estimates, tagged 0 (no batch's: tags start at 1).
// The constructor allocates what the render's largest submission can need, before the render
// is timed; this grows it only for a render of more samples than the scene's (the viewer).
void BatchSession::reserve_samples(uint64_t items) {
    if (items * kSampleBytes <= samples_.size()) return;
    samples_ = Buffer(ctx_, items * kSampleBytes, kStorage, false);
    ctx_.submit_and_wait(
        [&](VkCommandBuffer cmd) { vkCmdFillBuffer(cmd, samples_.handle(), 0, VK_WHOLE_SIZE, 0); });
    tracer_.bind(BINDING_SAMPLES, samples_);
    resolve_.bind(BINDING_SAMPLES, samples_);
}

uint64_t BatchSession::initial_work() const {
    return std::max(BatchPlanner::kInitialWork, kFirstLaunchItems * resident_invocations());
}

uint64_t BatchSession::max_work() const {
    const uint64_t by_memory = ctx_.info().memory_bytes / kSampleMemoryShare / kSampleBytes;
    const uint64_t bound = ctx_.info().type == "cpu" ? kCpuDeviceMaxWork : BatchPlanner::kMaxWork;
    return std::clamp(by_memory, BatchPlanner::kInitialWork, bound);
}

uint64_t BatchSession::resident_invocations() const {
    return tp::resident_invocations(ctx_.info(), invocations_);
}

void BatchSession::read_buffer(const Buffer& src, void* dst, size_t bytes) const {
    const Buffer host(ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        record_shader_barrier(cmd, stages());
        const VkBufferCopy region{0, 0, bytes};
        vkCmdCopyBuffer(cmd, src.handle(), host.handle(), 1, &region);
        record_host_read_barrier(cmd);
    });
    std::memcpy(dst, host.mapped(), bytes);
}

// One submission: launch the render invocations, resolve the estimates into the accumulators,
// record `after`, copy the counters back. The shaders clear the cut-short and next-item
// counters (interface.h).
void BatchSession::launch(const std::function<void(VkCommandBuffer)>& after) {
    const VkPipelineStageFlags stage = stages();
    const uint64_t resident = resident_invocations();
    const uint32_t invocations = render_invocations(params_.item_count, resident);
    const uint32_t rows = params_.row_end - params_.row_begin;
    const uint32_t resolve_groups =
        (width_ * rows * resolve_slots(params_.sample_count, slots_) + RESOLVE_GROUP_SIZE - 1) /
        RESOLVE_GROUP_SIZE;
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        record_shader_barrier(cmd, stage); // the previous launch's accumulator writes
        timer_.record_mark(cmd, 0);
        if (debug_render_)
            tracer_.record_debug_launch(cmd, params_, invocations);
        else
            tracer_.record_launch(cmd, params_, invocations);
        timer_.record_mark(cmd, 1);
        record_shader_barrier(cmd, stage);
        resolve_.record_dispatch(cmd, &params_, resolve_groups, 1, 1);
        timer_.record_mark(cmd, 2);
        record_shader_barrier(cmd, stage);
        if (after) after(cmd);
        timer_.record_mark(cmd, 3);
        const VkBufferCopy region{0, 0, kCounterBytes};
        vkCmdCopyBuffer(cmd, counters_.handle(), host_counters_.handle(), 1, &region);
        record_host_read_barrier(cmd);
    });
    const std::vector<double> t = timer_.read_intervals();
    split_.trace += t[0];
    split_.resolve += t[1];
    split_.after += t[2];
    gpu_seconds_ += t[0] + t[1];
    ++submissions_;
}

uint64_t BatchSession::counter(uint32_t slot) const {
    const auto* words = static_cast<const uint32_t*>(host_counters_.mapped());
    return uint64_t(words[slot]) | (uint64_t(words[slot + 1]) << 32);
}

} // namespace tp
