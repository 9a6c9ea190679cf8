// Power-law fits on a log-log plot: error against time falls as a power of time (slope -1
// for an unbiased Monte Carlo estimator, whose variance is V/n after n samples; Veach 1997,
// sec. 2.4.1), so a straight line through (log t, log e) interpolates between measured
// points better than a line through (t, e).
#pragma once

#include <optional>
#include <vector>

namespace tp::bench {

struct LogLogFit {
    double intercept = 0, slope = 0; // log10 e = intercept + slope log10 t
    size_t points = 0;               // (t, e) pairs with t > 0 and e > 0 that were used
    bool valid() const { return points >= 2 && slope < 0; }
};

// Least squares of log10 e on log10 t over the pairs where both are positive.
LogLogFit fit_loglog(const std::vector<double>& t, const std::vector<double>& e);

// The time at which the fitted line reaches `target`, if some measured e is at or below the
// target (an interpolation; e <= 0 counts as reached); empty when the measurements never got there
// ("not reached": the line is not extrapolated beyond the data) or the fit is not a falling line.
std::optional<double> time_to_reach(const LogLogFit& fit, const std::vector<double>& e,
                                    double target);

} // namespace tp::bench
