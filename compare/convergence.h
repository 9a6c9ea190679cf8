// `compare --convergence`: renderings of one scene at increasing spp against a reference.
//
// For an estimator with bias b_i and per-sample variance s_i^2 in pixel i, the expected error
// of the n-spp mean is E[(a_i - r_i)^2] = s_i^2 / n + b_i^2 + Var r_i (variance plus squared
// bias; Veach 1997, sec. 2.4.1). Averaged with the relMSE weights w_i = 1 / (r_i^2 + eps):
//
//     y(n) = relMSE(n) - mean(w Var r) = V / n + B,   V = mean(w s^2),  B = mean(w b^2),
//
// so an unbiased renderer gives y ∝ 1/n (a slope of -1 in log-log) and a biased one levels
// off at the plateau B; sqrt(B) is the bias as a root-mean-square relative error.
// V and B come from weighted least squares with weights n^2 (the standard error of y(n) ~ 1/n
// under H0), scaled by the per-point standard errors pooled (from the spread of the per-pixel
// terms; pixels are independent).
// The renderings must be independent (different seeds): a progressive series that shares
// samples correlates the y(n) and makes the standard errors too small.
// Verdict: bias when B / se(B) exceeds the one-sided normal quantile at alpha.
#pragma once

#include "compare/rgb_image.h"

#include <nlohmann/json.hpp>

#include <limits>
#include <string>
#include <vector>

namespace tp {

struct ConvergencePoint {
    std::string path;
    int64_t spp = 0;
    double relmse = 0;          // against the reference
    double excess = 0;          // y(n): relmse minus the reference's own noise
    double excess_stderr = 0;   // standard error of y(n)
    double noise_predicted = 0; // mean(w var_a): V/n as the image's variance channels predict it
};

struct ConvergenceResult {
    std::vector<ConvergencePoint> points; // sorted by spp
    double reference_noise = 0;           // mean(w Var r); 0 without reference variance
    double V = 0, V_stderr = 0;
    double B = 0, B_stderr = 0; // B unclamped: it is an estimate and may come out below 0
    double slope = std::numeric_limits<double>::quiet_NaN(); // of log y on log n, y > 0 only
    double alpha = 0.01;
    double p_value = 1.0; // one-sided, H0: B = 0
    bool biased = false;

    double relative_bias_rms() const;
};

// Throws InputError (naming the file) when an image lacks twinpath:spp, differs in size from
// the reference, or when fewer than two distinct spp are given.
ConvergenceResult convergence(const RgbImage& reference, const std::vector<RgbImage>& series,
                              double alpha);

nlohmann::json convergence_json(const ConvergenceResult& r, const RgbImage& reference);
std::string convergence_verdict_line(const ConvergenceResult& r);

} // namespace tp
