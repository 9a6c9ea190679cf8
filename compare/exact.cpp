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
    std::vector<uint8_t> bad(size_t(a.width) * size_t(a.height), 0);
    for (const auto& [name, da] : a.channels) {
        if (!b.has(name)) continue;
        const std::vector<float>& db = b.channel(name);
        size_t& count = r.mismatches[name];
        for (size_t i = 0; i < da.size(); ++i)
            if (!same(da[i], db[i], tolerance, r.max_abs_difference)) {
                ++count;
                bad[i] = 1;
            }
    }
    if (r.mismatches.empty()) input_error("{} and {} have no channel in common", path_a, path_b);
    for (uint8_t v : bad) r.mismatching_pixels += v;
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
            {"only_in_b", r.only_b}};
}

std::string exact_verdict_line(const ExactResult& r) {
    std::string worst;
    for (const auto& [name, count] : r.mismatches)
        if (count) worst += fmt::format("{}{} {}", worst.empty() ? "" : ", ", name, count);
    const std::string skipped = r.only_a.empty() && r.only_b.empty()
                                    ? ""
                                    : fmt::format("; {} channels in one file only, not compared",
                                                  r.only_a.size() + r.only_b.size());
    if (r.identical())
        return fmt::format("identical: {} channels equal within {}{}", r.mismatches.size(),
                           r.tolerance, skipped);
    return fmt::format("different: {} of {} pixels differ by more than {} ({}); max |diff| "
                       "{:.3g}{}",
                       r.mismatching_pixels, size_t(r.width) * size_t(r.height), r.tolerance, worst,
                       r.max_abs_difference, skipped);
}

} // namespace tp
