// How compare shows linear radiance: one exposure for both images, chosen from the reference
// so that its 99th percentile of max(R, G, B) maps to display white (scenes differ by orders
// of magnitude: the furnace is ~5, a Cornell box ~0.1-1).
#pragma once

#include "compare/rgb_image.h"

#include <cstdint>
#include <vector>

namespace tp {

float auto_exposure(const RgbImage& ref);

// sRGB-encoded values in [0, 1], interleaved RGB, rows top to bottom.
std::vector<float> display_srgb(const RgbImage& img, float exposure_stops);

// 8-bit version of the same, for PNG files.
std::vector<uint8_t> display_srgb8(const RgbImage& img, float exposure_stops);

} // namespace tp
