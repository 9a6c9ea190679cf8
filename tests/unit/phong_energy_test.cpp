// Energy of the modified Phong BRDF (Lafortune & Willems 1994): its directional albedo
// rho(wo) = integral over the hemisphere of f(wo, wi) cos(theta_i) d omega_i is at most 1 when
// kd + ks <= 1, equals kd + ks at normal incidence and kd for the diffuse part at every angle;
// and the sampler's mean weight f cos / pdf estimates the same albedo.
//
// Quadrature: tests/support/chi2.h's adaptive Gauss-Legendre cubature over phong_chart.h's
// chart, in which the horizon is a cell edge and the lobe is resolved, so the integrand is smooth
// in every cell. A cell's 5x5-point estimate is compared with the sum over its quadrants and
// accepted at a relative difference of 1e-3; the quadrants' sum is returned, more accurate by
// the rule's order (2^10 on a smooth cell), so ~1e-6. The closed forms below measure the
// error reached. The tolerance of every albedo assertion is
//   eps(n) = 1e-6 + n 2^-25:
// the cubature's 1e-6, plus the float rounding of cos(alpha) in phong_eval (2^-25 near 1),
// which cos^n turns into a relative error of n 2^-25 (2e-5 of the lobe at n = 10^4 is what
// it reaches).
#include "chi2/suite.h"
#include "unit/phong_chart.h"

#include "shared/brdf.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace tp::test::chi2;

namespace {

const tp::vec3 kN(0.0f, 0.0f, 1.0f);

tp::vec3 outgoing(double theta_degrees) {
    const double t = glm::radians(theta_degrees);
    return tp::vec3(float(std::sin(t)), 0.0f, float(std::cos(t)));
}

double tolerance(float n) {
    return 1e-6 + double(n) * 0x1p-25;
}

// rho(wo) of phong_eval for scalar kd, ks (the red channel of grey colours).
double albedo(float kd, float ks, float n, double theta_o_degrees) {
    const tp::vec3 wo = outgoing(theta_o_degrees);
    const SphereChart chart = tp::test::phong_chart(glm::radians(theta_o_degrees), double(n));
    return integrate_sphere(chart, [&](const glm::dvec3& w) {
        const tp::vec3 wi(w);
        const float cos_i = wi.z;
        if (cos_i <= 0.0f) return 0.0;
        return double(tp::phong_eval(tp::vec3(kd), tp::vec3(ks), n, kN, wo, wi).x * cos_i);
    });
}

const float kExponents[] = {0.0f, 1.0f, 10.0f, 100.0f, 1000.0f, 10000.0f};

} // namespace

TEST_CASE("Phong albedo: closed forms", "[phong][energy]") {
    for (float n : kExponents) {
        CAPTURE(n);
        // Normal incidence: the lobe about wo = n lies entirely above the horizon and
        // integral (n+2)/(2 pi) cos^(n+1) d omega = 1, so rho = kd + ks exactly.
        CHECK(std::abs(albedo(0.0f, 1.0f, n, 0.0) - 1.0) <= tolerance(n));
        CHECK(std::abs(albedo(0.3f, 0.6f, n, 0.0) - 0.9) <= tolerance(n));
    }
    for (double theta : {0.0, 30.0, 60.0, 85.0, 89.9}) {
        CAPTURE(theta);
        // Lambertian part: kd / pi integrated against cos is kd at every angle.
        CHECK(std::abs(albedo(1.0f, 0.0f, 50.0f, theta) - 1.0) <= tolerance(0.0f));
    }
}

TEST_CASE("Phong albedo is at most 1 when kd + ks <= 1", "[phong][energy]") {
    // kd + ks = 1 is the hardest case (the albedo grows with both); one pair below it.
    const std::pair<float, float> pairs[] = {
        {1.0f, 0.0f}, {0.0f, 1.0f}, {0.5f, 0.5f}, {0.2f, 0.8f}, {0.25f, 0.5f}};
    for (float n : kExponents)
        for (double theta : {0.0, 30.0, 60.0, 80.0, 89.0})
            for (const auto& [kd, ks] : pairs) {
                const double a = albedo(kd, ks, n, theta);
                CAPTURE(kd, ks, n, theta, a);
                CHECK(a <= 1.0 + tolerance(n));
                CHECK(a <=
                      double(kd + ks) + tolerance(n)); // and at most its normal-incidence value
                CHECK(a >= double(kd) - tolerance(n)); // the diffuse part alone gives kd
            }
}

TEST_CASE("Phong sample weights average to the albedo", "[phong][energy]") {
    // E[f cos / p] over phong_sample's draws (a failed draw counts 0) is the integral of f cos
    // over the pdf's support, which holds f's. 10^6 draws; 5 standard errors (from the sample
    // variance) plus the quadrature tolerance.
    const struct {
        float kd, ks, n;
        double theta;
    } cases[] = {{0.3f, 0.6f, 10.0f, 40.0},
                 {0.1f, 0.9f, 1000.0f, 70.0},
                 {0.0f, 1.0f, 20.0f, 85.0},
                 {0.7f, 0.2f, 1.0f, 0.0}};
    for (const auto& c : cases) {
        const tp::vec3 wo = outgoing(c.theta);
        Uniform u(31);
        double sum = 0.0, sum_sq = 0.0;
        const int draws = 1000000;
        for (int i = 0; i < draws; ++i) {
            const glm::vec4 r = u.next4();
            const tp::BsdfSample s = tp::phong_sample(tp::vec3(c.kd), tp::vec3(c.ks), c.n, kN, wo,
                                                      r.x, tp::vec2(r.y, r.z));
            const double w = s.lobe == tp::LOBE_NONE ? 0.0 : double(s.weight.x);
            sum += w;
            sum_sq += w * w;
        }
        const double mean = sum / draws;
        const double se = std::sqrt((sum_sq / draws - mean * mean) / (draws - 1));
        const double a = albedo(c.kd, c.ks, c.n, c.theta);
        CAPTURE(c.kd, c.ks, c.n, c.theta, mean, se, a);
        CHECK(std::abs(mean - a) <= 5.0 * se + tolerance(c.n));
    }
}
