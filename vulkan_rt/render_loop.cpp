#include "vulkan_rt/render_loop.h"

#include "util/error.h"
#include "vulkan_rt/barriers.h"
#include "vulkan_rt/batch_planner.h"
#include "vulkan_rt/gpu_timer.h"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace tp {
namespace {

// Wall time aimed at per submission: short against display watchdogs (2 s on Windows) and
// --time-limit, long against the ~0.1 ms cost of a submit-and-wait round trip.
constexpr double kTargetSubmitSeconds = 0.1;

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                        VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                        VK_BUFFER_USAGE_TRANSFER_DST_BIT;

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The accumulators, counters and timer of one render, and the batches run through a Tracer.
class BatchSession {
  public:
    BatchSession(const VulkanContext& ctx, const FlatScene& scene, const SceneBuffers& sb,
                 Tracer& tracer, const DebugRequest& debug, uint32_t sample_offset)
        : ctx_(ctx), tracer_(tracer), sample_offset_(sample_offset),
          width_(scene.params.camera.width), height_(scene.params.camera.height),
          accum_(ctx, VkDeviceSize(width_) * height_ * sizeof(PixelAccum), kStorage, false),
          counters_(ctx, kCounterBytes, kStorage, false),
          host_counters_(ctx, kCounterBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true),
          debug_capacity_(debug_capacity(scene, debug, sample_offset)),
          debug_(ctx, sizeof(DebugHeader) + VkDeviceSize(debug_capacity_) * sizeof(PathVertex),
                 kStorage, false),
          aov_(ctx,
               debug.aov ? VkDeviceSize(width_) * height_ * sizeof(PixelAov) : sizeof(PixelAov),
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

    double gpu_seconds() const { return timer_.active() ? gpu_seconds_ : -1.0; }
    uint32_t submissions() const { return submissions_; }
    uint32_t repeats() const { return repeats_; }

    // The first sample of the range that the batches' sample_begin counts from.
    void set_sample_offset(uint32_t first) { sample_offset_ = first; }

    // Traces the batch to completion. Dispatches are repeated while some pixels stopped early
    // (accumulate.glsl, loop budget); each repetition resumes them where they stopped. Returns
    // whether that happened.
    bool run(const Batch& b) {
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
    std::vector<PixelAov> aovs() {
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
    void path_log(uint32_t first, uint32_t end, uint32_t y, DebugOutput& out) {
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
    Film read_back(RenderStats& st) const {
        const Buffer host(ctx_, accum_.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
        ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
            record_shader_barrier(cmd, tracer_.shader_stage());
            const VkBufferCopy region{0, 0, accum_.size()};
            vkCmdCopyBuffer(cmd, accum_.handle(), host.handle(), 1, &region);
            record_host_read_barrier(cmd);
        });
        const auto* pixels = static_cast<const PixelAccum*>(host.mapped());
        Film film(width_, height_);
        for (uint32_t p = 0; p < width_ * height_; ++p) {
            film.add_batch(p, pixels[p].count, pixels[p].sum, pixels[p].sum_sq);
            st.samples += pixels[p].count;
        }
        // The counters came back with the last launch.
        st.rays.camera = counter(COUNTER_CAMERA);
        st.rays.extension = counter(COUNTER_EXTENSION);
        st.rays.shadow = counter(COUNTER_SHADOW);
        st.nan_samples = counter(COUNTER_NAN);
        return film;
    }

  private:
    static constexpr VkDeviceSize kCounterBytes = COUNTER_WORDS * sizeof(uint32_t);
    // Path-log records the GPU can hold: every logged sample's longest path, at most 2^16
    // (18 MiB); further records are counted as dropped.
    static uint32_t debug_capacity(const FlatScene& scene, const DebugRequest& d,
                                   uint32_t sample_offset) {
        if (!d.log) return 1;
        const uint64_t n =
            uint64_t(d.end_sample(sample_offset, scene.spp) - d.first_sample(sample_offset)) *
            path_log_records_per_sample(scene.params.max_depth);
        return uint32_t(std::clamp<uint64_t>(n, 1, 1u << 16));
    }

    void set_pass(uint32_t pass) {
        debug_header_.pass = pass;
        ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
            record_shader_barrier(cmd, tracer_.shader_stage());
            vkCmdUpdateBuffer(cmd, debug_.handle(), 0, sizeof(DebugHeader), &debug_header_);
        });
    }

    void debug_launch(const BatchParams& b) {
        ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
            record_shader_barrier(cmd, tracer_.shader_stage());
            tracer_.record_debug_launch(cmd, b, width_);
            record_shader_barrier(cmd, tracer_.shader_stage());
        });
    }

    void read_buffer(const Buffer& src, void* dst, size_t bytes) const {
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
    void launch() {
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

    uint64_t counter(uint32_t slot) const {
        const auto* words = static_cast<const uint32_t*>(host_counters_.mapped());
        return uint64_t(words[slot]) | (uint64_t(words[slot + 1]) << 32);
    }

    const VulkanContext& ctx_;
    Tracer& tracer_;
    uint32_t sample_offset_;
    uint32_t width_, height_;
    Buffer accum_, counters_, host_counters_;
    uint32_t debug_capacity_;
    Buffer debug_, aov_;
    DebugHeader debug_header_{};
    bool debug_render_ = false; // the image itself is rendered by the debug variant
    GpuTimer timer_;
    BatchParams params_{};
    double gpu_seconds_ = 0;
    uint32_t submissions_ = 0, repeats_ = 0;
};

} // namespace

RenderParams seeded_params(const FlatScene& scene, uint32_t seed) {
    RenderParams p = scene.params;
    p.seed = seed;
    return p;
}

RenderResult render_batches(const VulkanContext& ctx, const FlatScene& scene,
                            const RenderOptions& options, const SceneBuffers& scene_buffers,
                            Tracer& tracer, const AccelStats& accel) {
    RenderResult result;
    RenderStats& st = result.stats;
    st.backend = "vulkan";
    st.mode = tracer.mode();
    st.device = ctx.info().name;
    st.scene = scene.name;
    st.seed = options.seed;
    st.width = scene.params.camera.width;
    st.height = scene.params.camera.height;
    st.build_time_s = accel.build_time_s;
    st.accel_bytes = accel.bytes;
    for (const auto& [key, value] : accel.extra) st.extra[key] = value;
    st.pipeline = accel.pipeline;

    BatchSession session(ctx, scene, scene_buffers, tracer, options.debug, options.sample_offset);
    const auto t0 = std::chrono::steady_clock::now();
    double snapshot_seconds = 0; // read-backs for checkpoints: not rendering time
    uint64_t work = BatchPlanner::kInitialWork;
    bool stopped = false;
    // One range, [sample_offset, sample_offset + spp), or those options.sample_source grants.
    while (!stopped) {
        RenderOptions::SampleGrant range{options.sample_offset, scene.spp};
        if (options.sample_source) {
            const double s = seconds_since(t0);
            range = options.sample_source(s > 0 ? double(st.spp) * st.width * st.height / s : 0);
            if (range.count == 0) break;
        }
        session.set_sample_offset(range.begin);
        BatchPlanner planner(st.width, st.height, range.count, kTargetSubmitSeconds, work);
        planner.stop_at(options.next_stop(0, range.count));
        while (!planner.done()) {
            const Batch b = planner.next();
            const auto t_batch = std::chrono::steady_clock::now();
            const bool cut_short = session.run(b);
            planner.completed(b, seconds_since(t_batch), cut_short);
            if (options.progress) options.progress(planner.fraction_done());
            if (planner.done() && options.on_checkpoint &&
                options.is_checkpoint(planner.samples_done())) {
                const auto t_snap = std::chrono::steady_clock::now();
                RenderResult snapshot{Film(), st, {}};
                snapshot.stats.wall_time_s = seconds_since(t0) - snapshot_seconds;
                snapshot.stats.gpu_time_s = session.gpu_seconds();
                snapshot.stats.spp = planner.samples_done();
                snapshot.film = session.read_back(snapshot.stats);
                options.on_checkpoint(snapshot);
                snapshot_seconds += seconds_since(t_snap);
            }
            planner.stop_at(options.next_stop(planner.samples_done(), range.count));
            stopped = (options.time_limit_s > 0 && seconds_since(t0) >= options.time_limit_s) ||
                      options.stop_requested();
            if (planner.at_pass_boundary() && stopped) break;
        }
        work = planner.work();
        st.spp += planner.samples_done();
        if (planner.samples_done() > 0)
            st.sample_ranges.push_back(
                {options.seed, range.begin, uint64_t(range.begin) + planner.samples_done()});
        if (!options.sample_source) break;
    }
    st.wall_time_s = seconds_since(t0) - snapshot_seconds;
    st.gpu_time_s = session.gpu_seconds();
    st.extra["submissions"] = std::to_string(session.submissions());
    st.extra["repeated_submissions"] = std::to_string(session.repeats());
    result.film = session.read_back(st);
    const DebugRequest& d = options.debug;
    if (d.aov) result.debug.aovs = session.aovs();
    const uint32_t K = options.sample_offset;
    if (d.log)
        session.path_log(d.first_sample(K), std::min(d.end_sample(K, st.spp), K + st.spp),
                         d.pixel_y, result.debug);
    return result;
}

std::vector<uint32_t> debug_spirv(const uint32_t* embedded, size_t bytes) {
    const char* path = std::getenv("TWINPATH_DEBUG_SPIRV");
    if (!path || !*path) return std::vector<uint32_t>(embedded, embedded + bytes / 4);
    std::ifstream in(path, std::ios::binary);
    std::vector<char> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) runtime_error("TWINPATH_DEBUG_SPIRV={}: cannot read it", path);
    if (data.empty() || data.size() % 4 != 0)
        runtime_error("TWINPATH_DEBUG_SPIRV={}: not a SPIR-V module", path);
    std::vector<uint32_t> words(data.size() / 4);
    std::memcpy(words.data(), data.data(), data.size());
    return words;
}

bool debug_spirv_overridden() {
    const char* path = std::getenv("TWINPATH_DEBUG_SPIRV");
    return path && *path;
}

} // namespace tp
