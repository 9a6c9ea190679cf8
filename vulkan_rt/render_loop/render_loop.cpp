#include "vulkan_rt/render_loop/render_loop.h"

#include "render/sampler.h"
#include "util/clock.h"
#include "util/error.h"
#include "vulkan_rt/render_loop/batch_session.h"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace tp {
namespace {

// Wall time aimed at per submission: short against display watchdogs (2 s on Windows) and
// --time-limit, long against the ~0.1 ms cost of a submit-and-wait round trip.
constexpr double kTargetSubmitSeconds = 0.1;

} // namespace

RenderParams seeded_params(const FlatScene& scene, const RenderOptions& options) {
    RenderParams p = scene.params;
    p.seed = options.seed;
    p.sampler_id = options.sampler;
    return p;
}

RenderResult render_batches(const VulkanContext& ctx, const FlatScene& scene,
                            const RenderOptions& options, ModeSetup& mode) {
    Tracer& tracer = *mode.tracer;
    const AccelStats& accel = mode.accel;
    RenderResult result;
    RenderStats& st = result.stats;
    st.backend = "vulkan";
    st.mode = vk_mode_name(tracer.mode());
    st.device = ctx.info().name;
    st.scene = scene.name;
    st.seed = options.seed;
    st.sampler = sampler_name(options.sampler);
    st.width = scene.params.camera.width;
    st.height = scene.params.camera.height;
    st.build_time_s = accel.build_time_s;
    st.upload_time_s = accel.upload_time_s;
    st.accel_bytes = accel.bytes;
    count_triangles(st, scene);
    for (const auto& [key, value] : accel.extra) st.extra[key] = value;
    st.pipeline = accel.pipeline;

    BatchSession session(ctx, scene, mode.buffers, tracer, options.debug, options.sample_offset,
                         options.sampler, options.gpu_invocations);
    const auto t0 = std::chrono::steady_clock::now();
    double snapshot_seconds = 0; // read-backs for checkpoints: not rendering time
    uint64_t work = session.initial_work();
    bool stopped = false;
    if (options.on_first_pass) options.on_first_pass();
    // One range, [sample_offset, sample_offset + spp), or those options.sample_source grants.
    while (!stopped) {
        RenderOptions::SampleGrant range{options.sample_offset, scene.spp};
        if (options.sample_source) {
            const double s = seconds_since(t0);
            range = options.sample_source(s > 0 ? double(st.spp) * st.width * st.height / s : 0);
            if (range.count == 0) break;
        }
        session.set_sample_offset(range.begin);
        BatchPlanner planner(st.width, st.height, range.count, kTargetSubmitSeconds, work,
                             session.max_work());
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
    st.extra["render_invocations"] = std::to_string(session.resident_invocations());
    result.film = session.read_back(st);
    st.device_memory_peak_bytes = ctx.memory_tally().peak();
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
