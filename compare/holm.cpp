#include "compare/holm.h"

#include <algorithm>
#include <numeric>

namespace tp {

HolmResult holm(const std::vector<double>& p, double level) {
    HolmResult r;
    const size_t m = p.size();
    r.rejected.assign(m, 0);
    if (m == 0) return r;
    std::vector<size_t> order(m);
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return p[i] < p[j]; });
    r.p_value = std::min(1.0, double(m) * p[order[0]]);
    // Reject H_(k), k = 0, 1, ..., while p_(k) <= level / (m - k); stop at the first failure.
    for (size_t k = 0; k < m && p[order[k]] <= level / double(m - k); ++k) {
        r.rejected[order[k]] = 1;
        ++r.count;
    }
    return r;
}

} // namespace tp
