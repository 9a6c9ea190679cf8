#include "render/stats.h"

#include "util/error.h"

#include <nlohmann/json.hpp>

#include <fstream>

namespace tp {

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
    j["threads"] = s.threads;
    j["wall_time_s"] = s.wall_time_s;
    j["build_time_s"] = s.build_time_s;
    j["gpu_time_s"] = s.gpu_time_s >= 0 ? nlohmann::json(s.gpu_time_s) : nlohmann::json(nullptr);
    j["rays"] = {{"camera", s.rays.camera},
                 {"extension", s.rays.extension},
                 {"shadow", s.rays.shadow},
                 {"total", s.rays.total()}};
    j["rays_per_second"] = s.rays_per_second();
    j["samples"] = s.samples;
    j["nan_samples"] = s.nan_samples;
    j["accel_bytes"] = s.accel_bytes;
    j["features"] = {
        {"scene", s.scene_features}, {"variant", s.feature_variant}, {"mask", s.feature_mask}};
    for (const auto& [k, v] : s.extra) j["extra"][k] = v;
    std::ofstream out(path);
    if (!out) runtime_error("cannot write {}", path);
    out << j.dump(2) << "\n";
    if (!out) runtime_error("cannot write {}", path);
}

} // namespace tp
