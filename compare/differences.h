// Per pixel-channel difference d = a - b, the variance of that difference and the
// Welch-Satterthwaite degrees of freedom, shared by the pixel test, the tile test and the
// report. Pixels are independent (every random number depends on its own pixel, docs/design.md),
// so these are the only second moments the tests need.
//
// Unequal sample counts: the image with fewer samples borrows the other's per-sample variance
// when that is larger. Var(mean) = sigma^2 / n, and each image estimates sigma^2 as
// s^2 = n var. For a heavy-tailed pixel (a caustic reached only when a BSDF sample happens to
// hit the light through glass) the side with few samples has usually not met its rare large
// samples, so its mean is low *and* its s^2 is far too small: the one-sample failure of
// Student's t under skew, whose tail error is of order gamma / sqrt(n) (Hall 1987, "Edgeworth
// expansion for Student's t statistic under minimal moment conditions"). At equal n the two
// images enter symmetrically and that error cancels to first order; at n_a << n_b the
// difference is dominated by a alone and it does not. The side with more samples has met the
// rare samples far more often, so under H0 (one estimator, one sigma) its s^2 is the better
// estimate. Taking max(s^2_a, s^2_b) for the side with fewer samples keeps both tails in
// check: a pixel that missed the rare samples gets the variance they imply (z ~ -sqrt(lambda)
// for lambda expected rare samples instead of a huge t), and one that met k of them keeps its
// own, larger s^2, which self-normalises the excess (z ~ sqrt(k) instead of (k - lambda) /
// sqrt(lambda)). When the two estimators differ in variance the larger one can only make the
// test conservative, never liberal. The pixel test applies the rule per pixel; the tile test
// applies it to the tile's summed variances (tile_test.h), where the max of two sums inflates
// the variance less than a sum of per-pixel maxima. docs/compare.md has the calibration at
// 1:8 and 1:64.
//
// The per-sample variance lent is s^2 = n var for an image whose samples are independent. For a
// batch-estimated image (the Sobol sampler, render/film.h) n var understates sigma^2 by the
// stratification's gain, so such an image lends its sample_variance channel instead: the
// unbiased sample variance of its samples, which estimates the variance of one sample's
// marginal distribution (docs/sampling.md, "Unequal spp").
#pragma once

#include "compare/rgb_image.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tp {

// Relative floor r for the standard deviation of a difference; see floor_variance().
constexpr double kDefaultRelativeFloor = 1e-4;

// The borrowing rule above for one pair of variances of the mean (a pixel's, or a tile's
// sums): which side borrows, the ratio n_other / n_self that turns the other side's per-sample
// variance over its own n into this side's, and 1 / dof of each image's estimate and of the
// per-sample variance it lends (0: taken as exact).
struct VarianceRule {
    enum Borrower : uint8_t { None, A, B } borrower = None;
    double ratio = 1.0;
    double inv_dof_a = 0.0, inv_dof_b = 0.0;
    double inv_dof_lend_a = 0.0, inv_dof_lend_b = 0.0;
};

// One image's side of a pixel-channel (or a tile's sums): its variance of the mean, what it
// lends (its per-sample variance over its own n; equal to var unless batch-estimated) and the
// sums of their squares over the summed pixels (var^2, lend^2 for one pixel).
struct SideVariance {
    double var = 0.0, var2 = 0.0;
    double lend = 0.0, lend2 = 0.0;
};

struct PairVariance {
    double var = 0.0;   // var_a + var_b after borrowing
    double welch = 0.0; // sum over the summed pixels of var_i^2 / dof_i, for Welch-Satterthwaite
    bool borrowed = false;
};

PairVariance pair_variance(const VarianceRule& rule, const SideVariance& a, const SideVariance& b);

struct Differences {
    int width = 0, height = 0;
    VarianceRule rule;
    Planes d;              // a - b
    Planes var_a, var_b;   // each image's own variance of the mean (0 for an exact image)
    Planes lend_a, lend_b; // what each lends: its per-sample variance over its own n
    Planes floor;          // floor^2 (floor_variance)
    Planes noise;          // var_a + var_b after borrowing: the variance the images estimated
    Planes var;            // noise + floor^2
    Planes welch;          // var_a^2/(dof_a) + var_b^2/(dof_b); 0 where the floor alone remains
    size_t at_floor = 0;   // pixel-channels whose estimated variance is 0 in both images
    // Pixel-channels where the image with fewer samples took the other's per-sample variance.
    size_t variance_borrowed = 0;
    std::vector<uint8_t> borrowed; // per pixel: 1 when any of its channels borrowed
    size_t pixels_borrowed = 0;    // pixels with a 1 in `borrowed`

    // Welch-Satterthwaite: nu = var^2 / welch; infinite (normal) when welch is 0.
    double dof(int c, size_t i) const;
};

// "A (8x fewer samples) took B's per-sample variance where it was larger: 812 of 3072
// pixel-channels, 301 of 1024 pixels", for the report.
std::string borrowing_sentence(const Differences& d);

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
// taken as exact (variance 0), as Mitsuba 3's render tests do with their reference. The
// variance borrowing above needs both images' variance and spp, and unequal spp.
Differences compute_differences(const RgbImage& a, const RgbImage& b, double relative_floor);

} // namespace tp
