#include "compare/metrics.h"

#include <cmath>

namespace tp {

ErrorMetrics error_metrics(const RgbImage& a, const RgbImage& b, const RgbImage& ref) {
    ErrorMetrics m;
    const size_t n = a.pixels();
    for (size_t c = 0; c < 3; ++c) {
        ChannelMetrics& cm = m.channel[c];
        double var_sum = 0.0;
        for (size_t i = 0; i < n; ++i) {
            const double r = ref.mean[c][i], d = a.mean[c][i] - b.mean[c][i];
            cm.mse += d * d;
            cm.relmse += d * d / (r * r + kRelativeEpsilon);
            cm.mape += std::fabs(d) / (std::fabs(r) + kRelativeEpsilon);
            cm.bias += d;
            var_sum +=
                (a.has_variance() ? a.var[c][i] : 0.0) + (b.has_variance() ? b.var[c][i] : 0.0);
        }
        const double inv = 1.0 / double(n);
        cm.mse *= inv;
        cm.relmse *= inv;
        cm.mape *= inv;
        cm.bias *= inv;
        cm.mse_noise = var_sum * inv;
        cm.bias_stderr = std::sqrt(var_sum) * inv;
        m.all.mse += cm.mse / 3.0;
        m.all.relmse += cm.relmse / 3.0;
        m.all.mape += cm.mape / 3.0;
        m.all.bias += cm.bias / 3.0;
        m.all.mse_noise += cm.mse_noise / 3.0;
    }
    return m;
}

} // namespace tp
