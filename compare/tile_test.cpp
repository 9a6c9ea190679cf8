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
    for (size_t c = 0; c < 3; ++c) {
        std::vector<double> sum_d(k, 0.0), sum_var(k, 0.0), sum_welch(k, 0.0);
        for (int y = 0; y < d.height; ++y)
            for (int x = 0; x < d.width; ++x) {
                const size_t i = size_t(y) * size_t(d.width) + size_t(x);
                const size_t j = size_t(y / tile) * size_t(t.tiles_x) + size_t(x / tile);
                sum_d[j] += d.d[c][i];
                sum_var[j] += d.var[c][i];
                sum_welch[j] += d.welch[c][i];
            }
        t.z[c].resize(k);
        double chi2 = 0.0;
        for (size_t j = 0; j < k; ++j) {
            const double z = sum_var[j] > 0.0 ? sum_d[j] / std::sqrt(sum_var[j]) : 0.0;
            const double dof =
                sum_welch[j] > 0.0 ? sum_var[j] * sum_var[j] / sum_welch[j] : HUGE_VAL;
            t.z[c][j] = equivalent_normal(z, dof);
            chi2 += t.z[c][j] * t.z[c][j];
        }
        t.chi2[c] = chi2;
        t.p[c] = chi2_upper(chi2, double(k));
    }
    t.p_value = std::min(1.0, 3.0 * std::min({t.p[0], t.p[1], t.p[2]}));
    return t;
}

} // namespace tp
