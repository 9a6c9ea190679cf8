#include "bench/sizes.h"

#include "bench/result_json.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>

using nlohmann::json;

namespace tp::bench {
namespace {

constexpr uint32_t kMaxSide = 16384; // as --width and --height
// The sample count of a point's render, which the time limit ends long before (as `render
// --time-limit` without --spp); with any --sample-offset it fits the 32-bit sample index.
constexpr uint32_t kUnlimitedSpp = 1u << 30;

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

json run_sizes(const std::vector<FlatScene>& scenes, const std::vector<ImageSize>& sizes,
               const Backend& backend, const BenchOptions& o,
               const std::function<void(double)>& progress) {
    const uint32_t rounds = std::max<uint32_t>(o.sizes_rounds, 1);
    std::vector<std::vector<RenderStats>> stats(sizes.size()); // [size][round]
    for (uint32_t round = 0; round < rounds; ++round)
        for (size_t i = 0; i < sizes.size(); ++i) {
            FlatScene s = scenes[i];
            s.spp = o.sizes_spp > 0 ? o.sizes_spp : kUnlimitedSpp;
            RenderOptions opt;
            opt.seed = o.seed;
            opt.threads = o.threads;
            opt.time_limit_s = o.sizes_spp > 0 ? 0 : o.sizes_time_s;
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
        run["points"].push_back(
            {{"width", sizes[i].width},
             {"height", sizes[i].height},
             {"pixels", sizes[i].pixels()},
             {"spp", best->spp},
             {"wall_s", best->wall_time_s},
             {"gpu_s", gpu_seconds(best->gpu_time_s)},
             {"samples", best->samples},
             {"rays", rays_json(best->rays)},
             {"mrays_s", number_or_null(mrays(*best))},
             {"rounds_mrays_s", each},
             {"triangles", best->triangles_unique},
             {"build_s", best->build_time_s},
             {"build_stages", build_stages_json(*best)},
             {"upload_s", best->upload_time_s >= 0 ? json(best->upload_time_s) : json(nullptr)},
             {"accel_bytes", best->accel_bytes},
             {"device_memory_peak_bytes", best->device_memory_peak_bytes > 0
                                              ? json(best->device_memory_peak_bytes)
                                              : json(nullptr)}});
    }
    return run;
}

} // namespace tp::bench
