#include "compare/colormap.h"

#include <algorithm>
#include <cmath>

namespace tp {

std::array<uint8_t, 3> diverging_color(double t) {
    constexpr double cool[3] = {59, 76, 192}, mid[3] = {221, 221, 221}, warm[3] = {180, 4, 38};
    t = std::clamp(t, -1.0, 1.0);
    const double* end = t < 0.0 ? cool : warm;
    const double s = std::fabs(t);
    std::array<uint8_t, 3> out;
    for (int k = 0; k < 3; ++k)
        out[size_t(k)] = uint8_t(std::lround(mid[k] + s * (end[k] - mid[k])));
    return out;
}

} // namespace tp
