// Rejection-rate checks for calibration tests: under H0 the number of rejections in n
// independent trials at level alpha is Binomial(n, alpha); its central 99% interval is the
// range a calibrated test stays inside (a 1% chance of failing when exact).
#pragma once

#include <cstddef>
#include <string>

namespace tp::test {

struct CountInterval {
    size_t lo = 0, hi = 0; // inclusive
};

// Central 99% interval of Binomial(n, p): 0.5% in each tail, rounded outwards (Boost.Math).
CountInterval binomial_interval99(size_t n, double p);

// The fewest successes a test of success probability p shows in n trials with probability
// 1 - tail: the largest k with P(X < k) <= tail for X ~ Binomial(n, p) (Boost.Math).
size_t binomial_lower_bound(size_t n, double p, double tail);

// "name: k of n rejected at alpha (99% interval [lo, hi])", for Catch2's INFO.
std::string describe_rate(const std::string& name, size_t k, size_t n, double alpha);

} // namespace tp::test
