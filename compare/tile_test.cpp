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
    std::array<std::vector<double>, 3> sum_d, sum_floor, sum_cross;
    std::array<std::vector<SideVariance>, 3> sum_a, sum_b;
    for (size_t c = 0; c < 3; ++c) {
        for (auto* v : {&sum_d, &sum_floor, &sum_cross}) (*v)[c].assign(k, 0.0);
        sum_a[c].assign(k, SideVariance{});
        sum_b[c].assign(k, SideVariance{});
    }
    auto add = [](SideVariance& s, double var, double lend) {
        s.var += var;
        s.var2 += var * var;
        s.lend += lend;
        s.lend2 += lend * lend;
    };
    for (int y = 0; y < d.height; ++y)
        for (int x = 0; x < d.width; ++x) {
            const size_t i = size_t(y) * size_t(d.width) + size_t(x);
            const size_t j = size_t(y / tile) * size_t(t.tiles_x) + size_t(x / tile);
            for (size_t c = 0; c < 3; ++c) {
                sum_d[c][j] += d.d[c][i];
                add(sum_a[c][j], d.var_a[c][i], d.lend_a[c][i]);
                add(sum_b[c][j], d.var_b[c][i], d.lend_b[c][i]);
                sum_floor[c][j] += d.floor[c][i];
                sum_cross[c][j] += d.d[pairs[c][0]][i] * d.d[pairs[c][1]][i];
            }
        }
    // The variance borrowing of differences.h, applied to the tile's sums.
    std::array<std::vector<double>, 3> sum_var, sum_noise, sum_welch;
    for (size_t c = 0; c < 3; ++c)
        for (auto* v : {&sum_var, &sum_noise, &sum_welch}) (*v)[c].resize(k);
    for (size_t c = 0; c < 3; ++c)
        for (size_t j = 0; j < k; ++j) {
            const PairVariance pv = pair_variance(d.rule, sum_a[c][j], sum_b[c][j]);
            sum_noise[c][j] = pv.var;
            sum_var[c][j] = pv.var + sum_floor[c][j];
            sum_welch[c][j] = pv.welch;
        }
    // Without estimated variance anywhere, the floor is the only scale: count every tile.
    const bool any_noise = std::any_of(sum_noise.begin(), sum_noise.end(), [](const auto& v) {
        return std::any_of(v.begin(), v.end(), [](double x) { return x > 0.0; });
    });
    auto counted = [&](size_t c, size_t j) { return !any_noise || sum_noise[c][j] > 0.0; };
    for (size_t c = 0; c < 3; ++c) {
        t.z[c].resize(k);
        double chi2 = 0.0;
        for (size_t j = 0; j < k; ++j) {
            const double v = sum_var[c][j];
            const double sd = sum_d[c][j];
            const double z = v > 0.0     ? sd / std::sqrt(v)
                             : sd == 0.0 ? 0.0
                                         : std::copysign(HUGE_VAL, sd);
            const double dof = sum_welch[c][j] > 0.0 ? v * v / sum_welch[c][j] : HUGE_VAL;
            t.z[c][j] = equivalent_normal(z, dof);
            chi2 += t.z[c][j] * t.z[c][j];
            t.counted[c] += counted(c, j);
        }
        t.chi2[c] = chi2;
        t.p[c] = chi2_upper(chi2, double(std::max<size_t>(t.counted[c], 1)));
        t.statistic += chi2;
    }
    double mean = 0.0, var = 0.0;
    for (size_t c = 0; c < 3; ++c) mean += double(t.counted[c]);
    var = 2.0 * mean;
    for (size_t q = 0; q < 3; ++q) {
        const size_t c0 = pairs[q][0], c1 = pairs[q][1];
        double sum = 0.0;
        size_t both = 0;
        for (size_t j = 0; j < k; ++j) {
            // A tile-channel without any variance, not even the floor's, is 0 in both images
            // everywhere (differences.h): it has no correlation to estimate, and 0 / 0 would
            // turn the whole statistic into NaN.
            const double scale = std::sqrt(sum_var[c0][j] * sum_var[c1][j]);
            if (!counted(c0, j) || !counted(c1, j) || !(scale > 0.0)) continue;
            sum += sum_cross[q][j] / scale;
            ++both;
        }
        t.correlation[q] = both ? std::clamp(sum / double(both), -1.0, 1.0) : 0.0;
        var += 4.0 * double(both) * t.correlation[q] * t.correlation[q];
    }
    t.scale = var / (2.0 * mean);
    t.dof = 2.0 * mean * mean / var;
    t.p_value = chi2_upper(t.statistic / t.scale, t.dof);
    return t;
}

} // namespace tp
