#include "compare/significance_map.h"

#include "compare/colormap.h"
#include "compare/distributions.h"

#include <cmath>

namespace tp {

double signed_max(double r, double g, double b) {
    double v = r;
    if (std::fabs(g) > std::fabs(v)) v = g;
    if (std::fabs(b) > std::fabs(v)) v = b;
    return v;
}

double significance_full_z(const CompareResult& r) {
    const size_t n = size_t(r.diff.width) * size_t(r.diff.height);
    return normal_upper_quantile(r.local_level / (2.0 * double(3 * n)));
}

std::vector<uint8_t> significance_map(const CompareResult& r) {
    const size_t n = size_t(r.diff.width) * size_t(r.diff.height);
    const double z_full = significance_full_z(r);
    std::vector<uint8_t> rgb(3 * n);
    for (size_t i = 0; i < n; ++i) {
        const bool sig =
            r.local.significant(0, i) || r.local.significant(1, i) || r.local.significant(2, i);
        const double z = signed_max(r.local.z[0][i], r.local.z[1][i], r.local.z[2][i]);
        const std::array<uint8_t, 3> c =
            sig ? std::array<uint8_t, 3>{255, 230, 0} : diverging_color(z / z_full);
        for (int k = 0; k < 3; ++k) rgb[3 * i + k] = c[k];
    }
    return rgb;
}

} // namespace tp
