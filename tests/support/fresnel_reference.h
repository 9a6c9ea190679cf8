// Fresnel reflectance of a smooth dielectric for unpolarised light, in double precision from
// the textbook equations (Born & Wolf; pbrt-v4 eq. 9.12-9.13), independent of brdf.h: the
// reference that the unit and chi-square tests of the dielectric hold brdf.h to.
#pragma once

#include <cmath>

namespace tp::test {

// cos_i: cosine of the incident angle; eta: ratio of the indices, transmitted over incident.
inline double fresnel_reference(double cos_i, double eta) {
    const double sin2_t = (1.0 - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0) return 1.0;
    const double cos_t = std::sqrt(1.0 - sin2_t);
    const double rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    const double rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

} // namespace tp::test
