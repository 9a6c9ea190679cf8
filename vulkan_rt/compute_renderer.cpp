#include "vulkan_rt/compute_renderer.h"

#include "shaders/interface.h"
#include "util/error.h"
#include "vulkan_rt/batch_planner.h"
#include "vulkan_rt/bvh_builder.h"
#include "vulkan_rt/compute_program.h"
#include "vulkan_rt/gpu_timer.h"
#include "vulkan_rt/scene_buffers.h"

#include <chrono>
#include <cstring>
#include <utility>

// Generated from shaders/render_compute.comp (shaders/spirv.cmake).
#include "render_compute.spv.h"

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

// The device side of one render: scene, BVH, accumulators, counters and the pipeline.
class ComputeSession {
  public:
    ComputeSession(const VulkanContext& ctx, const FlatScene& scene, uint32_t seed, BvhBuild bvh)
        : ctx_(ctx), width_(scene.params.camera.width), height_(scene.params.camera.height),
          bvh_(std::move(bvh)), scene_(upload_scene(ctx, scene, seeded(scene, seed), bvh_)),
          accum_(ctx, VkDeviceSize(width_) * height_ * sizeof(PixelAccum), kStorage, false),
          counters_(ctx, kCounterBytes, kStorage, false),
          host_counters_(ctx, kCounterBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true),
          program_(ctx, tp_spirv_render_compute, sizeof(tp_spirv_render_compute), BINDING_COUNT,
                   sizeof(BatchParams)),
          timer_(ctx) {
        std::vector<const Buffer*> bound;
        for (const Buffer& b : scene_.slots) bound.push_back(&b);
        bound.push_back(&accum_);
        bound.push_back(&counters_);
        std::vector<VkBuffer> bindings;
        for (const Buffer* b : bound) {
            // A binding covers its whole buffer, which must fit the device's range.
            if (b->size() > ctx.limits().maxStorageBufferRange)
                runtime_error("a {:.1f} MiB buffer (binding {}) exceeds the {:.1f} MiB "
                              "storage-buffer range of {}; lower --width/--height or use a "
                              "smaller scene",
                              double(b->size()) / 1048576.0, bindings.size(),
                              double(ctx.limits().maxStorageBufferRange) / 1048576.0,
                              ctx.info().name);
            bindings.push_back(b->handle());
        }
        program_.bind(bindings);
        std::memset(host_counters_.mapped(), 0, kCounterBytes);
        ctx.submit_and_wait([&](VkCommandBuffer cmd) {
            vkCmdFillBuffer(cmd, accum_.handle(), 0, VK_WHOLE_SIZE, 0);
            vkCmdFillBuffer(cmd, counters_.handle(), 0, VK_WHOLE_SIZE, 0);
        });
        params_.bvh_top_root = bvh_.top_root;
        params_.env_table_size = uint32_t(scene.env_table.size());
        params_.probe_iterations = LOOP_PROBE_ITERATIONS;
    }

    uint64_t accel_bytes() const { return bvh_.bytes(); }
    double gpu_seconds() const { return timer_.active() ? gpu_seconds_ : -1.0; }
    uint32_t submissions() const { return submissions_; }
    uint32_t repeats() const { return repeats_; }

    // Traces the batch to completion. Dispatches are repeated while some pixels stopped early
    // (accumulate.glsl, loop budget); each repetition resumes them where they stopped. Returns
    // whether that happened.
    bool run(const Batch& b) {
        params_.sample_begin = b.sample_begin;
        params_.sample_count = b.sample_count;
        params_.row_begin = b.row_begin;
        params_.row_end = b.row_end;
        bool cut_short = false;
        for (uint64_t camera = counter(COUNTER_CAMERA);; camera = counter(COUNTER_CAMERA)) {
            dispatch(b);
            if (counter(COUNTER_TRUNCATED) == 0) return cut_short;
            if (counter(COUNTER_CAMERA) == camera)
                runtime_error("the Vulkan device ends shader loops before one path is traced "
                              "(lavapipe allows 65535 loop iterations per invocation); lower "
                              "--max-depth");
            cut_short = true;
            ++repeats_;
        }
    }

    // Merges every pixel into a double-precision film and fills the counters of `st`.
    Film read_back(RenderStats& st) const {
        const Buffer host(ctx_, accum_.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
        ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
            record_compute_barrier(cmd);
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
        // The counters came back with the last dispatch.
        st.rays.camera = counter(COUNTER_CAMERA);
        st.rays.extension = counter(COUNTER_EXTENSION);
        st.rays.shadow = counter(COUNTER_SHADOW);
        st.nan_samples = counter(COUNTER_NAN);
        return film;
    }

  private:
    static constexpr VkDeviceSize kCounterBytes = COUNTER_WORDS * sizeof(uint32_t);

    static RenderParams seeded(const FlatScene& scene, uint32_t seed) {
        RenderParams p = scene.params;
        p.seed = seed;
        return p;
    }

    // One submission: clear the cut-short counter, dispatch the batch's rows, copy the
    // counters back.
    void dispatch(const Batch& b) {
        const uint32_t groups_x = (width_ + RENDER_GROUP_X - 1) / RENDER_GROUP_X;
        const uint32_t groups_y = (b.row_end - b.row_begin + RENDER_GROUP_Y - 1) / RENDER_GROUP_Y;
        ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
            record_compute_barrier(cmd); // the previous dispatch's accumulator writes
            vkCmdFillBuffer(cmd, counters_.handle(), COUNTER_TRUNCATED * sizeof(uint32_t),
                            2 * sizeof(uint32_t), 0);
            record_compute_barrier(cmd);
            timer_.record_begin(cmd);
            program_.record_dispatch(cmd, &params_, groups_x, groups_y, 1);
            timer_.record_end(cmd);
            record_compute_barrier(cmd);
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
    uint32_t width_, height_;
    BvhBuild bvh_;
    SceneBuffers scene_;
    Buffer accum_, counters_, host_counters_;
    ComputeProgram program_;
    GpuTimer timer_;
    BatchParams params_{};
    double gpu_seconds_ = 0;
    uint32_t submissions_ = 0, repeats_ = 0;
};

} // namespace

RenderResult render_compute(const VulkanContext& ctx, const FlatScene& scene,
                            const RenderOptions& options) {
    RenderResult result;
    RenderStats& st = result.stats;
    st.backend = "vulkan";
    st.mode = "compute";
    st.device = ctx.info().name;
    st.scene = scene.name;
    st.seed = options.seed;
    st.width = scene.params.camera.width;
    st.height = scene.params.camera.height;

    const auto t_build = std::chrono::steady_clock::now();
    BvhBuild bvh = build_bvh(scene);
    st.build_time_s = seconds_since(t_build);
    ComputeSession session(ctx, scene, options.seed, std::move(bvh));
    st.accel_bytes = session.accel_bytes();

    BatchPlanner planner(st.width, st.height, scene.spp, kTargetSubmitSeconds);
    planner.stop_at(options.next_stop(0, scene.spp));
    const auto t0 = std::chrono::steady_clock::now();
    double snapshot_seconds = 0; // read-backs for checkpoints: not rendering time
    while (!planner.done()) {
        const Batch b = planner.next();
        const auto t_batch = std::chrono::steady_clock::now();
        const bool cut_short = session.run(b);
        planner.completed(b, seconds_since(t_batch), cut_short);
        if (options.progress) options.progress(planner.fraction_done());
        if (planner.done() && options.on_checkpoint && options.is_checkpoint(planner.samples_done())) {
            const auto t_snap = std::chrono::steady_clock::now();
            RenderResult snapshot{Film(), st};
            snapshot.stats.wall_time_s = seconds_since(t0) - snapshot_seconds;
            snapshot.stats.gpu_time_s = session.gpu_seconds();
            snapshot.stats.spp = planner.samples_done();
            snapshot.film = session.read_back(snapshot.stats);
            options.on_checkpoint(snapshot);
            snapshot_seconds += seconds_since(t_snap);
        }
        planner.stop_at(options.next_stop(planner.samples_done(), scene.spp));
        if (planner.at_pass_boundary() && options.time_limit_s > 0 &&
            seconds_since(t0) >= options.time_limit_s)
            break;
    }
    st.wall_time_s = seconds_since(t0) - snapshot_seconds;
    st.gpu_time_s = session.gpu_seconds();
    st.spp = planner.samples_done();
    st.extra["submissions"] = std::to_string(session.submissions());
    st.extra["repeated_submissions"] = std::to_string(session.repeats());
    result.film = session.read_back(st);
    return result;
}

} // namespace tp
