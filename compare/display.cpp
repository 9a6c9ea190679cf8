#include "compare/display.h"

#include "image/exposure.h"
#include "image/png_io.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace tp {

float auto_exposure(const RgbImage& ref) {
    std::vector<double> peak(ref.pixels());
    for (size_t i = 0; i < peak.size(); ++i)
        peak[i] = std::max({ref.mean[0][i], ref.mean[1][i], ref.mean[2][i]});
    return auto_exposure_stops(peak);
}

std::vector<float> display_srgb(const RgbImage& img, float exposure_stops) {
    const double scale = std::exp2(double(exposure_stops));
    std::vector<float> out(img.pixels() * 3);
    for (size_t i = 0; i < img.pixels(); ++i)
        for (size_t c = 0; c < 3; ++c)
            out[3 * i + c] = linear_to_srgb(float(img.mean[c][i] * scale)); // clamps to [0, 1]
    return out;
}

std::vector<uint8_t> display_srgb8(const RgbImage& img, float exposure_stops) {
    std::array<std::vector<float>, 3> f;
    for (size_t c = 0; c < 3; ++c) f[c].assign(img.mean[c].begin(), img.mean[c].end());
    return tonemap_srgb8(f[0], f[1], f[2], exposure_stops);
}

} // namespace tp
