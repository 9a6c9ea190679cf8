// The local test: one Welch t statistic per pixel-channel, z = (a - b) / sqrt(var_a + var_b)
// (plus the floor, differences.h), with Welch-Satterthwaite degrees of freedom, and Holm's
// procedure over all 3 W H pixel-channels. It finds a few pixels that are far off.
//
// Student's t rather than the normal: with 16 spp the normal tail at |z| = 5 is ~30x too
// light (t with ~30 dof), and Holm's thresholds sit exactly there (p ~ alpha / 10^4).
// With two images the statistic is symmetric in a and b, so a skewed (firefly) sample
// distribution makes it conservative rather than liberal; docs/compare.md has the numbers.
#pragma once

#include "compare/differences.h"
#include "compare/holm.h"

namespace tp {

struct PixelTest {
    Planes z;                      // signed, (a - b) / sigma
    Planes p;                      // two-sided p-value per pixel-channel
    HolmResult holm;               // hypotheses ordered channel-major: index c * W * H + pixel
    size_t significant_pixels = 0; // pixels with at least one significant channel
    double max_abs_z = 0.0;
    int max_x = 0, max_y = 0, max_channel = 0;

    bool significant(int c, size_t pixel) const;
};

PixelTest pixel_test(const Differences& d, double level);

} // namespace tp
