#include "vulkan_rt/renderer/batch_session.h"

#include "render/sampler.h"
#include "util/error.h"
#include "vulkan_rt/device/barriers.h"

#include <algorithm>
#include <cstring>

namespace tp {
namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                        VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                        VK_BUFFER_USAGE_TRANSFER_DST_BIT;

} // namespace

BatchSession::BatchSession(const VulkanContext& ctx, const FlatScene& scene, const SceneBuffers& sb,
                           Tracer& tracer, const DebugRequest& debug, uint32_t sample_offset,
                           uint32_t sampler)
    : ctx_(ctx), tracer_(tracer), sample_offset_(sample_offset), width_(scene.params.camera.width),
      height_(scene.params.camera.height), batches_(film_batches(sampler)),
      slots_(accum_slots(sampler)),
      accum_(ctx, VkDeviceSize(width_) * height_ * slots_ * sizeof(PixelAccum), kStorage, false),
      counters_(ctx, kCounterBytes, kStorage, false),
      host_counters_(ctx, kCounterBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true),
      debug_capacity_(debug_capacity(scene, debug, sample_offset)),
      debug_(ctx, sizeof(DebugHeader) + VkDeviceSize(debug_capacity_) * sizeof(PathVertex),
             kStorage, false),
      aov_(ctx, debug.aov ? VkDeviceSize(width_) * height_ * sizeof(PixelAov) : sizeof(PixelAov),
           kStorage, false),
      timer_(ctx) {
    for (uint32_t slot = 0; slot < sb.slots.size(); ++slot) tracer.bind(slot, sb.slots[slot]);
    tracer.bind(BINDING_ACCUM, accum_);
    tracer.bind(BINDING_COUNTERS, counters_);
    tracer.bind(BINDING_DEBUG, debug_);
    tracer.bind(BINDING_AOV, aov_);
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
        record_shader_barrier(cmd, tracer.shader_stage());
        vkCmdUpdateBuffer(cmd, debug_.handle(), 0, sizeof(DebugHeader), &debug_header_);
    });
    params_.env_table_size = uint32_t(scene.env_table.size());
    params_.probe_iterations = LOOP_PROBE_ITERATIONS;
}

void BatchSession::clear() {
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        record_shader_barrier(cmd, tracer_.shader_stage());
        vkCmdFillBuffer(cmd, accum_.handle(), 0, VK_WHOLE_SIZE, 0);
        vkCmdFillBuffer(cmd, counters_.handle(), 0, VK_WHOLE_SIZE, 0);
        record_shader_barrier(cmd, tracer_.shader_stage());
    });
    std::memset(host_counters_.mapped(), 0, kCounterBytes);
}

bool BatchSession::run(const Batch& b) {
    params_.sample_begin = sample_offset_ + b.sample_begin;
    params_.sample_count = b.sample_count;
    params_.row_begin = b.row_begin;
    params_.row_end = b.row_end;
    bool cut_short = false;
    for (uint64_t camera = counter(COUNTER_CAMERA);; camera = counter(COUNTER_CAMERA)) {
        launch();
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
        record_shader_barrier(cmd, tracer_.shader_stage());
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
        record_shader_barrier(cmd, tracer_.shader_stage());
        vkCmdUpdateBuffer(cmd, debug_.handle(), 0, sizeof(DebugHeader), &debug_header_);
    });
}

void BatchSession::debug_launch(const BatchParams& b) {
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        record_shader_barrier(cmd, tracer_.shader_stage());
        tracer_.record_debug_launch(cmd, b, width_);
        record_shader_barrier(cmd, tracer_.shader_stage());
    });
}

void BatchSession::read_buffer(const Buffer& src, void* dst, size_t bytes) const {
    const Buffer host(ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        record_shader_barrier(cmd, tracer_.shader_stage());
        const VkBufferCopy region{0, 0, bytes};
        vkCmdCopyBuffer(cmd, src.handle(), host.handle(), 1, &region);
        record_host_read_barrier(cmd);
    });
    std::memcpy(dst, host.mapped(), bytes);
}

// One submission: clear the cut-short counter, launch the batch's rows, copy the counters
// back.
void BatchSession::launch() {
    const VkPipelineStageFlags stage = tracer_.shader_stage();
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        record_shader_barrier(cmd, stage); // the previous launch's accumulator writes
        vkCmdFillBuffer(cmd, counters_.handle(), COUNTER_TRUNCATED * sizeof(uint32_t),
                        2 * sizeof(uint32_t), 0);
        record_shader_barrier(cmd, stage);
        timer_.record_begin(cmd);
        if (debug_render_)
            tracer_.record_debug_launch(cmd, params_, width_);
        else
            tracer_.record_launch(cmd, params_, width_);
        timer_.record_end(cmd);
        record_shader_barrier(cmd, stage);
        const VkBufferCopy region{0, 0, kCounterBytes};
        vkCmdCopyBuffer(cmd, counters_.handle(), host_counters_.handle(), 1, &region);
        record_host_read_barrier(cmd);
    });
    gpu_seconds_ += timer_.read_seconds();
    ++submissions_;
}

uint64_t BatchSession::counter(uint32_t slot) const {
    const auto* words = static_cast<const uint32_t*>(host_counters_.mapped());
    return uint64_t(words[slot]) | (uint64_t(words[slot + 1]) << 32);
}

} // namespace tp
