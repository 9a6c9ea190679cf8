#include "bench/specialization.h"

#include "scene/features.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <utility>

using nlohmann::json;

namespace tp::bench {
namespace {

// The register count of a variant's path loop: the first statistic named like "Register Count"
// (NVIDIA), "... registers ..." or "VGPRs" (AMD) of the executable of the compute or
// ray-generation stage, which holds the path loop; null when the driver reports none.
json register_count(const json& pipeline) {
    if (!pipeline.is_object()) return nullptr;
    for (const json& e : pipeline.value("executables", json::array())) {
        const json stages = e.value("stages", json::array());
        if (std::find(stages.begin(), stages.end(), "compute") == stages.end() &&
            std::find(stages.begin(), stages.end(), "raygen") == stages.end())
            continue;
        for (const json& st : e.value("statistics", json::array())) {
            std::string name = st.value("name", "");
            std::transform(name.begin(), name.end(), name.begin(),
                           [](unsigned char c) { return char(std::tolower(c)); });
            if ((name.find("register") != std::string::npos || name == "vgprs") &&
                st.value("value", json()).is_number())
                return st["value"];
        }
    }
    return nullptr;
}

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

std::string specialization_section(const json& r) {
    // A register column when the driver reported register counts (--pipeline-stats).
    bool registers = false;
    for (const json& sc : r["scenes"])
        for (const json& row : sc.value("specialization", json::array()))
            registers = registers ||
                        register_count(row["specialized"].value("pipeline", json())).is_number();
    std::string md = fmt::format(
        "### Specialization\n\nTime per spp of the path loop with every feature compiled in "
        "(`--features all`) over the loop specialized to the scene's features; > 1 means the "
        "specialized loop is faster. GPU time where the device measures it, else wall time; "
        "best of {} alternating rounds of {} spp each, same seed.{}\n\n"
        "| scene | backend/mode | features | all, ms/spp | specialized, ms/spp | ratio |{}\n"
        "|---|---|---|---:|---:|---:|{}\n",
        r["settings"].value("spec_rounds", 0), r["settings"].value("spec_spp", 0),
        registers ? " Registers: the driver's register count of the path loop's stage (compute "
                    "or ray generation), all features → specialized (`--pipeline-stats`)."
                  : "",
        registers ? " registers |" : "", registers ? "---:|" : "");
    const auto count = [](const json& v) { return v.is_number() ? v.dump() : std::string("-"); };
    const auto ms = [](const json& v) {
        return v.is_number() ? fmt::format("{:.3g}", v.get<double>() * 1e3) : std::string("-");
    };
    for (const json& sc : r["scenes"]) {
        if (!sc.contains("specialization")) continue;
        for (const json& row : sc["specialization"]) {
            std::string features;
            for (const json& f : row["features"])
                features += (features.empty() ? "" : ", ") + f.get<std::string>();
            const bool gpu = row["ratio_gpu"].is_number();
            const char* key = gpu ? "gpu_per_spp_s" : "wall_per_spp_s";
            md += fmt::format("| {} | {}/{} | {} | {} | {} | {:.3f}{} |",
                              sc["name"].get<std::string>(), row["backend"].get<std::string>(),
                              row["mode"].get<std::string>(), features.empty() ? "none" : features,
                              ms(row["all"][key]), ms(row["specialized"][key]),
                              row["ratio"].get<double>(), gpu ? " (GPU)" : "");
            if (registers)
                md += fmt::format(
                    " {} → {} |", count(register_count(row["all"].value("pipeline", json()))),
                    count(register_count(row["specialized"].value("pipeline", json()))));
            md += "\n";
        }
    }
    return md + "\n";
}

} // namespace tp::bench
