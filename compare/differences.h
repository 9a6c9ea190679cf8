// Per pixel-channel difference d = a - b, the variance of that difference and the
// Welch-Satterthwaite degrees of freedom, shared by the pixel test, the tile test and the
// report. Pixels are independent (every random number depends on its own pixel, DESIGN.md),
// so these are the only second moments the tests need.
#pragma once

#include "compare/rgb_image.h"

namespace tp {

// Relative floor r for the standard deviation of a difference; see floor_variance().
constexpr double kDefaultRelativeFloor = 1e-4;

struct Differences {
    int width = 0, height = 0;
    Planes d;            // a - b
    Planes noise;        // var_a + var_b: the variance the images estimated
    Planes var;          // noise + floor^2
    Planes welch;        // var_a^2/(n_a-1) + var_b^2/(n_b-1); 0 where the floor alone remains
    size_t at_floor = 0; // pixel-channels whose estimated variance is 0 in both images

    // Welch-Satterthwaite: nu = var^2 / welch; infinite (normal) when welch is 0.
    double dof(int c, size_t i) const;
};

// Squared floor sigma_f^2 = r^2 (max(|a|,|b|)^2 + s^2), s = the channel's mean of max(|a|,|b|).
// Why: a pixel whose samples were all equal has a variance estimate of exactly 0, and two
// such pixels (an emitter seen directly, a constant background) can still differ by float
// rounding: the CPU film accumulates in double but stores float32 (2^-24 ~ 6e-8 relative), and
// a float32 GPU accumulator of n equal samples errs by up to (n-1) 2^-24 (Higham, "Accuracy
// and Stability of Numerical Algorithms", 2nd ed., sec. 4.2): r = 1e-4 covers n ~ 1600 in the
// worst case and ~1e6 samples at the typical sqrt(n) 2^-24. The second term keeps values near
// zero from turning a 1e-30 difference into a huge z; it is 1e-4 of the channel's mean level,
// far below display precision (1/255). Added to every pixel, the floor is negligible wherever
// sampling noise exists: a relative standard deviation of 1e-4 needs ~1e8 samples.
double floor_variance(double a, double b, double channel_scale, double relative_floor);

// `a` must have variance channels or `b` must (the caller checks); an image without them is
// taken as exact (variance 0), as Mitsuba 3's render tests do with their reference.
Differences compute_differences(const RgbImage& a, const RgbImage& b, double relative_floor);

} // namespace tp
