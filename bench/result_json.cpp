#include "bench/result_json.h"

#include <cmath>
#include <sstream>
#include <string>

using nlohmann::json;

namespace tp::bench {

json number_or_null(double v) {
    return std::isfinite(v) ? json(v) : json(nullptr);
}

json number_or_null(const std::optional<double>& v) {
    return v ? number_or_null(*v) : json(nullptr);
}

json gpu_seconds(double gpu_s) {
    return gpu_s >= 0 ? number_or_null(gpu_s) : json(nullptr);
}

json build_stages_json(const RenderStats& stats) {
    const auto it = stats.extra.find("bvh_build_stages");
    if (it == stats.extra.end()) return nullptr;
    json stages = json::object();
    std::istringstream in(it->second);
    std::string name;
    double seconds = 0;
    while (in >> name >> seconds) stages[name] = seconds;
    return stages;
}

json rays_json(const RayCounts& rays) {
    return {{"camera", rays.camera}, {"extension", rays.extension}, {"shadow", rays.shadow}};
}

double total_rays(const json& rays) {
    return rays["camera"].get<double>() + rays["extension"].get<double>() +
           rays["shadow"].get<double>();
}

json mrays_per_s(const json& rays, const char* kind, double seconds) {
    if (!(seconds > 0)) return nullptr;
    return 1e-6 * (kind ? rays[kind].get<double>() : total_rays(rays)) / seconds;
}

} // namespace tp::bench
