#include "bench/sizes.h"

#include "bench/result_json.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <optional>

namespace fs = std::filesystem;
using nlohmann::json;

namespace tp::bench {
namespace {

constexpr uint32_t kMaxSide = 16384; // as --width and --height
// The sample count of a point's render, which the time limit ends long before (as `render
// --time-limit` without --spp); with any --sample-offset it fits the 32-bit sample index.
constexpr uint32_t kUnlimitedSpp = 1u << 30;
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

std::string ImageSize::name() const {
    return fmt::format("{}x{}", width, height);
}

ImageSize parse_image_size(const std::string& word) {
    const auto side = [&](const std::string& text) {
        if (text.empty() || text.size() > 5 ||
            text.find_first_not_of("0123456789") != std::string::npos)
            input_error("--sizes-list: '{}' is not an image size (WIDTHxHEIGHT, or N for NxN)",
                        word);
        const unsigned long v = std::stoul(text);
        if (v < 1 || v > kMaxSide)
            input_error("--sizes-list: '{}': each side must be 1 to {}", word, kMaxSide);
        return uint32_t(v);
    };
    for (const char* separator : {"x", "X", "×"}) {
        const size_t at = word.find(separator);
        if (at != std::string::npos)
            return {side(word.substr(0, at)), side(word.substr(at + std::strlen(separator)))};
    }
    const uint32_t n = side(word);
    return {n, n};
}

std::vector<ImageSize> parse_image_sizes(const std::vector<std::string>& words) {
    if (words.empty()) input_error("--sizes-list must not be empty");
    std::vector<ImageSize> sizes;
    for (const std::string& w : words) sizes.push_back(parse_image_size(w));
    std::sort(sizes.begin(), sizes.end(), [](const ImageSize& a, const ImageSize& b) {
        return a.pixels() != b.pixels() ? a.pixels() < b.pixels() : a.width < b.width;
    });
    sizes.erase(std::unique(sizes.begin(), sizes.end()), sizes.end());
    return sizes;
}

ImageSize ratio_base(const std::vector<ImageSize>& sizes) {
    const ImageSize hd{1920, 1080};
    if (std::find(sizes.begin(), sizes.end(), hd) != sizes.end() || sizes.empty()) return hd;
    return sizes.back(); // ascending (parse_image_sizes)
}

json run_sizes(const std::vector<FlatScene>& scenes, const std::vector<ImageSize>& sizes,
               const Backend& backend, const BenchOptions& o,
               const std::function<void(double)>& progress) {
    const uint32_t rounds = std::max<uint32_t>(o.sizes_rounds, 1);
    std::vector<std::vector<RenderStats>> stats(sizes.size()); // [size][round]
    for (uint32_t round = 0; round < rounds; ++round)
        for (size_t i = 0; i < sizes.size(); ++i) {
            FlatScene s = scenes[i];
            s.spp = kUnlimitedSpp;
            RenderOptions opt;
            opt.seed = o.seed;
            opt.threads = o.threads;
            opt.time_limit_s = o.sizes_time_s;
            stats[i].push_back(render_on(backend, s, opt, o.device).stats);
            if (progress) progress(double(round * sizes.size() + i + 1) / (rounds * sizes.size()));
        }
    // GPU time only where every render measured it, so that all points of a line are alike.
    bool gpu = true;
    for (const auto& per_size : stats)
        for (const RenderStats& st : per_size) gpu = gpu && st.gpu_time_s > 0;
    const auto seconds = [&](const RenderStats& st) {
        return gpu ? st.gpu_time_s : st.wall_time_s;
    };
    const auto mrays = [&](const RenderStats& st) {
        return seconds(st) > 0 ? 1e-6 * double(st.rays.total()) / seconds(st) : 0.0;
    };

    json run = {{"backend", backend.name},       {"mode", backend.mode}, {"device", backend.device},
                {"timer", gpu ? "gpu" : "wall"}, {"rounds", rounds},     {"points", json::array()}};
    for (size_t i = 0; i < sizes.size(); ++i) {
        const auto best = std::max_element(
            stats[i].begin(), stats[i].end(),
            [&](const RenderStats& a, const RenderStats& b) { return mrays(a) < mrays(b); });
        json each = json::array();
        for (const RenderStats& st : stats[i]) each.push_back(mrays(st));
        run["points"].push_back({{"width", sizes[i].width},
                                 {"height", sizes[i].height},
                                 {"pixels", sizes[i].pixels()},
                                 {"spp", best->spp},
                                 {"wall_s", best->wall_time_s},
                                 {"gpu_s", gpu_seconds(best->gpu_time_s)},
                                 {"samples", best->samples},
                                 {"rays", rays_json(best->rays)},
                                 {"mrays_s", number_or_null(mrays(*best))},
                                 {"rounds_mrays_s", each}});
    }
    return run;
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
    std::string md = fmt::format(
        "### Rays per second against image size\n\n"
        "Each point renders one image size for at least {:g} s (as many whole passes of samples "
        "as fit in that time, so small images get many samples; seed {}) and is the best of {} "
        "over all sizes in turn. Mrays/s counts every ray traced (camera, extension, "
        "shadow) over GPU time (timestamp queries) where the device measures it, else over "
        "wall time (the CPU); each line says which. × {} is the rate over the same "
        "backend/mode's rate at {}. Numbers in `sizes.csv`.\n\n",
        settings["sizes"]["time_s"].get<double>(), settings["seed"].get<int>(),
        settings["sizes"]["rounds"] == 1
            ? std::string("one round")
            : fmt::format("{} rounds", settings["sizes"]["rounds"].get<int>()),
        display_name(base), display_name(base));

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

} // namespace tp::bench
