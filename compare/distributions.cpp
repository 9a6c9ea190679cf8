#include "compare/distributions.h"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>

#include <cmath>

namespace tp {
namespace {

// Beyond this the t and normal tails agree to better than 1e-6 relative up to |z| ~ 40.
constexpr double kNormalDof = 1e8;

} // namespace

double normal_upper(double z) {
    return boost::math::cdf(boost::math::complement(boost::math::normal(), z));
}

double normal_upper_quantile(double p) {
    return boost::math::quantile(boost::math::complement(boost::math::normal(), p));
}

double two_sided_p(double z, double dof) {
    const double t = std::fabs(z);
    if (!std::isfinite(t)) return 0.0;
    if (!(dof < kNormalDof)) return 2.0 * normal_upper(t);
    return 2.0 * boost::math::cdf(boost::math::complement(boost::math::students_t(dof), t));
}

double equivalent_normal(double z, double dof) {
    if (!(dof < kNormalDof) || z == 0.0 || !std::isfinite(z)) return z;
    const double upper =
        boost::math::cdf(boost::math::complement(boost::math::students_t(dof), std::fabs(z)));
    // An upper tail that underflows is beyond any threshold; |z| itself is then a fine stand-in
    // (the t tail is heavier, so the exact answer lies below |z| but is still enormous).
    const double q = upper > 0.0 ? normal_upper_quantile(upper) : std::fabs(z);
    return std::copysign(q, z);
}

double chi2_upper(double x, double k) {
    if (!std::isfinite(x)) return 0.0;
    if (!(x > 0.0)) return 1.0;
    // Far below the mean Boost evaluates the lower tail P(a, y), a = k/2, y = x/2, by a series
    // whose prefix y^a e^-y / Gamma(a+1) overflows Gamma for k above about 5000 (a tile test of
    // a 1080p image that equals the other one). The series' terms fall by at least y/(a+1), so
    // P(a, y) <= y^a e^-y / Gamma(a+1) * (a+1)/(a+1-y) (Abramowitz & Stegun 6.5.29); below
    // 2^-60 the upper tail 1 - P is 1 in double.
    const double a = 0.5 * k, y = 0.5 * x;
    if (y < a + 1.0) {
        const double log_lower =
            a * std::log(y) - y - std::lgamma(a + 1.0) + std::log((a + 1.0) / (a + 1.0 - y));
        if (log_lower < -60.0 * std::log(2.0)) return 1.0;
    }
    return boost::math::cdf(boost::math::complement(boost::math::chi_squared(k), x));
}

double chi2_upper_quantile(double p, double k) {
    return boost::math::quantile(boost::math::complement(boost::math::chi_squared(k), p));
}

} // namespace tp
