// Error metrics of A against B, per channel and over all three, in the forms the
// rendering literature uses (e.g. Rousselle, Knaus & Zwicker 2011): MSE, relative MSE
// (a - b)^2 / (r^2 + eps) and MAPE |a - b| / (|r| + eps) with r the
// reference (one of A and B), eps = 0.01 so that black pixels do
// not dominate. With variance channels, the MSE that noise alone would give, mean(var_a +
// var_b), is reported next to the MSE: their difference estimates the squared bias without
// bias of its own (E[(a - b)^2] = Var a + Var b + bias^2).
#pragma once

#include "compare/rgb_image.h"

#include <array>

namespace tp {

constexpr double kRelativeEpsilon = 0.01;

struct ChannelMetrics {
    double mse = 0, relmse = 0, mape = 0;
    double bias = 0;        // mean(a - b)
    double bias_stderr = 0; // sqrt(sum(var_a + var_b)) / N: the standard error of `bias`
    double mse_noise = 0;   // mean(var_a + var_b)
};

struct ErrorMetrics {
    std::array<ChannelMetrics, 3> channel;
    ChannelMetrics all; // mean over the channels (bias_stderr left 0: channels are correlated)
};

// `ref` is `a` or `b`: the image whose values divide in relMSE and MAPE.
ErrorMetrics error_metrics(const RgbImage& a, const RgbImage& b, const RgbImage& ref);

} // namespace tp
