#include "vulkan_rt/compute_renderer.h"

#include "render_compute.spv.h"
#include "shaders/interface.h"
#include "util/error.h"
#include "vulkan_rt/batch_planner.h"
#include "vulkan_rt/bvh_builder.h"
#include "vulkan_rt/compute_program.h"
#include "vulkan_rt/gpu_timer.h"
#include "vulkan_rt/scene_buffers.h"

#include <chrono>
#include <cstring>

namespace tp {
namespace {

// Wall time aimed at per submission: short against display watchdogs (2 s on Windows) and
// --time-limit, long against the ~0.1 ms cost of a submit-and-wait round trip.
constexpr double kTargetSubmitSeconds = 0.1;

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

uint64_t counter(const uint32_t* words, uint32_t slot) {
    return uint64_t(words[slot]) | (uint64_t(words[slot + 1]) << 32);
}

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
    const uint32_t W = scene.params.camera.width, H = scene.params.camera.height;
    st.width = W;
    st.height = H;

    const auto t_build = std::chrono::steady_clock::now();
    const BvhBuild bvh = build_bvh(scene);
    RenderParams params = scene.params;
    params.seed = options.seed;
    const SceneBuffers sb = upload_scene(ctx, scene, params, bvh);
    st.build_time_s = seconds_since(t_build);
    st.accel_bytes = bvh.bytes();

    const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                     VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                     VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    const VkDeviceSize accum_bytes = VkDeviceSize(W) * H * sizeof(PixelAccum);
    const VkDeviceSize counter_bytes = COUNTER_WORDS * sizeof(uint32_t);
    const Buffer accum(ctx, accum_bytes, usage, false);
    const Buffer counters(ctx, counter_bytes, usage, false);

    ComputeProgram program(ctx, tp_spirv_render_compute, sizeof(tp_spirv_render_compute),
                           BINDING_COUNT, sizeof(BatchParams));
    std::vector<VkBuffer> bindings;
    for (const Buffer& b : sb.slots) bindings.push_back(b.handle());
    bindings.push_back(accum.handle());
    bindings.push_back(counters.handle());
    program.bind(bindings);
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
        vkCmdFillBuffer(cmd, accum.handle(), 0, VK_WHOLE_SIZE, 0);
        vkCmdFillBuffer(cmd, counters.handle(), 0, VK_WHOLE_SIZE, 0);
    });

    const GpuTimer timer(ctx);
    const Buffer host_counters(ctx, counter_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    auto* words = static_cast<uint32_t*>(host_counters.mapped());
    std::memset(words, 0, counter_bytes);
    BatchPlanner planner(W, H, scene.spp, kTargetSubmitSeconds);
    BatchParams bp{};
    bp.bvh_top_root = bvh.top_root;
    bp.env_table_size = uint32_t(scene.env_table.size());
    bp.probe_iterations = LOOP_PROBE_ITERATIONS;
    double gpu_seconds = 0;
    uint32_t submissions = 0, repeats = 0;
    const auto t0 = std::chrono::steady_clock::now();
    while (!planner.done()) {
        const Batch b = planner.next();
        bp.sample_begin = b.sample_begin;
        bp.sample_count = b.sample_count;
        bp.row_begin = b.row_begin;
        bp.row_end = b.row_end;
        const uint32_t groups_x = (W + RENDER_GROUP_X - 1) / RENDER_GROUP_X;
        const uint32_t groups_y = (b.row_end - b.row_begin + RENDER_GROUP_Y - 1) / RENDER_GROUP_Y;
        const auto t_submit = std::chrono::steady_clock::now();
        // Repeated while some pixels stopped early (accumulate.glsl, loop budget); each
        // repetition resumes them where they stopped.
        bool cut_short = false;
        for (uint64_t camera_before = counter(words, COUNTER_CAMERA);; ++repeats) {
            ctx.submit_and_wait([&](VkCommandBuffer cmd) {
                record_compute_barrier(cmd); // the previous dispatch's accumulator writes
                vkCmdFillBuffer(cmd, counters.handle(), COUNTER_TRUNCATED * sizeof(uint32_t),
                                2 * sizeof(uint32_t), 0);
                record_compute_barrier(cmd);
                timer.record_begin(cmd);
                program.record_dispatch(cmd, &bp, groups_x, groups_y, 1);
                timer.record_end(cmd);
                record_compute_barrier(cmd);
                const VkBufferCopy region{0, 0, counter_bytes};
                vkCmdCopyBuffer(cmd, counters.handle(), host_counters.handle(), 1, &region);
                record_host_read_barrier(cmd);
            });
            gpu_seconds += timer.read_seconds();
            ++submissions;
            if (counter(words, COUNTER_TRUNCATED) == 0) break;
            if (counter(words, COUNTER_CAMERA) == camera_before)
                runtime_error("the Vulkan device ends shader loops before one path is traced "
                              "(lavapipe allows 65535 loop iterations per invocation); lower "
                              "--max-depth");
            camera_before = counter(words, COUNTER_CAMERA);
            cut_short = true;
        }
        planner.completed(b, seconds_since(t_submit), cut_short);
        if (options.progress) options.progress(planner.fraction_done());
        if (planner.at_pass_boundary() && options.time_limit_s > 0 &&
            seconds_since(t0) >= options.time_limit_s)
            break;
    }
    st.wall_time_s = seconds_since(t0);
    st.gpu_time_s = timer.active() ? gpu_seconds : -1.0;
    st.spp = planner.samples_done();
    st.extra["submissions"] = std::to_string(submissions);
    st.extra["repeated_submissions"] = std::to_string(repeats);

    // Read back and merge into the double-precision film; the counters came back with the
    // last dispatch.
    const Buffer host(ctx, accum_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
        record_compute_barrier(cmd);
        const VkBufferCopy region{0, 0, accum_bytes};
        vkCmdCopyBuffer(cmd, accum.handle(), host.handle(), 1, &region);
        record_host_read_barrier(cmd);
    });
    const auto* pixels = static_cast<const PixelAccum*>(host.mapped());
    result.film = Film(W, H);
    for (uint32_t p = 0; p < W * H; ++p) {
        result.film.add_batch(p, pixels[p].count, pixels[p].sum, pixels[p].sum_sq);
        st.samples += pixels[p].count;
    }
    st.rays.camera = counter(words, COUNTER_CAMERA);
    st.rays.extension = counter(words, COUNTER_EXTENSION);
    st.rays.shadow = counter(words, COUNTER_SHADOW);
    st.nan_samples = counter(words, COUNTER_NAN);
    return result;
}

} // namespace tp
