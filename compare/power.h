// The power of compare's global test (tile_test.h) against a uniform relative bias: the model
// that `twinpath verify` plans its sample counts with (docs/compare.md, "Power model").
//
// Let both images estimate a pixel-channel's mean mu with per-sample variance sigma^2, and one
// of them be off by delta mu everywhere. Tile j's channel c then has z_jc ~ N(m_jc, 1) with
//
//     m_jc = delta S_jc / sqrt(V_jc / n_eff),  S_jc = sum_i mu_ic,  V_jc = sum_i sigma^2_ic,
//     1 / n_eff = 1 / n_a + 1 / n_b,
//
// the sums over the tile's pixels that have a variance (a pixel without any, such as an emitter
// seen directly, is left out: the floor makes a bias there far easier to see, and leaving it
// out keeps the model on the safe side). The channels of a tile are correlated with the matrix
// R of tile_test.h, so X = sum z^2 has
//
//     E X   = sum_c K_c + sum_jc m_jc^2,
//     Var X = 2 sum_c K_c + 4 sum_q K_q r_q^2 + 4 sum_j m_j^T R m_j,
//
// (the moments of a quadratic form in normal variables), and X is matched in these two moments
// to a chi-square a chi2_f, as the test matches its null to g chi2_h (Patnaik 1949, "The
// non-central chi-square and F-distributions and their applications"; with m = 0 both are the
// null of tile_test.h). The power at a level is P(a chi2_f >= g chi2_h(1 - level)). Since every
// m scales with delta sqrt(n_eff), the power depends on delta^2 n_eff alone.
//
// The model is the global test's alone: the verdict rejects when the local test does too, so
// the whole test's power is at least this (compare.h). With the Sobol sampler the variance of a
// mean is below sigma^2 / n (docs/sampling.md), which again only adds power.
#pragma once

#include "compare/rgb_image.h"

#include <array>

namespace tp {

struct PowerModel {
    double signal = 0;      // sum_jc S_jc^2 / V_jc: the noncentrality at delta = 1, n_eff = 1
    double signal_corr = 0; // sum_j s_j^T R s_j with s_jc = S_jc / sqrt(V_jc)
    double null_mean = 0;   // sum_c K_c: tile-channels with a variance
    double null_var = 0;    // 2 sum_c K_c + 4 sum_q K_q r_q^2
    // The standard error of `signal` from the error of the V_jc estimates (VarianceSplit); 0
    // when not estimated.
    double signal_se = 0;
    // False when no tile has any variance: no sample count makes a bias visible to the model
    // (and every difference of such images is found through the floor, differences.h).
    bool informative() const { return signal > 0.0; }
    // The model at the lower confidence bound signal - z se (at least a quarter of signal):
    // signal and signal_corr both scale as 1 / V.
    PowerModel lower_bound(double z) const;
};

// Two independent estimates of the per-sample variance, with their degrees of freedom, whose
// pooled value (weighted by the degrees of freedom) is the one the model is built from. The
// error of a tile's V_jc is unknown from one estimate; from two, the difference of their tile
// sums estimates it: Var(V_pooled) = (V_a - V_b)^2 d_a d_b / (d_a + d_b)^2 (the pooled value
// weights each by its d, and Var(V_a - V_b) = v (1 / d_a + 1 / d_b) for a variance v per degree
// of freedom). A tile's error moves the signal by -sum_c (S_jc / V_jc)^2 dV_jc (its channels'
// errors together, since they come from the same paths); tiles are independent.
struct VarianceSplit {
    const Planes* a = nullptr;
    const Planes* b = nullptr;
    double dof_a = 0, dof_b = 0;
};

// `mean` and `sample_variance`: per pixel-channel mu and sigma^2 of one sample, estimated from
// any renderings of the scene; `correlation`: R's RG, RB, GB (TileTest::correlation); `tile`:
// the global test's tile side, clipped to the image as compare clips it; `split`: when given,
// signal_se from it.
PowerModel power_model(int width, int height, const Planes& mean, const Planes& sample_variance,
                       const std::array<double, 3>& correlation, int tile,
                       const VarianceSplit* split = nullptr);

// 1 / (1 / n_a + 1 / n_b).
double effective_spp(double n_a, double n_b);

// The probability that the global test at `level` rejects a relative bias `bias` at n_eff.
double global_test_power(const PowerModel& m, double bias, double n_eff, double level);

// The smallest n_eff at which the power reaches `power`; +inf when the model is not
// informative.
double required_effective_spp(const PowerModel& m, double bias, double level, double power);

// The smallest relative bias found with probability `power` at n_eff; +inf when the model is
// not informative.
double detectable_bias(const PowerModel& m, double n_eff, double level, double power);

} // namespace tp
