// The global test: evidence pooled over the whole image, so that a small bias spread over
// many pixels is found even when no single pixel is significant.
//
// The image is cut into T x T tiles (edge tiles smaller). Per tile and channel the summed
// difference has the summed variance, z_T = sum d / sqrt(sum var), with Welch-Satterthwaite
// dof nu_T ~ T^2 (spp - 1); z_T is mapped to the normal quantile of equal tail probability.
// Under H0 the tiles are independent N(0,1), so X_c = sum_T z_T^2 ~ chi-square(K) for each
// channel c (K tiles); a bias of delta per pixel adds the noncentrality sum delta^2 / sigma^2
// whatever T is, so fewer, larger tiles mean fewer degrees of freedom for the same signal:
// more power for smooth bias, less for a bias confined to a few pixels.
//
// Fireflies: one rare large sample makes a pixel's mean and its variance estimate move
// together, and the per-pixel statistic is then far from normal. A tile sums T^2 pixels, so
// its skewness falls by T (the central limit theorem over pixels), and z_T is close to normal
// where single pixels are not; tests/compare/test_calibration.cpp checks the rejection rate
// with lognormal and Pareto samples.
//
// Channels are tested separately and combined by Bonferroni (3 min p): R, G and B of one pixel
// are correlated through their shared paths, so their chi-squares may not be summed.
#pragma once

#include "compare/differences.h"

#include <array>

namespace tp {

constexpr int kDefaultTile = 8;

struct TileTest {
    int tile = kDefaultTile;
    int tiles_x = 0, tiles_y = 0;
    Planes z; // normal-equivalent tile z, tiles_x * tiles_y per channel
    std::array<double, 3> chi2{}, p{};
    double p_value = 1.0; // min(1, 3 min_c p_c)

    int tiles() const { return tiles_x * tiles_y; }
};

TileTest tile_test(const Differences& d, int tile);

} // namespace tp
