#include "compare/power.h"

#include "compare/distributions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace tp {
namespace {

constexpr size_t kPairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};

// Bisection of a monotone increasing predicate's threshold on a log scale in [lo, hi].
template <typename Reaches>
double log_bisect(double lo, double hi, Reaches&& reaches) {
    if (!reaches(hi)) return std::numeric_limits<double>::infinity();
    for (int i = 0; i < 200 && hi / lo > 1.0 + 1e-9; ++i) {
        const double mid = std::sqrt(lo * hi);
        (reaches(mid) ? hi : lo) = mid;
    }
    return hi;
}

} // namespace

PowerModel PowerModel::lower_bound(double z) const {
    if (!informative()) return *this;
    const double f = std::max(0.25, 1.0 - z * signal_se / signal);
    PowerModel m = *this;
    m.signal *= f;
    m.signal_corr *= f;
    m.signal_se *= f;
    return m;
}

PowerModel power_model(int width, int height, const Planes& mean, const Planes& sample_variance,
                       const std::array<double, 3>& correlation, int tile,
                       const VarianceSplit* split) {
    tile = std::max(1, std::min(tile, std::max(width, height)));
    const int tx = (width + tile - 1) / tile, ty = (height + tile - 1) / tile;
    const size_t k = size_t(tx) * size_t(ty);
    std::array<std::vector<double>, 3> sum_mean, sum_var, sum_a, sum_b;
    for (size_t c = 0; c < 3; ++c)
        for (auto* v : {&sum_mean, &sum_var, &sum_a, &sum_b}) (*v)[c].assign(k, 0.0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t i = size_t(y) * size_t(width) + size_t(x);
            const size_t j = size_t(y / tile) * size_t(tx) + size_t(x / tile);
            for (size_t c = 0; c < 3; ++c)
                if (sample_variance[c][i] > 0.0) {
                    sum_mean[c][j] += mean[c][i];
                    sum_var[c][j] += sample_variance[c][i];
                    if (split) {
                        sum_a[c][j] += (*split->a)[c][i];
                        sum_b[c][j] += (*split->b)[c][i];
                    }
                }
        }
    PowerModel m;
    std::array<std::vector<double>, 3> s; // S / sqrt(V) per tile-channel, 0 where V is 0
    for (size_t c = 0; c < 3; ++c) {
        s[c].assign(k, 0.0);
        for (size_t j = 0; j < k; ++j)
            if (sum_var[c][j] > 0.0) {
                s[c][j] = sum_mean[c][j] / std::sqrt(sum_var[c][j]);
                m.signal += s[c][j] * s[c][j];
                m.null_mean += 1.0;
            }
    }
    m.null_var = 2.0 * m.null_mean;
    for (size_t j = 0; j < k; ++j) {
        double quad = 0.0;
        for (size_t c = 0; c < 3; ++c) quad += s[c][j] * s[c][j];
        for (size_t q = 0; q < 3; ++q) {
            const size_t c0 = kPairs[q][0], c1 = kPairs[q][1];
            if (sum_var[c0][j] > 0.0 && sum_var[c1][j] > 0.0) {
                m.null_var += 4.0 * correlation[q] * correlation[q];
                quad += 2.0 * correlation[q] * s[c0][j] * s[c1][j];
            }
        }
        m.signal_corr += quad;
    }
    if (split) {
        const double da = split->dof_a, db = split->dof_b;
        double var = 0.0;
        for (size_t j = 0; j < k; ++j) {
            double change = 0.0; // of the signal, per unit of (V_a - V_b) in every channel
            for (size_t c = 0; c < 3; ++c)
                if (sum_var[c][j] > 0.0)
                    change += s[c][j] * s[c][j] / sum_var[c][j] * (sum_a[c][j] - sum_b[c][j]);
            var += change * change * da * db / ((da + db) * (da + db));
        }
        m.signal_se = std::sqrt(var);
    }
    return m;
}

double effective_spp(double n_a, double n_b) {
    return 1.0 / (1.0 / n_a + 1.0 / n_b);
}

double global_test_power(const PowerModel& m, double bias, double n_eff, double level) {
    if (m.null_mean <= 0.0) return 0.0;
    // The null g chi2_h of tile_test.h and its critical value.
    const double g = m.null_var / (2.0 * m.null_mean);
    const double h = 2.0 * m.null_mean * m.null_mean / m.null_var;
    const double critical = g * chi2_upper_quantile(level, h);
    // Under the bias: a chi2_f with the same two moments as X.
    const double w = bias * bias * n_eff;
    const double mean = m.null_mean + w * m.signal;
    const double var = m.null_var + 4.0 * w * m.signal_corr;
    const double a = var / (2.0 * mean), f = 2.0 * mean * mean / var;
    return chi2_upper(critical / a, f);
}

double required_effective_spp(const PowerModel& m, double bias, double level, double power) {
    if (!m.informative()) return std::numeric_limits<double>::infinity();
    return log_bisect(1e-6, 1e15,
                      [&](double n) { return global_test_power(m, bias, n, level) >= power; });
}

double detectable_bias(const PowerModel& m, double n_eff, double level, double power) {
    // The power depends on bias^2 n_eff alone (power.h).
    return std::sqrt(required_effective_spp(m, 1.0, level, power) / n_eff);
}

} // namespace tp
