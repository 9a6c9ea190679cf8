// The per-pixel significance picture of a comparison: each pixel's z of largest magnitude over
// R, G, B on the diverging colour map (blue: A below B, red: A above), at full colour where the
// first Holm step would reject a pixel-channel, and yellow where a pixel-channel is rejected.
// The report's z.png and the viewer's compare overlay.
#pragma once

#include "compare/compare.h"

#include <cstdint>
#include <vector>

namespace tp {

// Of r, g, b, the value of largest magnitude, sign kept.
double signed_max(double r, double g, double b);

// The |z| at which the map reaches full colour: the first Holm step's threshold over the
// 3 W H pixel-channels at the local level.
double significance_full_z(const CompareResult& r);

// RGB8 rows, top down, r.diff.width x r.diff.height.
std::vector<uint8_t> significance_map(const CompareResult& r);

} // namespace tp
