#include "compare/tile_test.h"

#include "compare/distributions.h"

#include <algorithm>
#include <cmath>

namespace tp {

TileTest tile_test(const Differences& d, int tile) {
    TileTest t;
    t.tile = tile;
    t.tiles_x = (d.width + tile - 1) / tile;
    t.tiles_y = (d.height + tile - 1) / tile;
    const size_t k = size_t(t.tiles());
    const size_t pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    std::array<std::vector<double>, 3> sum_d, sum_var, sum_welch, sum_cross;
    for (size_t c = 0; c < 3; ++c) {
        sum_d[c].assign(k, 0.0);
        sum_var[c].assign(k, 0.0);
        sum_welch[c].assign(k, 0.0);
        sum_cross[c].assign(k, 0.0);
    }
    for (int y = 0; y < d.height; ++y)
        for (int x = 0; x < d.width; ++x) {
            const size_t i = size_t(y) * size_t(d.width) + size_t(x);
            const size_t j = size_t(y / tile) * size_t(t.tiles_x) + size_t(x / tile);
            for (size_t c = 0; c < 3; ++c) {
                sum_d[c][j] += d.d[c][i];
                sum_var[c][j] += d.var[c][i];
                sum_welch[c][j] += d.welch[c][i];
                sum_cross[c][j] += d.d[pairs[c][0]][i] * d.d[pairs[c][1]][i];
            }
        }
    for (size_t c = 0; c < 3; ++c) {
        t.z[c].resize(k);
        double chi2 = 0.0;
        for (size_t j = 0; j < k; ++j) {
            const double v = sum_var[c][j];
            const double z = v > 0.0 ? sum_d[c][j] / std::sqrt(v) : 0.0;
            const double dof = sum_welch[c][j] > 0.0 ? v * v / sum_welch[c][j] : HUGE_VAL;
            t.z[c][j] = equivalent_normal(z, dof);
            chi2 += t.z[c][j] * t.z[c][j];
        }
        t.chi2[c] = chi2;
        t.p[c] = chi2_upper(chi2, double(k));
        t.statistic += chi2;
    }
    double trace_r2 = 3.0; // tr(R^2) = 3 + 2 sum of the squared off-diagonal correlations
    for (size_t q = 0; q < 3; ++q) {
        double sum = 0.0;
        size_t used = 0;
        for (size_t j = 0; j < k; ++j) {
            const double v = sum_var[pairs[q][0]][j] * sum_var[pairs[q][1]][j];
            if (v <= 0.0) continue;
            sum += sum_cross[q][j] / std::sqrt(v);
            ++used;
        }
        t.correlation[q] = used ? std::clamp(sum / double(used), -1.0, 1.0) : 0.0;
        trace_r2 += 2.0 * t.correlation[q] * t.correlation[q];
    }
    t.scale = trace_r2 / 3.0;
    t.dof = 3.0 * double(k) / t.scale;
    t.p_value = chi2_upper(t.statistic / t.scale, t.dof);
    return t;
}

} // namespace tp
