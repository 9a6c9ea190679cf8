#include "scene/alias_table.h"

#include "util/error.h"

#include <cmath>

namespace tp {

std::vector<AliasEntry> build_alias_table(const std::vector<double>& weights) {
    const size_t n = weights.size();
    double sum = 0.0;
    for (double w : weights) {
        if (!(w >= 0.0) || !std::isfinite(w)) runtime_error("alias table: invalid weight {}", w);
        sum += w;
    }
    if (n == 0 || !(sum > 0.0)) runtime_error("alias table: weights sum to zero");
    std::vector<AliasEntry> table(n);
    std::vector<double> scaled(n);
    std::vector<uint32_t> small, large;
    for (size_t i = 0; i < n; ++i) {
        table[i].pdf = float(weights[i] / sum);
        table[i].alias = uint32_t(i);
        scaled[i] = weights[i] / sum * double(n);
        (scaled[i] < 1.0 ? small : large).push_back(uint32_t(i));
    }
    while (!small.empty() && !large.empty()) {
        const uint32_t s = small.back(), l = large.back();
        small.pop_back();
        table[s].prob = float(scaled[s]);
        table[s].alias = l;
        scaled[l] = (scaled[l] + scaled[s]) - 1.0;
        if (scaled[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // What remains has probability 1 up to round-off (Vose, sec. 3).
    for (uint32_t i : large) table[i].prob = 1.0f;
    for (uint32_t i : small) table[i].prob = 1.0f;
    return table;
}

} // namespace tp
