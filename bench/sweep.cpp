#include "bench/sweep.h"

#include "bench/result_json.h"

#include <algorithm>

namespace tp::bench {
namespace {

SweepRow row_from(const RenderStats& s, uint32_t depth) {
    SweepRow r;
    r.depth = depth;
    r.spp = s.spp;
    r.wall_s = s.wall_time_s;
    r.gpu_s = s.gpu_time_s;
    r.rays = s.rays;
    r.samples = s.samples;
    return r;
}

nlohmann::json rows_json(const std::vector<SweepRow>& rows) {
    nlohmann::json a = nlohmann::json::array();
    for (const SweepRow& r : rows)
        a.push_back({{"depth", r.depth},
                     {"spp", r.spp},
                     {"wall_s", r.wall_s},
                     {"gpu_s", gpu_seconds(r.gpu_s)},
                     {"samples", r.samples},
                     {"rays", rays_json(r.rays)}});
    return a;
}

} // namespace

SweepRun run_sweep(const FlatScene& scene, const Backend& backend, const BenchOptions& options,
                   const std::function<void(double)>& progress) {
    SweepRun run;
    run.backend = backend;
    // Progress over the whole sweep, weighting each render by its samples times its depth.
    double total = 0, done = 0;
    for (uint32_t d : options.table_depths) total += double(options.table_fixed_spp) * d;
    const uint32_t max_s = *std::max_element(options.table_spp.begin(), options.table_spp.end());
    total += double(max_s) * options.table_fixed_depth;
    const auto render = [&](uint32_t depth, uint32_t spp, RenderOptions opt) {
        FlatScene s = scene;
        s.params.max_depth = s.params.min_depth = depth;
        s.spp = spp;
        opt.seed = options.seed;
        opt.threads = options.threads;
        const double weight = double(spp) * depth;
        if (progress)
            opt.progress = [&, weight](double f) { progress((done + f * weight) / total); };
        const RenderResult r = render_on(backend, s, opt, options.device);
        done += weight;
        run.accel_bytes = r.stats.accel_bytes;
        run.build_s = r.stats.build_time_s;
        run.extra = r.stats.extra;
        return r;
    };

    for (uint32_t d : options.table_depths)
        run.depth_rows.push_back(row_from(render(d, options.table_fixed_spp, {}).stats, d));

    RenderOptions opt;
    opt.checkpoints = options.table_spp;
    opt.on_checkpoint = [&](const RenderResult& snap) {
        run.spp_rows.push_back(row_from(snap.stats, options.table_fixed_depth));
    };
    render(options.table_fixed_depth, max_s, opt);
    return run;
}

nlohmann::json sweep_json(const SweepRun& run) {
    return {{"backend", run.backend.name},
            {"mode", run.backend.mode},
            {"device", run.backend.device},
            {"accel_bytes", run.accel_bytes},
            {"build_s", run.build_s},
            {"extra", run.extra},
            {"depth_rows", rows_json(run.depth_rows)},
            {"spp_rows", rows_json(run.spp_rows)}};
}

} // namespace tp::bench
