#include "compare/exact.h"

#include "util/error.h"

#include <fmt/format.h>

#include <cmath>

namespace tp {
namespace {

bool same(float x, float y, double tolerance, double& max_diff) {
    if (std::isnan(x) || std::isnan(y)) return std::isnan(x) && std::isnan(y);
    if (std::isinf(x) || std::isinf(y)) return x == y;
    const double d = std::fabs(double(x) - double(y));
    max_diff = std::max(max_diff, d);
    return d <= tolerance;
}

bool is_aov_channel(const std::string& name) {
    for (const char* prefix : {"albedo.", "normal.", "depth.", "id.", "pbr."})
        if (name.rfind(prefix, 0) == 0) return true;
    return false;
}

// The tolerance of one AOV value: ids exact, the rest relative 1e-4 (float rounding of two
// different ray-triangle tests and interpolations), at least `tolerance`.
double aov_tolerance(const std::string& name, float x, float y, double tolerance) {
    if (name.rfind("id.", 0) == 0) return tolerance;
    const double m = std::max({1.0, std::fabs(double(x)), std::fabs(double(y))});
    return std::max(tolerance, 1e-4 * (std::isfinite(m) ? m : 1.0));
}

// Pixels whose instance id differs from a 4-neighbour's in either image.
std::vector<uint8_t> silhouettes(const ExrImage& a, const ExrImage& b) {
    const int W = a.width, H = a.height;
    std::vector<uint8_t> s(size_t(W) * size_t(H), 0);
    for (const ExrImage* img : {&a, &b}) {
        const std::vector<float>& id = img->channel("id.instance");
        const auto at = [&](int x, int y) { return id[size_t(y) * size_t(W) + size_t(x)]; };
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const float v = at(x, y);
                if ((x > 0 && at(x - 1, y) != v) || (x + 1 < W && at(x + 1, y) != v) ||
                    (y > 0 && at(x, y - 1) != v) || (y + 1 < H && at(x, y + 1) != v))
                    s[size_t(y) * size_t(W) + size_t(x)] = 1;
            }
    }
    return s;
}

} // namespace

ExactResult exact_compare(const std::string& path_a, const ExrImage& a, const std::string& path_b,
                          const ExrImage& b, double tolerance) {
    if (a.width != b.width || a.height != b.height)
        input_error("{} is {}x{} but {} is {}x{}: images of different sizes cannot be compared",
                    path_a, a.width, a.height, path_b, b.width, b.height);
    ExactResult r;
    r.path_a = path_a;
    r.path_b = path_b;
    r.width = a.width;
    r.height = a.height;
    r.tolerance = tolerance;
    for (const auto& [name, data] : a.channels)
        if (!b.has(name)) r.only_a.push_back(name);
    for (const auto& [name, data] : b.channels)
        if (!a.has(name)) r.only_b.push_back(name);
    r.aov_mode = a.has("id.instance") && b.has("id.instance");
    std::vector<uint8_t> bad(size_t(a.width) * size_t(a.height), 0);
    for (const auto& [name, da] : a.channels) {
        if (!b.has(name)) continue;
        if (r.aov_mode && !is_aov_channel(name)) continue;
        const std::vector<float>& db = b.channel(name);
        size_t& count = r.mismatches[name];
        for (size_t i = 0; i < da.size(); ++i) {
            const double tol =
                r.aov_mode ? aov_tolerance(name, da[i], db[i], tolerance) : tolerance;
            if (!same(da[i], db[i], tol, r.max_abs_difference)) {
                ++count;
                bad[i] = 1;
            }
        }
    }
    if (r.mismatches.empty()) input_error("{} and {} have no channel in common", path_a, path_b);
    r.mask.assign(bad.size(), 0);
    const std::vector<uint8_t> edge =
        r.aov_mode ? silhouettes(a, b) : std::vector<uint8_t>(bad.size(), 0);
    for (size_t i = 0; i < bad.size(); ++i) {
        r.silhouette_pixels += edge[i];
        if (!bad[i]) continue;
        const std::pair<int, int> xy{int(i % size_t(a.width)), int(i / size_t(a.width))};
        if (edge[i]) {
            ++r.silhouette_mismatches;
            r.mask[i] = 1;
            if (r.silhouette_examples.size() < 20) r.silhouette_examples.push_back(xy);
        } else {
            ++r.mismatching_pixels;
            r.mask[i] = 2;
            if (r.mismatch_examples.size() < 20) r.mismatch_examples.push_back(xy);
        }
    }
    return r;
}

nlohmann::json exact_json(const ExactResult& r) {
    return {{"verdict", r.identical() ? "identical" : "different"},
            {"mode", "exact"},
            {"a", r.path_a},
            {"b", r.path_b},
            {"width", r.width},
            {"height", r.height},
            {"tolerance", r.tolerance},
            {"mismatching_pixels", r.mismatching_pixels},
            {"fraction_mismatching",
             double(r.mismatching_pixels) / (double(r.width) * double(r.height))},
            {"mismatches", r.mismatches},
            {"max_abs_difference", r.max_abs_difference},
            {"only_in_a", r.only_a},
            {"only_in_b", r.only_b},
            {"aov_mode", r.aov_mode},
            {"silhouette_pixels", r.silhouette_pixels},
            {"silhouette_mismatches", r.silhouette_mismatches},
            {"silhouette_examples", r.silhouette_examples},
            {"mismatch_examples", r.mismatch_examples}};
}

std::string exact_verdict_line(const ExactResult& r) {
    std::string worst;
    for (const auto& [name, count] : r.mismatches)
        if (count) worst += fmt::format("{}{} {}", worst.empty() ? "" : ", ", name, count);
    const std::string skipped = r.only_a.empty() && r.only_b.empty()
                                    ? ""
                                    : fmt::format("; {} channels in one file only, not compared",
                                                  r.only_a.size() + r.only_b.size());
    std::string silhouette;
    if (r.aov_mode) {
        silhouette = fmt::format("; AOV layers only, {} silhouette pixels of which {} differ",
                                 r.silhouette_pixels, r.silhouette_mismatches);
        for (size_t i = 0; i < std::min<size_t>(5, r.silhouette_examples.size()); ++i)
            silhouette += fmt::format("{}({},{})", i ? " " : ": ", r.silhouette_examples[i].first,
                                      r.silhouette_examples[i].second);
        if (r.silhouette_examples.size() > 5) silhouette += " ...";
    }
    if (r.identical())
        return fmt::format("identical: {} channels equal within {}{}{}", r.mismatches.size(),
                           r.aov_mode ? "their per-layer tolerances"
                                      : fmt::format("{}", r.tolerance),
                           silhouette, skipped);
    std::string where;
    for (size_t i = 0; i < std::min<size_t>(5, r.mismatch_examples.size()); ++i)
        where += fmt::format("{}({},{})", i ? " " : ", first at ", r.mismatch_examples[i].first,
                             r.mismatch_examples[i].second);
    return fmt::format("different: {} of {} pixels{} differ by more than {} ({}{}); max |diff| "
                       "{:.3g}{}{}",
                       r.mismatching_pixels, size_t(r.width) * size_t(r.height),
                       r.aov_mode ? " off silhouettes" : "",
                       r.aov_mode ? "their per-layer tolerances" : fmt::format("{}", r.tolerance),
                       worst, where, r.max_abs_difference, silhouette, skipped);
}

} // namespace tp
