#include "render/stats.h"

#include "scene/flatten.h"
#include "util/error.h"
#include "util/json_file.h"

#include <nlohmann/json.hpp>

namespace tp {
namespace {

nlohmann::json feedback_json(const PipelineFeedback& f) {
    return {{"stage", f.stage},
            {"valid", f.valid},
            {"cache_hit", f.cache_hit},
            {"base_pipeline_acceleration", f.base_pipeline_acceleration},
            {"duration_ms", f.duration_ms}};
}

// "pipeline_creation": the whole pipeline's feedback with its stages', or {"feedback": false}
// when the device has no VK_EXT_pipeline_creation_feedback.
nlohmann::json creation_json(const PipelineReport& p) {
    if (p.feedback.empty()) return {{"feedback", false}};
    nlohmann::json j = feedback_json(p.feedback.front());
    j.erase("stage");
    j["feedback"] = true;
    j["stages"] = nlohmann::json::array();
    for (size_t i = 1; i < p.feedback.size(); ++i)
        j["stages"].push_back(feedback_json(p.feedback[i]));
    return j;
}

nlohmann::json statistic_json(const PipelineStatistic& st) {
    static const char* const kFormats[] = {"bool32", "int64", "uint64", "float64"};
    nlohmann::json j = {
        {"name", st.name}, {"description", st.description}, {"format", kFormats[st.value.index()]}};
    std::visit([&](auto v) { j["value"] = v; }, st.value);
    return j;
}

nlohmann::json ranges_json(const std::vector<SampleRange>& ranges) {
    nlohmann::json j = nlohmann::json::array();
    for (const SampleRange& r : ranges)
        j.push_back({{"seed", r.seed}, {"begin", r.begin}, {"end", r.end}});
    return j;
}

} // namespace

nlohmann::json pipeline_stats_json(const RenderStats& s) {
    if (!s.pipeline) return nullptr;
    const PipelineReport& p = *s.pipeline;
    nlohmann::json j = {{"mode", s.mode},
                        {"variant", s.feature_variant},
                        {"feature_mask", s.feature_mask},
                        {"creation", creation_json(p)},
                        {"statistics_available", p.statistics_available}};
    if (!p.statistics_note.empty()) j["statistics_note"] = p.statistics_note;
    j["executables"] = nlohmann::json::array();
    for (const PipelineExecutable& e : p.executables) {
        nlohmann::json ej = {{"stages", e.stages},
                             {"name", e.name},
                             {"description", e.description},
                             {"subgroup_size", e.subgroup_size},
                             {"statistics", nlohmann::json::array()}};
        for (const PipelineStatistic& st : e.statistics)
            ej["statistics"].push_back(statistic_json(st));
        j["executables"].push_back(ej);
    }
    return j;
}

void count_triangles(RenderStats& s, const FlatScene& scene) {
    s.triangles_unique = 0;
    s.triangles_instanced = 0;
    for (const MeshInfo& m : scene.meshes) s.triangles_unique += m.triangle_count;
    for (const Instance& i : scene.instances)
        s.triangles_instanced += scene.meshes[i.mesh].triangle_count;
}

void write_stats_json(const std::string& path, const RenderStats& s) {
    nlohmann::json j;
    j["scene"] = s.scene;
    j["backend"] = s.backend;
    j["mode"] = s.mode;
    j["device"] = s.device;
    j["width"] = s.width;
    j["height"] = s.height;
    j["spp"] = s.spp;
    j["seed"] = s.seed;
    j["sampler"] = s.sampler;
    j["threads"] = s.threads;
    j["wall_time_s"] = s.wall_time_s;
    j["build_time_s"] = s.build_time_s;
    j["upload_time_s"] = s.upload_time_s >= 0 ? nlohmann::json(s.upload_time_s) : nullptr;
    j["gpu_time_s"] = s.gpu_time_s >= 0 ? nlohmann::json(s.gpu_time_s) : nlohmann::json(nullptr);
    j["rays"] = {{"camera", s.rays.camera},
                 {"extension", s.rays.extension},
                 {"shadow", s.rays.shadow},
                 {"total", s.rays.total()}};
    j["rays_per_second"] = s.rays_per_second();
    j["samples"] = s.samples;
    j["nan_samples"] = s.nan_samples;
    j["accel_bytes"] = s.accel_bytes;
    j["device_memory_peak_bytes"] =
        s.device_memory_peak_bytes > 0 ? nlohmann::json(s.device_memory_peak_bytes) : nullptr;
    j["triangles_unique"] = s.triangles_unique;
    j["triangles_instanced"] = s.triangles_instanced;
    j["features"] = {
        {"scene", s.scene_features}, {"variant", s.feature_variant}, {"mask", s.feature_mask}};
    if (s.pipeline) j["pipeline_creation"] = creation_json(*s.pipeline);
    for (const auto& [k, v] : s.extra) j["extra"][k] = v;
    if (!s.sample_ranges.empty()) j["sample_ranges"] = ranges_json(s.sample_ranges);
    for (const DeviceShare& d : s.devices)
        j["devices"].push_back(
            {{"device", d.device},
             {"spp", d.spp},
             {"sample_ranges", ranges_json(d.ranges)},
             {"samples", d.samples},
             {"wall_time_s", d.wall_time_s},
             {"gpu_time_s", d.gpu_time_s >= 0 ? nlohmann::json(d.gpu_time_s) : nullptr},
             {"rays", d.rays.total()},
             {"rays_per_second",
              d.wall_time_s > 0 ? double(d.rays.total()) / d.wall_time_s : 0.0}});
    write_json(path, j);
}

void write_pipeline_stats_json(const std::string& path, const RenderStats& s) {
    const auto extra = [&](const char* key) {
        const auto it = s.extra.find(key);
        return it == s.extra.end() ? std::string() : it->second;
    };
    write_json(path, {{"schema", "twinpath-pipeline-stats/1"},
                      {"scene", s.scene},
                      {"device", s.device},
                      {"driver", extra("driver")},
                      {"pipelines", nlohmann::json::array({pipeline_stats_json(s)})}});
}

} // namespace tp
