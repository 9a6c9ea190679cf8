#include "tools/lab/scene_sizes_report.h"

#include "bench/scenes.h"
#include "tools/lab/result_fields.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

using nlohmann::json;

namespace tp::lab {

std::string scene_sizes_table(const json& r, const bench::ImageSize& size) {
    std::vector<const json*> scenes;
    std::vector<std::string> labels;
    for (const json& sc : r["scenes"]) {
        if (!sc.contains("sizes") || !bench::parse_sized_scene(sc["name"].get<std::string>()))
            continue;
        scenes.push_back(&sc);
        for (const json& run : sc["sizes"])
            if (std::find(labels.begin(), labels.end(), run_label(run)) == labels.end())
                labels.push_back(run_label(run));
    }
    if (scenes.empty()) return "";
    std::stable_sort(scenes.begin(), scenes.end(), [](const json* a, const json* b) {
        return (*a)["unique_triangles"].get<uint64_t>() < (*b)["unique_triangles"].get<uint64_t>();
    });
    std::string md = fmt::format(
        "Scene sizes at {}×{}: N distinct meshes (no instancing), each backend/mode's Mrays/s and "
        "its acceleration structure's build in seconds (compute mode's seconds per stage: each "
        "point's `build_stages` in bench.json).\n\n| scene | triangles |",
        size.width, size.height);
    std::string rule = "|---|---:|";
    for (const std::string& l : labels) {
        md += fmt::format(" {}: Mrays/s, build |", l);
        rule += "---:|";
    }
    md += "\n" + rule + "\n";
    for (const json* sc : scenes) {
        md += fmt::format("| {} | {:.3g} M |", (*sc)["name"].get<std::string>(),
                          1e-6 * (*sc)["unique_triangles"].get<double>());
        for (const std::string& l : labels) {
            std::string cell = "–";
            for (const json& run : (*sc)["sizes"])
                for (const json& p : run["points"])
                    if (run_label(run) == l && p["width"] == size.width &&
                        p["height"] == size.height && p["mrays_s"].is_number())
                        cell = fmt::format("{:.4g}, {:.2f} s", p["mrays_s"].get<double>(),
                                           p.value("build_s", 0.0));
            md += fmt::format(" {} |", cell);
        }
        md += "\n";
    }
    return md + "\n";
}

} // namespace tp::lab
