// Diverging colour map for signed quantities (differences, z-scores): blue for negative, a
// light grey at zero, red for positive, after Moreland's "cool to warm" map ("Diverging Color
// Maps for Scientific Visualization", ISVC 2009), here interpolated linearly in sRGB between
// his end and middle colours.
#pragma once

#include <array>
#include <cstdint>

namespace tp {

// t in [-1, 1] (clamped) -> sRGB8.
std::array<uint8_t, 3> diverging_color(double t);

} // namespace tp
