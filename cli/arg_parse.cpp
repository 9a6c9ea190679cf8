#include "arg_parse.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <vector>

namespace tp {
namespace {
std::vector<std::string> split(const std::string& s) {
    std::vector<std::string> parts;
    size_t start = 0;
    for (size_t i = 0; i <= s.size(); ++i)
        if (i == s.size() || s[i] == ',') {
            parts.push_back(s.substr(start, i - start));
            start = i + 1;
        }
    return parts;
}
} // namespace

glm::dvec3 parse_xyz(const std::string& option, const std::string& text) {
    const auto parts = split(text);
    if (parts.size() != 3) input_error("{}: expected X,Y,Z, got '{}'", option, text);
    glm::dvec3 v;
    for (int i = 0; i < 3; ++i) {
        const std::string& p = parts[size_t(i)];
        const char* end = p.data() + p.size();
        auto [ptr, ec] = std::from_chars(p.data(), end, v[i]);
        if (ec != std::errc() || ptr != end || !std::isfinite(v[i]))
            input_error("{}: '{}' is not a finite number", option, p);
    }
    return v;
}

CLI::Validator number_in(double lo, double hi) {
    return CLI::Validator(
        [lo, hi](std::string& text) -> std::string {
            double v = 0.0;
            if (!CLI::detail::lexical_cast(text, v) || !(v >= lo && v <= hi))
                return fmt::format("{} is not a number in [{}, {}]", text, lo, hi);
            return {};
        },
        fmt::format("NUMBER in [{}, {}]", lo, hi));
}

uvec2 parse_pixel(const std::string& option, const std::string& text) {
    const auto parts = split(text);
    if (parts.size() != 2) input_error("{}: expected X,Y, got '{}'", option, text);
    uvec2 v;
    for (int i = 0; i < 2; ++i) {
        const std::string& p = parts[size_t(i)];
        const char* end = p.data() + p.size();
        auto [ptr, ec] = std::from_chars(p.data(), end, v[i]);
        if (ec != std::errc() || ptr != end)
            input_error("{}: '{}' is not a pixel coordinate", option, p);
    }
    return v;
}

double parse_relative_bias(const std::string& option, const std::string& text) {
    const bool pct = !text.empty() && text.back() == '%';
    const std::string number = pct ? text.substr(0, text.size() - 1) : text;
    double v = 0.0;
    if (number.empty() || !CLI::detail::lexical_cast(number, v) || !std::isfinite(v))
        input_error("{} {}: expected a relative bias such as 1% or 0.01", option, text);
    if (pct) v /= 100.0;
    if (!(v > 0.0 && v < 1.0))
        input_error("{} {}: the bias must lie strictly between 0 and 100%", option, text);
    return v;
}

} // namespace tp
