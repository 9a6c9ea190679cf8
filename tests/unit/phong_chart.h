// A sphere chart for integrals of the Phong BRDF and pdf (tests/support/chi2.h): about the normal
// +Z, so that the horizon theta = pi/2, where the integrands are cut off, is a row edge and no
// cell straddles it; plus a band of rows and columns a quarter of the lobe's width apart around
// the mirror direction of wo = (sin theta_o, 0, cos theta_o), six widths to either side, so that
// a lobe cos^n with width ~1/sqrt(n + 1) is resolved (beyond six widths cos^n < 2e-8 of its
// peak). Every cell then holds a smooth integrand and the cubature converges at its full order.
#pragma once

#include "support/chi2.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace tp::test {

inline chi2::SphereChart phong_chart(double theta_o, double n) {
    const double pi = 3.14159265358979323846;
    const double w = 0.25 / std::sqrt(n + 1.0);
    std::vector<double> theta, phi;
    for (int i = 0; i <= 16; ++i) theta.push_back(0.5 * pi * i / 16.0);
    for (int i = 1; i <= 4; ++i) theta.push_back(0.5 * pi + 0.5 * pi * i / 4.0);
    for (int i = 0; i <= 32; ++i) phi.push_back(2.0 * pi * i / 32.0);
    const double sin_o = std::sin(theta_o);
    for (int k = -24; k <= 24; ++k) {
        const double t = theta_o + k * w;
        if (t > 0.0 && t < pi) theta.push_back(t);
        if (sin_o > 1e-3 && std::abs(k * w) < pi * sin_o) phi.push_back(pi + k * w / sin_o);
    }
    for (std::vector<double>* e : {&theta, &phi}) {
        std::sort(e->begin(), e->end());
        e->erase(std::unique(e->begin(), e->end(),
                             [](double a, double b) { return std::abs(a - b) < 1e-12; }),
                 e->end());
    }
    return chi2::SphereChart(glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), theta,
                             phi);
}

} // namespace tp::test
