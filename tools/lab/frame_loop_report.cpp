#include "tools/lab/frame_loop_report.h"

#include <fmt/core.h>

#include <algorithm>

using nlohmann::json;

namespace tp::lab {

json frame_loop_fixed_ms(const json& run) {
    const json& points = run["points"];
    if (points.size() < 2) return nullptr;
    const auto by_spp = [](const json& a, const json& b) {
        return a["spp_per_frame"].get<double>() < b["spp_per_frame"].get<double>();
    };
    const json& lo = *std::min_element(points.begin(), points.end(), by_spp);
    const json& hi = *std::max_element(points.begin(), points.end(), by_spp);
    const double s0 = lo["spp_per_frame"].get<double>(), s1 = hi["spp_per_frame"].get<double>();
    if (s1 <= s0) return nullptr;
    const double t0 = lo["ms_mean"].get<double>(), t1 = hi["ms_mean"].get<double>();
    return t0 - s0 * (t1 - t0) / (s1 - s0);
}

std::string frame_loop_section(const json& r) {
    std::string md = fmt::format(
        "### Frame loop\n\nThe viewer's frame loop without a window (`view --headless`): each "
        "frame one batch of the same samples of every pixel, its resolve pass and the display "
        "pass in one submission, {} timed frames per row after two untimed ones. Trace, resolve "
        "and display: GPU time per frame from timestamps; host: the rest of the wall time "
        "(recording, submitting, waiting, the counters' read-back). Fixed: the cost of a frame "
        "at 0 spp on the line through the fewest and the most samples per frame.\n\n"
        "| scene | backend/mode | size | spp/frame | median ms | mean ms | trace | resolve | "
        "display | host | Mrays/s | fixed ms |\n"
        "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
        r["settings"]["frame_loop"].value("frames", 0));
    const auto ms = [](const json& v) {
        return v.is_number() ? fmt::format("{:.3f}", v.get<double>()) : std::string("-");
    };
    for (const json& sc : r["scenes"]) {
        for (const json& run : sc.value("frame_loop", json::array())) {
            const json fixed = frame_loop_fixed_ms(run);
            bool first = true;
            for (const json& p : run["points"]) {
                const json& gpu = p["gpu_ms"];
                const json none;
                md += fmt::format(
                    "| {} | {}/{} | {}x{} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
                    sc["name"].get<std::string>(), run["backend"].get<std::string>(),
                    run["mode"].get<std::string>(), run["width"].get<int>(),
                    run["height"].get<int>(), p["spp_per_frame"].get<int>(), ms(p["ms_median"]),
                    ms(p["ms_mean"]), ms(gpu.is_object() ? gpu["trace"] : none),
                    ms(gpu.is_object() ? gpu["resolve"] : none),
                    ms(gpu.is_object() ? gpu["display"] : none), ms(p["host_ms"]),
                    p["mrays_s"].is_number() ? fmt::format("{:.1f}", p["mrays_s"].get<double>())
                                             : std::string("-"),
                    first ? ms(fixed) : std::string(""));
                first = false;
            }
        }
    }
    return md + "\n";
}

} // namespace tp::lab
