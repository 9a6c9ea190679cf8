#include "compare/pixel_test.h"

#include "compare/distributions.h"

#include <algorithm>
#include <cmath>

namespace tp {

bool PixelTest::significant(int c, size_t pixel) const {
    return holm.rejected[size_t(c) * z[0].size() + pixel] != 0;
}

PixelTest pixel_test(const Differences& d, double level) {
    PixelTest t;
    const size_t n = size_t(d.width) * size_t(d.height);
    // A p-value at or above max(level, 1/m) can neither be rejected by Holm (whose largest
    // threshold is `level`) nor move the family p-value min(1, m min p) below 1, so it is
    // recorded as 1. The normal tail is a lower bound of the t tail, which skips the costly
    // t distribution (~5 us) for all but the few pixel-channels in the tails.
    const double cutoff = std::max(level, 1.0 / (3.0 * double(n)));
    std::vector<double> all_p(3 * n, 1.0);
    for (int c = 0; c < 3; ++c) {
        const size_t cc = size_t(c);
        t.z[cc].resize(n);
        for (size_t i = 0; i < n; ++i) {
            // var is 0 only without noise and without floor (--floor 0, or a channel that is
            // 0 everywhere): any difference is then infinitely significant.
            const double v = d.var[cc][i], di = d.d[cc][i];
            const double z = v > 0.0     ? di / std::sqrt(v)
                             : di == 0.0 ? 0.0
                                         : std::copysign(HUGE_VAL, di);
            t.z[cc][i] = z;
            if (2.0 * normal_upper(std::fabs(z)) < cutoff)
                all_p[cc * n + i] = two_sided_p(z, d.dof(c, i));
            if (std::fabs(z) > t.max_abs_z) {
                t.max_abs_z = std::fabs(z);
                t.max_x = int(i % size_t(d.width));
                t.max_y = int(i / size_t(d.width));
                t.max_channel = c;
            }
        }
    }
    t.holm = holm(all_p, level);
    for (size_t i = 0; i < n; ++i)
        t.significant_pixels +=
            (t.holm.rejected[i] | t.holm.rejected[n + i] | t.holm.rejected[2 * n + i]) != 0;
    return t;
}

} // namespace tp
