#include "compare/differences.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tp {

double Differences::dof(int c, size_t i) const {
    const double w = welch[size_t(c)][i];
    if (w <= 0.0) return std::numeric_limits<double>::infinity();
    const double v = var[size_t(c)][i];
    return v * v / w;
}

double floor_variance(double a, double b, double channel_scale, double relative_floor) {
    const double m = std::max(std::fabs(a), std::fabs(b));
    return relative_floor * relative_floor * (m * m + channel_scale * channel_scale);
}

Differences compute_differences(const RgbImage& a, const RgbImage& b, double relative_floor) {
    Differences out;
    out.width = a.width;
    out.height = a.height;
    const size_t n = a.pixels();
    // Degrees of freedom of each variance estimate: n - 1 for the unbiased sample variance.
    // Without twinpath:spp the estimate is taken as exact (normal p-values).
    auto inv_dof = [](const RgbImage& img) {
        return img.spp ? 1.0 / double(std::max<int64_t>(*img.spp - 1, 1)) : 0.0;
    };
    const double ka = inv_dof(a), kb = inv_dof(b);
    for (size_t c = 0; c < 3; ++c) {
        double scale = 0.0;
        for (size_t i = 0; i < n; ++i)
            scale += std::max(std::fabs(a.mean[c][i]), std::fabs(b.mean[c][i]));
        scale /= double(n);
        out.d[c].resize(n);
        out.noise[c].resize(n);
        out.var[c].resize(n);
        out.welch[c].resize(n);
        for (size_t i = 0; i < n; ++i) {
            const double va = a.has_variance() ? a.var[c][i] : 0.0;
            const double vb = b.has_variance() ? b.var[c][i] : 0.0;
            out.d[c][i] = a.mean[c][i] - b.mean[c][i];
            out.noise[c][i] = va + vb;
            out.var[c][i] =
                va + vb + floor_variance(a.mean[c][i], b.mean[c][i], scale, relative_floor);
            out.welch[c][i] = va * va * ka + vb * vb * kb;
            out.at_floor += (va + vb == 0.0);
        }
    }
    return out;
}

} // namespace tp
