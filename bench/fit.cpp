#include "bench/fit.h"

#include <cmath>

namespace tp::bench {

LogLogFit fit_loglog(const std::vector<double>& t, const std::vector<double>& e) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    LogLogFit f;
    for (size_t i = 0; i < t.size() && i < e.size(); ++i) {
        if (!(t[i] > 0) || !(e[i] > 0)) continue;
        const double x = std::log10(t[i]), y = std::log10(e[i]);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        ++f.points;
    }
    const double n = double(f.points), det = n * sxx - sx * sx;
    if (f.points < 2 || det <= 0) {
        f.points = 0;
        return f;
    }
    f.slope = (n * sxy - sx * sy) / det;
    f.intercept = (sy - f.slope * sx) / n;
    return f;
}

std::optional<double> time_to_reach(const LogLogFit& fit, const std::vector<double>& e,
                                    double target) {
    if (!fit.valid()) return std::nullopt;
    bool reached = false;
    for (double v : e) reached = reached || v <= target; // v <= 0: below what the data resolve
    if (!reached) return std::nullopt;
    return std::pow(10.0, (std::log10(target) - fit.intercept) / fit.slope);
}

} // namespace tp::bench
