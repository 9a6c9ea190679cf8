#include "tools/lab/sizes_report.h"

#include "tools/lab/result_fields.h"
#include "tools/lab/scene_sizes_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <optional>

namespace fs = std::filesystem;
using nlohmann::json;
using tp::bench::ImageSize;
using tp::bench::parse_image_sizes;

namespace tp::lab {
namespace {

constexpr const char* kDash = "–";

ImageSize size_of(const json& point) {
    return {point["width"].get<uint32_t>(), point["height"].get<uint32_t>()};
}

// "1920×1080", for people.
std::string display_name(const ImageSize& s) {
    return fmt::format("{}×{}", s.width, s.height);
}

// Rates of at least 1000 Mrays/s with every digit (3 significant digits would print 4.33e+03).
std::string rate_text(const json& v) {
    if (!v.is_number()) return kDash;
    const double x = v.get<double>();
    return x >= 1000 ? fmt::format("{:.0f}", x) : fmt::format("{:.3g}", x);
}

std::vector<ImageSize> settings_sizes(const json& result) {
    std::vector<std::string> words;
    for (const json& w : result["settings"]["sizes"]["list"]) words.push_back(w);
    return parse_image_sizes(words);
}

// The index of the point of `run` at `size`.
std::optional<size_t> point_index(const json& run, const ImageSize& size) {
    for (size_t i = 0; i < run["points"].size(); ++i)
        if (size_of(run["points"][i]) == size) return i;
    return std::nullopt;
}

// The point of `run` at `size`, or null.
const json* point_at(const json& run, const ImageSize& size) {
    const std::optional<size_t> i = point_index(run, size);
    return i ? &run["points"][*i] : nullptr;
}

std::string timer_text(const json& run) {
    return run["timer"] == "gpu" ? "GPU time" : "wall time";
}

} // namespace

ImageSize ratio_base(const std::vector<ImageSize>& sizes) {
    const ImageSize hd{1920, 1080};
    if (std::find(sizes.begin(), sizes.end(), hd) != sizes.end() || sizes.empty()) return hd;
    return sizes.back(); // ascending (parse_image_sizes)
}

std::vector<json> rate_ratios(const json& run, const ImageSize& base) {
    const json* b = point_at(run, base);
    const bool have_base = b && (*b)["mrays_s"].is_number() && (*b)["mrays_s"].get<double>() > 0;
    std::vector<json> ratios;
    for (const json& p : run["points"])
        ratios.push_back(have_base && p["mrays_s"].is_number()
                             ? json(p["mrays_s"].get<double>() / (*b)["mrays_s"].get<double>())
                             : json(nullptr));
    return ratios;
}

LinePlot sizes_plot(const json& scene) {
    LinePlot plot;
    plot.title =
        fmt::format("{}: rays per second against image size", scene["name"].get<std::string>());
    plot.x_label = "pixels (log scale)";
    plot.y_label = "Mrays/s";
    plot.linear_y = true;
    plot.markers = true;
    std::vector<ImageSize> ticks;
    for (const json& run : scene["sizes"]) {
        PlotSeries s;
        s.label = fmt::format("{} ({})", run_label(run), run["timer"] == "gpu" ? "GPU" : "wall");
        for (const json& p : run["points"]) {
            if (p["mrays_s"].is_number())
                s.points.emplace_back(p["pixels"].get<double>(), p["mrays_s"].get<double>());
            if (std::find(ticks.begin(), ticks.end(), size_of(p)) == ticks.end())
                ticks.push_back(size_of(p));
        }
        plot.series.push_back(s);
    }
    for (const ImageSize& t : ticks) plot.x_ticks.emplace_back(double(t.pixels()), display_name(t));
    return plot;
}

std::string sizes_section(const json& r, const std::string& base_dir) {
    const json& settings = r["settings"];
    const std::vector<ImageSize> sizes = settings_sizes(r);
    const ImageSize base = ratio_base(sizes);
    const ImageSize everyday{settings["width"].get<uint32_t>(), settings["height"].get<uint32_t>()};
    const json& spp = settings["sizes"].value("spp", json(nullptr));
    const std::string each =
        spp.is_number()
            ? fmt::format("renders one image size at {} spp", spp.get<int>())
            : fmt::format("renders one image size for at least {:g} s (as many whole passes of "
                          "samples as fit in that time, so small images get many samples)",
                          settings["sizes"]["time_s"].get<double>());
    std::string md = fmt::format(
        "### Rays per second against image size\n\n"
        "Each point {} (seed {}) and is the best of {} "
        "over all sizes in turn. Mrays/s counts every ray traced (camera, extension, "
        "shadow) over GPU time (timestamp queries) where the device measures it, else over "
        "wall time (the CPU); each line says which. × {} is the rate over the same "
        "backend/mode's rate at {}. Numbers in `sizes.csv`.\n\n",
        each, settings["seed"].get<int>(),
        settings["sizes"]["rounds"] == 1
            ? std::string("one round")
            : fmt::format("{} rounds", settings["sizes"]["rounds"].get<int>()),
        display_name(base), display_name(base));

    md += scene_sizes_table(r, base);

    // The summary: the run's own image size (the everyday verification size, --width x
    // --height) against the base, per scene and backend/mode, when both were measured.
    std::vector<std::string> labels;
    for (const json& sc : r["scenes"])
        for (const json& run : sc.value("sizes", json::array()))
            if (std::find(labels.begin(), labels.end(), run_label(run)) == labels.end())
                labels.push_back(run_label(run));
    const bool summary = !(everyday == base) &&
                         std::find(sizes.begin(), sizes.end(), everyday) != sizes.end() &&
                         std::find(sizes.begin(), sizes.end(), base) != sizes.end();
    if (summary && !labels.empty()) {
        md += fmt::format("{0} against {1}: Mrays/s at {0} / at {1} = ratio.\n\n| scene |",
                          display_name(everyday), display_name(base));
        std::string rule = "|---|";
        for (const std::string& l : labels) {
            md += fmt::format(" {} |", l);
            rule += "---:|";
        }
        md += "\n" + rule + "\n";
        for (const json& sc : r["scenes"]) {
            if (!sc.contains("sizes")) continue;
            md += fmt::format("| {} |", sc["name"].get<std::string>());
            for (const std::string& l : labels) {
                std::string cell = kDash;
                for (const json& run : sc["sizes"]) {
                    if (run_label(run) != l) continue;
                    const json *a = point_at(run, everyday), *b = point_at(run, base);
                    if (a && b && (*a)["mrays_s"].is_number() && (*b)["mrays_s"].is_number())
                        cell = fmt::format("{} / {} = {:.2f}", rate_text((*a)["mrays_s"]),
                                           rate_text((*b)["mrays_s"]),
                                           (*a)["mrays_s"].get<double>() /
                                               (*b)["mrays_s"].get<double>());
                }
                md += fmt::format(" {} |", cell);
            }
            md += "\n";
        }
        md += "\n";
    }

    // Per scene: rows per backend/mode (Mrays/s, ratio to the base, spp), a column per size.
    for (const json& sc : r["scenes"]) {
        if (!sc.contains("sizes")) continue;
        md += fmt::format("**{}**: {} triangles ({} unique); max depth {}",
                          sc["name"].get<std::string>(), sc["triangles"].get<uint64_t>(),
                          sc["unique_triangles"].get<uint64_t>(), sc["max_depth"].get<int>());
        if (sc.contains("sizes_plot"))
            md += fmt::format(
                "; [plot]({})",
                (fs::path(base_dir) / sc["sizes_plot"].get<std::string>()).generic_string());
        md += "\n\n| backend/mode | time | |";
        std::string rule = "|---|---|---|";
        for (const ImageSize& s : sizes) {
            md += fmt::format(" {} |", display_name(s));
            rule += "---:|";
        }
        md += "\n" + rule + "\n";
        for (const json& run : sc["sizes"]) {
            const std::vector<json> ratios = rate_ratios(run, base);
            std::string rate =
                            fmt::format("| {} | {} | Mrays/s |", run_label(run), timer_text(run)),
                        ratio = fmt::format("| | | × {} |", display_name(base)),
                        spp = "| | | spp |";
            for (const ImageSize& s : sizes) {
                const std::optional<size_t> i = point_index(run, s);
                const json* p = i ? &run["points"][*i] : nullptr;
                rate += fmt::format(" {} |", p ? rate_text((*p)["mrays_s"]) : kDash);
                ratio += fmt::format(" {} |", i && ratios[*i].is_number()
                                                  ? fmt::format("{:.2f}", ratios[*i].get<double>())
                                                  : kDash);
                spp += fmt::format(" {} |", p ? (*p)["spp"].dump() : kDash);
            }
            md += rate + "\n" + ratio + "\n" + spp + "\n";
        }
        md += "\n";
    }
    return md;
}

} // namespace tp::lab
