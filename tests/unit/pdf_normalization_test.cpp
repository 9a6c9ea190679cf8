// Every direction pdf of sampling.h and brdf.h integrates over the sphere to the probability that
// its sampler returns a direction: 1, except for the Phong mixture, whose glossy lobe can reach
// below the horizon.
//
// Quadrature as in phong_energy_test.cpp (charts whose cell edges follow the horizon wherever a
// pdf is cut off there); tolerance eps(n) = 1e-6 + n 2^-25, the cubature's error plus the
// float rounding of cos(alpha) raised to the n-th power.
#include "chi2/suite.h"
#include "unit/phong_chart.h"

#include "shared/brdf.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace tp::test::chi2;

namespace {

const glm::dvec3 kZ(0.0, 0.0, 1.0);

double tolerance(float n) {
    return 1e-6 + double(n) * 0x1p-25;
}

SphereChart lobe_chart(const glm::dvec3& axis, float n) {
    return SphereChart::lobe(axis, 0.05 / (double(n) + 1.0), 48, 64);
}

} // namespace

TEST_CASE("cosine and uniform sphere pdfs integrate to 1", "[pdf]") {
    CHECK(std::abs(integrate_sphere(SphereChart::uniform(kZ, 32, 32),
                                    [](const glm::dvec3& w) {
                                        return double(tp::cosine_hemisphere_pdf(float(w.z)));
                                    }) -
                   1.0) <= tolerance(0.0f));
    CHECK(std::abs(integrate_sphere(SphereChart::uniform(kZ, 32, 32),
                                    [](const glm::dvec3&) { return double(tp::INV_FOUR_PI); }) -
                   1.0) <= tolerance(0.0f));
}

TEST_CASE("Phong lobe pdf integrates to 1 for n from 0 to 10^4", "[pdf]") {
    for (float n : {0.0f, 1.0f, 10.0f, 100.0f, 1000.0f, 10000.0f}) {
        const double mass = integrate_sphere(lobe_chart(kZ, n), [n](const glm::dvec3& w) {
            return double(tp::phong_lobe_pdf(float(w.z), n));
        });
        CAPTURE(n, mass);
        CHECK(std::abs(mass - 1.0) <= tolerance(n));
    }
}

TEST_CASE("Phong mixture pdf integrates to 1 - (1 - P_d) x (lobe mass below the horizon)",
          "[pdf]") {
    // phong_sample draws the glossy lobe with probability 1 - P_d and gives up when the draw
    // lands below the horizon, which happens with the lobe's mass there,
    //   m_below = integral over n.w <= 0 of (n + 1)/(2 pi) cos^n(alpha) d omega,
    // while phong_pdf, which is 0 below the horizon, must integrate to exactly what is left.
    // m_below is integrated on its own, from the lobe pdf alone, in the lobe's frame.
    const struct {
        float kd, ks, n;
        double theta_o;
    } cases[] = {{0.5f, 0.5f, 1.0f, 0.0},   {0.5f, 0.5f, 1.0f, 60.0},   {0.2f, 0.7f, 10.0f, 45.0},
                 {0.0f, 0.9f, 20.0f, 85.0}, {0.1f, 0.8f, 100.0f, 80.0}, {0.05f, 0.9f, 1e4f, 89.0},
                 {0.8f, 0.0f, 50.0f, 70.0}};
    const tp::vec3 n(0.0f, 0.0f, 1.0f);
    for (const auto& c : cases) {
        const double t = glm::radians(c.theta_o);
        const tp::vec3 wo(float(std::sin(t)), 0.0f, float(std::cos(t)));
        const SphereChart chart = tp::test::phong_chart(t, double(c.n));
        // The lobe as phong_pdf evaluates it, cos(alpha) from the float mirror direction.
        const tp::vec3 r = tp::mirror_direction(n, wo);
        const auto lobe = [&](const glm::dvec3& w) {
            return double(tp::phong_lobe_pdf(glm::dot(r, tp::vec3(w)), c.n));
        };
        const double total = integrate_sphere(chart, [&](const glm::dvec3& w) {
            return double(tp::phong_pdf(tp::vec3(c.kd), tp::vec3(c.ks), c.n, n, wo, tp::vec3(w)));
        });
        const double below = integrate_sphere(
            chart, [&](const glm::dvec3& w) { return w.z <= 0.0 ? lobe(w) : 0.0; });
        const double lobe_total = integrate_sphere(chart, lobe);
        const double pd = double(tp::phong_diffuse_probability(tp::vec3(c.kd), tp::vec3(c.ks)));
        CAPTURE(c.kd, c.ks, c.n, c.theta_o, total, below, lobe_total, pd);
        // The float lobe integrates to 1 only up to the rounding of cos(alpha) raised to the
        // n-th power (kCosError = 1e-6 from a float reflection, normalize and dot; measured in
        // brdf_test.cpp); that deviation is measured here and carried into the mixture's
        // tolerance, which otherwise is the cubature's.
        CHECK(std::abs(lobe_total - 1.0) <= tolerance(c.n) + double(c.n) * 1e-6);
        CHECK(std::abs(total - (1.0 - (1.0 - pd) * below)) <=
              2.0 * tolerance(0.0f) + (1.0 - pd) * std::abs(lobe_total - 1.0));
        if (c.theta_o == 0.0) CHECK(below == 0.0); // the lobe about the normal stays above
    }
}
