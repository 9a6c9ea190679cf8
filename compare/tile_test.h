// The global test: evidence pooled over the whole image, so that a small bias spread over
// many pixels is found even when no single pixel is significant.
//
// The image is cut into T x T tiles (edge tiles smaller). Per tile and channel the summed
// difference has the summed variance, z_T = sum d / sqrt(sum var), with Welch-Satterthwaite
// dof nu_T ~ T^2 (spp - 1); z_T is mapped to the normal quantile of equal tail probability.
// Under H0 the tiles are independent N(0,1), so X_c = sum_T z_T^2 ~ chi-square(K) for each
// channel c (K tiles); a bias of delta per pixel adds the noncentrality sum delta^2 / sigma^2
// whatever T is, so fewer, larger tiles mean fewer degrees of freedom for the same signal:
// more power for smooth bias, less for a bias confined to a few pixels. A tile-channel whose
// pixels all have zero estimated variance (an emitter seen directly) is not a N(0,1) variable
// but ~0 under H0: its z^2 stays in the sum (a real difference there is still found) but not
// in the degrees of freedom, which would otherwise be inflated.
//
// Fireflies: one rare large sample makes a pixel's mean and its variance estimate move
// together, and the per-pixel statistic is then far from normal. A tile sums T^2 pixels, so
// its skewness falls by T (the central limit theorem over pixels), and z_T is close to normal
// where single pixels are not; tests/compare/test_calibration.cpp checks the rejection rate
// with lognormal and Pareto samples.
//
// Channels: R, G and B of one pixel come from the same paths and are strongly correlated, so
// the 3 K tile-channel z^2 are summed into one statistic X whose null distribution is a
// weighted sum of chi-squares, X = sum_j lambda_j chi2_K over the eigenvalues lambda_j of the
// channels' correlation matrix R. It is approximated by matching two moments, X ~ g chi2_h
// with E X = sum_c K_c and Var X = 2 sum_c K_c + 4 sum_(c<c') K_cc' r_cc'^2 (K_c the counted
// tiles of channel c, K_cc' those counted in both): g = Var / 2E, h = 2 E^2 / Var
// (Satterthwaite 1946; Box 1954, "Some theorems on quadratic forms..."); with every tile
// counted, g = tr(R^2) / 3, exact for independent (g = 1) and identical channels (g = 3). R is
// estimated over the whole image from the products of the pixel differences: under H0,
// E[d_c d_c'] = Cov(d_c, d_c'), so sum_i d_ic d_ic' / sqrt(V_Tc V_Tc') estimates the tile-level
// correlation without bias, with an error ~ 1/sqrt(pixels). (Counting the channels as three
// tests by Bonferroni would spend a third of the level on each of three nearly equal tests.)
#pragma once

#include "compare/differences.h"

#include <array>

namespace tp {

constexpr int kDefaultTile = 8;

struct TileTest {
    int tile = kDefaultTile;
    int tiles_x = 0, tiles_y = 0;
    Planes z;                            // normal-equivalent tile z, tiles_x * tiles_y per channel
    std::array<double, 3> chi2{}, p{};   // per channel, chi2_(K_c): diagnostics for the report
    std::array<size_t, 3> counted{};     // K_c: tile-channels with estimated variance
    std::array<double, 3> correlation{}; // estimated R: RG, RB, GB
    double statistic = 0;                // X = sum of all 3 K tile z^2
    double scale = 1, dof = 0;           // g and h
    double p_value = 1.0;                // P(g chi2_h >= X)

    int tiles() const { return tiles_x * tiles_y; }
};

TileTest tile_test(const Differences& d, int tile);

} // namespace tp
