#include "rates.h"

#include <boost/math/distributions/binomial.hpp>
#include <fmt/format.h>

namespace tp::test {

CountInterval binomial_interval99(size_t n, double p) {
    const boost::math::binomial_distribution<double> b(double(n), p);
    // The default discrete-quantile policy rounds outwards: the interval covers >= 99%.
    return {size_t(boost::math::quantile(b, 0.005)),
            size_t(boost::math::quantile(boost::math::complement(b, 0.005)))};
}

size_t binomial_lower_bound(size_t n, double p, double tail) {
    const boost::math::binomial_distribution<double> b(double(n), p);
    size_t k = 0;
    while (k < n && boost::math::cdf(b, double(k)) <= tail) ++k;
    return k;
}

std::string describe_rate(const std::string& name, size_t k, size_t n, double alpha) {
    const CountInterval ci = binomial_interval99(n, alpha);
    return fmt::format("{}: {} of {} rejected at alpha {} (rate {:.4f}; 99% interval [{}, {}])",
                       name, k, n, alpha, double(k) / double(n), ci.lo, ci.hi);
}

} // namespace tp::test
