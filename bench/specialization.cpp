#include "bench/specialization.h"

#include "scene/features.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

using nlohmann::json;

namespace tp::bench {
namespace {

struct Timing {
    double wall_per_spp = std::numeric_limits<double>::infinity();
    double gpu_per_spp = std::numeric_limits<double>::infinity(); // inf: not measured
    RenderStats last;
};

} // namespace

json run_specialization(const FlatScene& scene, const Backend& backend, const BenchOptions& o,
                        const std::function<void(double)>& progress) {
    FlatScene s = scene;
    s.spp = o.spec_spp;
    Timing t[2]; // 0: every feature, 1: the scene's
    const uint32_t rounds = std::max<uint32_t>(o.spec_rounds, 1);
    for (uint32_t round = 0; round < rounds; ++round)
        for (int v = 0; v < 2; ++v) {
            RenderOptions opt;
            opt.seed = o.seed;
            opt.threads = o.threads;
            opt.all_features = v == 0;
            const RenderResult r = render_on(backend, s, opt, o.device, o.pipeline_stats);
            const double spp = std::max<uint32_t>(r.stats.spp, 1);
            t[v].wall_per_spp = std::min(t[v].wall_per_spp, r.stats.wall_time_s / spp);
            if (r.stats.gpu_time_s > 0)
                t[v].gpu_per_spp = std::min(t[v].gpu_per_spp, r.stats.gpu_time_s / spp);
            t[v].last = r.stats;
            if (progress) progress(double(2 * round + v + 1) / double(2 * rounds));
        }
    const auto finite_or_null = [](double x) { return std::isfinite(x) ? json(x) : json(nullptr); };
    const bool gpu = std::isfinite(t[0].gpu_per_spp) && std::isfinite(t[1].gpu_per_spp);
    json j;
    j["backend"] = backend.name;
    j["mode"] = backend.mode;
    j["device"] = backend.device;
    j["spp"] = o.spec_spp;
    j["rounds"] = rounds;
    j["features"] = analyze_features(scene).names();
    j["feature_mask"] = render_feature_mask(scene, false);
    j["all"] = {{"wall_per_spp_s", t[0].wall_per_spp},
                {"gpu_per_spp_s", finite_or_null(t[0].gpu_per_spp)},
                {"rays", t[0].last.rays.total()},
                {"shadow_rays", t[0].last.rays.shadow}};
    j["specialized"] = {{"wall_per_spp_s", t[1].wall_per_spp},
                        {"gpu_per_spp_s", finite_or_null(t[1].gpu_per_spp)},
                        {"rays", t[1].last.rays.total()},
                        {"shadow_rays", t[1].last.rays.shadow}};
    // > 1: the specialized loop is faster. GPU time when the device measured it (it excludes
    // submission overhead), wall time otherwise.
    j["ratio_wall"] = t[0].wall_per_spp / t[1].wall_per_spp;
    j["ratio_gpu"] = gpu ? json(t[0].gpu_per_spp / t[1].gpu_per_spp) : json(nullptr);
    j["ratio"] = gpu ? j["ratio_gpu"] : j["ratio_wall"];
    for (const char* k : {"pipeline_cache", "pipeline_create_ms"})
        if (t[1].last.extra.count(k)) j["specialized"][k] = t[1].last.extra.at(k);
    // --pipeline-stats: what the driver compiled each variant into (docs/gpu.md).
    if (o.pipeline_stats && t[0].last.pipeline)
        for (const auto& [key, timing] : {std::pair{"all", &t[0]}, {"specialized", &t[1]}})
            j[key]["pipeline"] = pipeline_stats_json(timing->last);
    return j;
}

} // namespace tp::bench
