// brdf.h against the equations it implements, evaluated independently in double precision:
// the modified Phong BRDF (thesis eq. 2.28) and its mixture pdf, reciprocity, phong_sample's
// agreement with phong_eval and phong_pdf, the mirror, and the smooth dielectric (Fresnel,
// Snell's law, total internal reflection).
#include "shared/brdf.h"
#include "support/fresnel_reference.h"

#include <catch2/catch.hpp>
#include <glm/glm.hpp>

#include <cmath>
#include <random>

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Rng {
    std::mt19937 g{17};
    float uniform() { return std::uniform_real_distribution<float>(0.0f, 1.0f)(g); }
    // A unit vector in the hemisphere about n, at least min_cos above its horizon.
    tp::vec3 above(const tp::vec3& n, float min_cos = 0.01f) {
        std::normal_distribution<float> d;
        for (;;) {
            tp::vec3 v = glm::normalize(tp::vec3(d(g), d(g), d(g)));
            if (glm::dot(v, n) < 0.0f) v = -v;
            if (glm::dot(v, n) >= min_cos) return v;
        }
    }
    tp::vec3 unit() { return above(tp::vec3(0, 0, 1), -1.0f); }
};

// Thesis eq. 2.28 in double: f = kd / pi + ks (n + 2) / (2 pi) max(cos alpha, 0)^n, the lobe
// confined to cos(alpha) > 0 for n = 0 too.
double phong_reference(double kd, double ks, double n, const glm::dvec3& nn, const glm::dvec3& wo,
                       const glm::dvec3& wi) {
    if (glm::dot(nn, wi) <= 0.0 || glm::dot(nn, wo) <= 0.0) return 0.0;
    const glm::dvec3 r = 2.0 * glm::dot(nn, wo) * nn - wo;
    const double c = glm::dot(r, wi);
    const double lobe = c > 0.0 ? std::pow(c, n) : 0.0;
    return kd / kPi + ks * (n + 2.0) / (2.0 * kPi) * lobe;
}

// The mixture pdf of brdf.h's comment: P_d cos / pi + (1 - P_d) (n + 1) / (2 pi) cos^n alpha
// over the upper hemisphere, P_d = kd / (kd + ks) for grey colours.
double pdf_reference(double kd, double ks, double n, const glm::dvec3& nn, const glm::dvec3& wo,
                     const glm::dvec3& wi) {
    const double cos_i = glm::dot(nn, wi);
    if (cos_i <= 0.0 || glm::dot(nn, wo) <= 0.0) return 0.0;
    const double pd = kd / (kd + ks);
    const glm::dvec3 r = 2.0 * glm::dot(nn, wo) * nn - wo;
    const double c = glm::dot(r, wi);
    const double lobe = c > 0.0 ? std::pow(c, n) : 0.0;
    return pd * cos_i / kPi + (1.0 - pd) * (n + 1.0) / (2.0 * kPi) * lobe;
}

// Float error of cos(alpha) = dot(mirror_direction(n, wo), wi) in brdf.h: a reflection, a
// normalize and a dot of unit vectors, measured below at < 1e-6; cos^n then carries a relative
// error of n 1e-6 / cos(alpha), and the whole term an absolute one of
// ks (n + 2) / (2 pi) n 1e-6 (cos^(n-1) <= 1).
constexpr double kCosError = 1e-6;

double phong_tolerance(double kd, double ks, double n, double f) {
    return 1e-6 * f + kd * 1e-7 + ks * (n + 2.0) / (2.0 * kPi) * n * kCosError;
}

const float kExponents[] = {0.0f, 1.0f, 3.5f, 10.0f, 100.0f, 1000.0f, 10000.0f};

} // namespace

TEST_CASE("cos(alpha) of the Phong lobe is computed to within 1e-6", "[phong]") {
    Rng rng;
    double worst = 0.0;
    for (int i = 0; i < 100000; ++i) {
        const tp::vec3 n = rng.unit(), wo = rng.above(n), wi = rng.above(n);
        const float c = glm::dot(tp::mirror_direction(n, wo), wi);
        const glm::dvec3 dn(n), dwo(wo);
        const double exact = glm::dot(2.0 * glm::dot(dn, dwo) * dn - dwo, glm::dvec3(wi)) /
                             glm::length(2.0 * glm::dot(dn, dwo) * dn - dwo);
        worst = std::max(worst, std::abs(double(c) - exact));
    }
    CHECK(worst < kCosError);
}

TEST_CASE("phong_eval matches thesis eq. 2.28 and phong_pdf the mixture pdf", "[phong]") {
    Rng rng;
    for (float n : kExponents)
        for (int i = 0; i < 3000; ++i) {
            const float kd = rng.uniform() * 0.5f, ks = rng.uniform() * 0.5f;
            const tp::vec3 nn = rng.unit(), wo = rng.above(nn), wi = rng.above(nn);
            // Bias half the directions into the lobe, where cos^n is not negligible.
            const tp::vec3 wl = i % 2 ? wi
                                      : glm::normalize(tp::mirror_direction(nn, wo) +
                                                       0.3f / std::sqrt(n + 1.0f) * rng.unit());
            if (glm::dot(wl, nn) <= 0.0f) continue;
            const double f = phong_reference(kd, ks, n, nn, wo, wl);
            const double p = pdf_reference(kd, ks, n, nn, wo, wl);
            CAPTURE(n, kd, ks, f, p);
            CHECK(std::abs(double(tp::phong_eval(tp::vec3(kd), tp::vec3(ks), n, nn, wo, wl).x) -
                           f) <= phong_tolerance(kd, ks, n, f));
            const double pd = double(kd) / double(kd + ks);
            CHECK(std::abs(double(tp::phong_pdf(tp::vec3(kd), tp::vec3(ks), n, nn, wo, wl)) - p) <=
                  phong_tolerance(pd, (1.0 - pd) * (double(n) + 1.0) / (double(n) + 2.0), n, p));
        }
}

TEST_CASE("Phong is reciprocal in wo and wi", "[phong]") {
    // Exactly so in the equations: cos(alpha) = 2 (n.wo)(n.wi) - wo.wi is symmetric; in float
    // the two evaluations differ by the rounding of cos(alpha) (twice kCosError).
    Rng rng;
    for (float n : kExponents)
        for (int i = 0; i < 3000; ++i) {
            const tp::vec3 kd(rng.uniform() * 0.5f), ks(rng.uniform() * 0.5f);
            const tp::vec3 nn = rng.unit(), a = rng.above(nn);
            const tp::vec3 b = i % 2 ? rng.above(nn)
                                     : glm::normalize(tp::mirror_direction(nn, a) +
                                                      0.3f / std::sqrt(n + 1.0f) * rng.unit());
            if (glm::dot(b, nn) <= 0.0f) continue;
            const double fab = double(tp::phong_eval(kd, ks, n, nn, a, b).x);
            const double fba = double(tp::phong_eval(kd, ks, n, nn, b, a).x);
            CAPTURE(n, fab, fba);
            CHECK(std::abs(fab - fba) <= 2.0 * phong_tolerance(kd.x, ks.x, n, fab));
        }
}

TEST_CASE("phong_power clamps at 0 for every exponent and avoids GLSL's undefined 0 to the 0",
          "[phong]") {
    // n = 0 too is confined to the lobe's hemisphere, where sample_phong_lobe draws.
    CHECK(tp::phong_power(0.5f, 0.0f) == 1.0f);
    CHECK(tp::phong_power(0.0f, 0.0f) == 0.0f);
    CHECK(tp::phong_power(-0.5f, 0.0f) == 0.0f);
    CHECK(tp::phong_power(0.0f, 10.0f) == 0.0f);
    CHECK(tp::phong_power(-0.5f, 10.0f) == 0.0f);
    CHECK(tp::phong_power(1.0f, 1e4f) == 1.0f);
    CHECK(tp::phong_power(0.5f, 3.0f) == Approx(0.125f).epsilon(1e-6));
}

TEST_CASE("phong_sample agrees with phong_eval and phong_pdf", "[phong]") {
    // For every returned sample: wi is unit and above the horizon, pdf is phong_pdf at wi,
    // weight is phong_eval cos / pdf in every channel, and the lobe flag follows u_lobe.
    Rng rng;
    for (float n : kExponents)
        for (int i = 0; i < 5000; ++i) {
            const tp::vec3 kd(rng.uniform() * 0.5f, rng.uniform() * 0.5f, rng.uniform() * 0.5f);
            const tp::vec3 ks(rng.uniform() * 0.5f, rng.uniform() * 0.5f, rng.uniform() * 0.5f);
            const tp::vec3 nn = rng.unit(), wo = rng.above(nn, 0.001f);
            const float u = rng.uniform();
            const tp::BsdfSample s =
                tp::phong_sample(kd, ks, n, nn, wo, u, tp::vec2(rng.uniform(), rng.uniform()));
            const float pd = tp::phong_diffuse_probability(kd, ks);
            CAPTURE(n, i, u, pd);
            if (s.lobe == tp::LOBE_NONE) { // only a glossy draw below the horizon fails
                CHECK(u >= pd);
                continue;
            }
            CHECK(s.lobe == (u < pd ? tp::LOBE_DIFFUSE : tp::LOBE_GLOSSY));
            CHECK(glm::length(s.wi) == Approx(1.0f).epsilon(1e-6));
            CHECK(glm::dot(s.wi, nn) > 0.0f);
            CHECK(s.pdf == tp::phong_pdf(kd, ks, n, nn, wo, s.wi));
            const tp::vec3 expected =
                tp::phong_eval(kd, ks, n, nn, wo, s.wi) * glm::dot(nn, s.wi) / s.pdf;
            for (int c = 0; c < 3; ++c)
                CHECK(s.weight[c] == Approx(expected[c]).epsilon(1e-6).margin(1e-30));
        }
    // No sample for a viewer below the surface.
    const tp::vec3 nn(0, 0, 1);
    CHECK(tp::phong_sample(tp::vec3(0.5f), tp::vec3(0.5f), 10.0f, nn, tp::vec3(0, 0.6f, -0.8f),
                           0.2f, tp::vec2(0.3f, 0.4f))
              .lobe == tp::LOBE_NONE);
    CHECK(tp::phong_eval(tp::vec3(0.5f), tp::vec3(0.5f), 10.0f, nn, tp::vec3(0, 0, 1),
                         tp::vec3(0, 0.6f, -0.8f)) == tp::vec3(0.0f));
}

TEST_CASE("perfect mirror reflects about the normal with weight ks", "[mirror]") {
    const tp::vec3 n = glm::normalize(tp::vec3(0.2f, 1.0f, -0.3f));
    const tp::vec3 wo = glm::normalize(tp::vec3(1.0f, 0.5f, 0.2f));
    const tp::BsdfSample s = tp::mirror_sample(tp::vec3(0.9f, 0.8f, 0.7f), n, wo);
    CHECK(s.lobe == tp::LOBE_SPECULAR);
    CHECK(s.weight == tp::vec3(0.9f, 0.8f, 0.7f));
    CHECK(s.pdf == 1.0f);
    CHECK(glm::length(s.wi - (2.0f * glm::dot(n, wo) * n - wo)) < 1e-6f);
    CHECK(glm::dot(s.wi, n) == Approx(glm::dot(wo, n)).epsilon(1e-6));
    CHECK(tp::mirror_sample(tp::vec3(1.0f), n, -wo).lobe == tp::LOBE_NONE);
}

TEST_CASE("Fresnel reflectance of a smooth dielectric", "[dielectric]") {
    // Against the textbook formula to 1e-6 (a dozen float operations on values <= 1; near the
    // critical angle the square root of 1 - sin^2(theta_t) magnifies its rounding, 2^-24, by
    // 1 / (2 (1 - sin^2(theta_t)))), and at
    // its landmarks: ((eta - 1)/(eta + 1))^2 at normal incidence, 0 for matched indices, the
    // p-polarised part vanishing at Brewster's angle, 1 beyond the critical angle and at
    // grazing incidence, and the same value seen from either side of the interface.
    for (double eta : {1.0 / 2.4, 1.0 / 1.5, 1.0 / 1.33, 1.0, 1.33, 1.5, 2.4})
        for (double c = 0.0; c <= 1.0; c += 0.01) {
            CAPTURE(eta, c);
            const double cos2_t = 1.0 - (1.0 - c * c) / (eta * eta);
            CHECK(std::abs(double(tp::fresnel_dielectric(float(c), float(eta))) -
                           tp::test::fresnel_reference(c, eta)) <=
                  1e-6 + 0x1p-24 / (2.0 * std::max(cos2_t, 1e-3)));
        }
    CHECK(tp::fresnel_dielectric(1.0f, 1.5f) == Approx(0.04f).epsilon(1e-6));
    CHECK(tp::fresnel_dielectric(0.6f, 1.0f) == Approx(0.0f).margin(1e-7));
    const double brewster = std::atan(1.5);
    const double cos_b = std::cos(brewster), cos_tb = std::cos(kPi / 2.0 - brewster);
    const double rs = (cos_b - 1.5 * cos_tb) / (cos_b + 1.5 * cos_tb);
    CHECK(tp::fresnel_dielectric(float(cos_b), 1.5f) == Approx(0.5 * rs * rs).epsilon(1e-5));
    CHECK(tp::fresnel_dielectric(0.5f, 1.0f / 1.5f) == 1.0f); // sin = 0.87 > 1/1.5: TIR
    CHECK(tp::fresnel_dielectric(0.0f, 1.5f) == Approx(1.0f).epsilon(1e-6));
    for (double c : {0.9, 0.6, 0.3}) {
        const double cos_t = std::sqrt(1.0 - (1.0 - c * c) / (1.5 * 1.5));
        CHECK(tp::fresnel_dielectric(float(c), 1.5f) ==
              Approx(tp::fresnel_dielectric(float(cos_t), float(1.0 / 1.5))).epsilon(1e-5));
    }
}

TEST_CASE(
    "dielectric sampling: mirror reflection and Snell refraction with their weights and sides",
    "[dielectric]") {
    const tp::vec3 n(0.0f, 0.0f, 1.0f);
    const tp::vec3 tf(0.9f, 0.8f, 1.0f);
    for (bool inside : {false, true})
        for (float cos_o : {1.0f, 0.8f, 0.5f, 0.2f}) {
            const float sin_o = std::sqrt(1.0f - cos_o * cos_o);
            const tp::vec3 wo(sin_o, 0.0f, inside ? -cos_o : cos_o);
            const tp::vec3 nw = inside ? -n : n; // the normal on wo's side
            const float ior = 1.5f, eta = inside ? 1.0f / ior : ior;
            const float F = tp::fresnel_dielectric(cos_o, eta);
            CAPTURE(inside, cos_o, F);
            // u_lobe below F reflects.
            const tp::BsdfSample r = tp::dielectric_sample(tf, ior, n, wo, 0.0f);
            CHECK(r.lobe == tp::LOBE_SPECULAR);
            CHECK(r.pdf == F);
            CHECK(r.weight == tp::vec3(1.0f));
            CHECK(glm::length(r.wi - (2.0f * cos_o * nw - wo)) < 1e-6f);
            // u_lobe at or above F refracts, unless F = 1 (total internal reflection).
            const tp::BsdfSample t = tp::dielectric_sample(tf, ior, n, wo, 0.99999994f);
            if (F >= 1.0f) {
                CHECK(t.lobe == tp::LOBE_SPECULAR);
                continue;
            }
            CHECK(t.lobe == (tp::LOBE_SPECULAR | tp::LOBE_TRANSMISSION));
            CHECK(t.pdf == Approx(1.0f - F).epsilon(1e-6));
            CHECK(glm::length(t.wi) == Approx(1.0f).epsilon(1e-6));
            CHECK(glm::dot(t.wi, nw) < 0.0f); // crosses to the other side
            // Snell: eta sin(theta_t) = sin(theta_i), in the plane of incidence.
            CHECK(eta * glm::length(glm::cross(t.wi, nw)) == Approx(sin_o).margin(1e-6));
            CHECK(glm::dot(glm::cross(wo, nw), t.wi) == Approx(0.0f).margin(1e-6));
            CHECK(t.wi.x * wo.x <= 0.0f); // the tangential part reverses: wi continues the ray
            // Radiance is compressed by 1 / eta^2 entering a denser medium.
            for (int c = 0; c < 3; ++c)
                CHECK(t.weight[c] == Approx(tf[c] / (eta * eta)).epsilon(1e-6));
        }
}
