#include "image/exposure.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace tp {

float auto_exposure_stops(std::vector<double>& peaks) {
    if (peaks.empty()) return 0.0f;
    const size_t k = std::min(peaks.size() - 1, size_t(0.99 * double(peaks.size())));
    std::nth_element(peaks.begin(), peaks.begin() + std::ptrdiff_t(k), peaks.end());
    const double p99 = peaks[k];
    if (!(p99 > 0.0) || !std::isfinite(p99)) return 0.0f;
    return float(std::clamp(-std::log2(p99), -30.0, 30.0));
}

float auto_exposure_stops(const std::vector<float>& r, const std::vector<float>& g,
                          const std::vector<float>& b) {
    std::vector<double> peaks(r.size());
    for (size_t i = 0; i < peaks.size(); ++i) peaks[i] = double(std::max({r[i], g[i], b[i]}));
    return auto_exposure_stops(peaks);
}

} // namespace tp
