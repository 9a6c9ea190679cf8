#include "bench/ladder.h"

#include "bench/result_json.h"
#include "compare/convergence.h"
#include "compare/metrics.h"
#include "render/sampler.h"

#include <fmt/format.h>

#include <limits>

namespace tp::bench {

std::vector<uint32_t> ladder_counts(uint32_t max_spp) {
    std::vector<uint32_t> counts;
    for (uint64_t n = 1; n < max_spp; n *= 2) counts.push_back(uint32_t(n));
    counts.push_back(max_spp);
    return counts;
}

LadderRun run_ladder(const FlatScene& scene, const Backend& backend, const std::string& sampler,
                     const Reference& reference, const BenchOptions& options,
                     const std::function<void(double)>& progress) {
    LadderRun run;
    run.backend = backend;
    run.sampler = sampler;
    FlatScene s = scene;
    s.spp = options.max_spp;

    std::vector<RgbImage> snapshots;
    RenderOptions opt;
    opt.seed = options.seed;
    opt.sampler = sampler_from_name(sampler);
    opt.threads = options.threads;
    opt.progress = progress;
    opt.checkpoints = ladder_counts(options.max_spp);
    opt.on_checkpoint = [&](const RenderResult& snap) {
        ExrImage img = snap.film.to_exr();
        img.integers["twinpath:spp"] = snap.stats.spp;
        snapshots.push_back(
            rgb_image_from_exr(img, fmt::format("{} {} spp", backend.label(), snap.stats.spp)));
        LadderPoint p;
        p.spp = snap.stats.spp;
        p.wall_s = snap.stats.wall_time_s;
        p.gpu_s = snap.stats.gpu_time_s;
        p.rays = snap.stats.rays;
        p.mape = error_metrics(snapshots.back(), reference.image, reference.image).all.mape;
        run.points.push_back(p);
    };
    const RenderResult final = render_on(backend, s, opt, options.device);
    run.threads = final.stats.threads;
    run.accel_bytes = final.stats.accel_bytes;
    run.build_s = final.stats.build_time_s;

    // relMSE, its excess over the reference's own noise, and V: compare --convergence.
    const ConvergenceResult c = convergence(reference.image, snapshots, 0.01);
    for (size_t i = 0; i < run.points.size(); ++i) {
        run.points[i].relmse = c.points[i].relmse;
        run.points[i].excess = c.points[i].excess;
    }
    run.reference_noise = c.reference_noise;
    run.V = c.V;
    run.spp_slope = c.slope;

    std::vector<double> t, e;
    for (const LadderPoint& p : run.points) {
        t.push_back(p.wall_s);
        e.push_back(p.excess);
    }
    run.fit = fit_loglog(t, e);
    run.time_to_1e2 = time_to_reach(run.fit, e, 1e-2);
    run.time_to_1e3 = time_to_reach(run.fit, e, 1e-3);
    return run;
}

nlohmann::json ladder_json(const LadderRun& run) {
    nlohmann::json j;
    j["backend"] = run.backend.name;
    j["mode"] = run.backend.mode;
    j["sampler"] = run.sampler;
    j["device"] = run.backend.device;
    j["threads"] = run.threads;
    j["accel_bytes"] = run.accel_bytes;
    j["build_s"] = run.build_s;
    j["reference_noise"] = run.reference_noise;
    j["V"] = run.V;
    j["spp_slope"] = number_or_null(run.spp_slope);
    j["fit"] = run.fit.valid() ? nlohmann::json{{"log10_intercept", run.fit.intercept},
                                                {"slope", run.fit.slope},
                                                {"points", run.fit.points}}
                               : nlohmann::json(nullptr);
    j["time_to_relmse"] = {{"1e-2", number_or_null(run.time_to_1e2)},
                           {"1e-3", number_or_null(run.time_to_1e3)}};
    nlohmann::json pts = nlohmann::json::array();
    for (const LadderPoint& p : run.points) {
        const double t = p.wall_s;
        // The thesis's efficiency epsilon = 1 / (V T) (sec. 2.6), V the error left at time T.
        const double efficiency =
            p.excess > 0 && t > 0 ? 1.0 / (p.excess * t) : std::numeric_limits<double>::quiet_NaN();
        nlohmann::json rays = rays_json(p.rays);
        pts.push_back({{"spp", p.spp},
                       {"wall_s", t},
                       {"gpu_s", gpu_seconds(p.gpu_s)},
                       {"relmse", p.relmse},
                       {"relmse_excess", p.excess},
                       {"mape", p.mape},
                       {"efficiency", number_or_null(efficiency)},
                       {"mrays_per_s", mrays_per_s(rays, nullptr, t)},
                       {"rays", rays}});
    }
    j["points"] = pts;
    return j;
}

} // namespace tp::bench
