#include "compare/pixel_test.h"

#include "compare/distributions.h"

#include <cmath>

namespace tp {

bool PixelTest::significant(int c, size_t pixel) const {
    return holm.rejected[size_t(c) * z[0].size() + pixel] != 0;
}

PixelTest pixel_test(const Differences& d, double level) {
    PixelTest t;
    const size_t n = size_t(d.width) * size_t(d.height);
    std::vector<double> all_p;
    all_p.reserve(3 * n);
    for (int c = 0; c < 3; ++c) {
        const size_t cc = size_t(c);
        t.z[cc].resize(n);
        t.p[cc].resize(n);
        for (size_t i = 0; i < n; ++i) {
            // var is 0 only where a = b = 0 in a channel that is 0 everywhere: no evidence.
            const double v = d.var[cc][i];
            const double z = v > 0.0 ? d.d[cc][i] / std::sqrt(v) : 0.0;
            t.z[cc][i] = z;
            t.p[cc][i] = two_sided_p(z, d.dof(c, i));
            all_p.push_back(t.p[cc][i]);
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
