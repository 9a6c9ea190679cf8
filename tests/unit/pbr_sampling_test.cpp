// What the chi-square tests of the glTF material (tests/chi2/pbr_chi2_test.cpp) cannot see: they
// test where pbr_sample's directions go, not what it says about them. Here, over random
// materials, frames, view directions and random numbers:
//   - every sample's pdf is pbr_pdf of the direction it returns, and its weight is
//     pbr_eval |cos| / pbr_pdf of that direction (a wrong weight leaves the directions' density
//     as it is);
//   - pbr_pdf is positive wherever pbr_eval is (else MIS and the sampler disagree on support);
//   - pbr_pdf integrates to the probability that pbr_sample returns a non-Dirac direction,
//     which is at most 1 and measured here by counting the draws that return none (rejected:
//     a reflection below the horizon, a refraction under total internal reflection) or a Dirac
//     lobe (the smooth limit);
//   - reciprocity: f(wo, wi) = f(wi, wo) for reflection and for the thin-walled transmission
//     (the surface seen from the other side), and on a volume boundary the radiance BTDF's
//     f(wo, wi) / eta_V^2 = f(wi, wo) / eta_L^2 (Walter et al. 2007, eq. 21 and its reciprocity
//     note; pbr.h's header), i.e. pbr_eval at the swapped pair with the relative index inverted
//     is eta^2 times pbr_eval at (wo, wi), eta = eta_L / eta_V.
#include "chi2/direction_at.h"
#include "support/chi2.h"
#include "support/pbr_reference.h"

#include "shared/pbr.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cmath>
#include <random>

namespace {

using glm::dvec3;
namespace ref = tp::test::pbr;

class Gen {
  public:
    explicit Gen(uint64_t seed) : rng_(seed) {}
    double uni() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_); }
    float unif() { return float(uint32_t(rng_()) >> 8) * (1.0f / 16777216.0f); }
    bool chance(double p) { return uni() < p; }
    double log_uniform(double lo, double hi) { return lo * std::pow(hi / lo, uni()); }
    dvec3 unit() {
        std::normal_distribution<double> g;
        return glm::normalize(dvec3(g(rng_), g(rng_), g(rng_)));
    }
    dvec3 color() { return dvec3(uni(), uni(), uni()); }

    // Any material the loaders can make, its edge cases mixed in: roughness 0 and around the
    // smooth limit 0.01, metallic and transmission 0, 1 or between, f0 clamped by a large
    // specular colour, volumes met from outside and from inside.
    ref::Params material() {
        ref::Params p;
        p.base_color = color();
        const double m = uni();
        p.metallic = m < 0.3 ? 0.0 : m < 0.5 ? 1.0 : uni();
        const double r = uni();
        p.roughness = r < 0.1   ? 0.0
                      : r < 0.2 ? (chance(0.5) ? 0.0099 : 0.0101)
                      : r < 0.3 ? 1.0
                                : log_uniform(0.01, 1.0);
        const double t = uni();
        p.transmission = t < 0.4 ? 0.0 : t < 0.7 ? 1.0 : uni();
        p.ior = 1.0 + 2.0 * uni();
        p.specular = chance(0.7) ? 1.0 : uni();
        p.specular_color = chance(0.7) ? dvec3(1.0) : 4.0 * color();
        p.volume = chance(0.4);
        if (p.volume && chance(0.5)) p.ior = 1.0 / p.ior;
        return p;
    }

  private:
    std::mt19937_64 rng_;
};

// A view direction on n's side down to 1e-3 of the horizon.
dvec3 view_direction(Gen& g, const dvec3& n) {
    const dvec3 v = g.unit();
    const dvec3 t = glm::normalize(v - glm::dot(v, n) * n);
    const double c = g.chance(0.2) ? g.log_uniform(1e-3, 0.1) : g.uni();
    return c * n + std::sqrt(1.0 - c * c) * t;
}

// A direction where the material has something: near the mirror direction, near the
// transmission lobe, or anywhere.
dvec3 probe_direction(Gen& g, const ref::Params& p, const dvec3& n, const dvec3& wo) {
    const double k = g.uni();
    const dvec3 mirror = 2.0 * glm::dot(n, wo) * n - wo;
    const dvec3 through = -wo; // the thin-walled transmission's centre
    if (k < 0.35)
        return glm::normalize(mirror +
                              g.log_uniform(1e-4, 1.0) * p.roughness * p.roughness * g.unit() +
                              1e-3 * g.unit());
    if (k < 0.6) return glm::normalize(through + g.log_uniform(1e-3, 1.0) * g.unit());
    return g.unit();
}

// How far g(wo, wi) moves when one coordinate of wo or wi moves by d: the sum over the six
// coordinates of the larger change of the two signs, per channel. This is the function's
// condition where it is evaluated, from the peak of D (alpha = roughness^2 wide) and a half
// vector normalized from a short sum (both directions grazing the surface) to the edge of total
// internal reflection, where Schlick's cosine on the dense side is the square root of a
// difference.
template <class G>
dvec3 sensitivity(const G& g, const tp::vec3& wo, const tp::vec3& wi, float d) {
    const dvec3 base = g(wo, wi);
    dvec3 sum(0.0);
    for (int which = 0; which < 2; ++which)
        for (int c = 0; c < 3; ++c) {
            dvec3 worst(0.0);
            for (const float sign : {-1.0f, 1.0f}) {
                tp::vec3 v[2] = {wo, wi};
                v[which][c] += sign * d;
                worst = glm::max(worst, glm::abs(g(v[0], v[1]) - base));
            }
            sum += worst;
        }
    return sum;
}

// How far two evaluations of the same pair of directions may see them apart: d = 16u (u =
// 2^-24), as frame_to_world and pbr_to_local each take sums of three products in a basis
// orthonormal to a few u, and a normalization.
constexpr float kRoundTrip = 16.0f * 0x1p-24f;

} // namespace

TEST_CASE("pbr_sample's pdf and weight are pbr_pdf and pbr_eval |cos| / pbr_pdf of its direction",
          "[pbr]") {
    // The sample's pdf and weight come from the local frame; pbr_pdf and pbr_eval recompute them
    // from the world-space direction; the two evaluations see directions up to kRoundTrip from
    // the same exact ones each, 2 kRoundTrip apart. So each is compared within its own
    // sensitivity to a move of 2 kRoundTrip, plus a relative 1e-5 (the pdf) or 1e-4 (the weight,
    // a quotient of two such chains) for the float rounding of the rest. Where that move turns
    // the half vector by more than D's width alpha (H = normalize(wo + wi) from a
    // sum of length s: 2 kRoundTrip / s > alpha, both directions grazing a lobe 1e-4 wide),
    // D's value at "the same" direction is not defined to float precision: the pdf is not
    // compared there (those samples are counted); the weight, in which D cancels, is. The weight is
    // compared to f |cos| / pdf taken as one function of the direction (in which D cancels).
    Gen g(4242);
    uint64_t samples = 0, checked = 0, none = 0, dirac = 0, pdf_bad = 0, weight_bad = 0;
    uint64_t ill_conditioned = 0;
    double worst_pdf = 0.0, worst_weight = 0.0;
    std::string first, first_pdf;
    for (int mi = 0; mi < 2000; ++mi) {
        const ref::Params p = g.material();
        const tp::Material m = ref::to_material(p);
        const dvec3 n = g.unit();
        const tp::vec3 nf(n);
        const auto pdf_at = [&](const tp::vec3& a, const tp::vec3& b) {
            return dvec3(double(tp::pbr_pdf(m, nf, a, b)));
        };
        const auto weight_at = [&](const tp::vec3& a, const tp::vec3& b) {
            const double pdf = double(tp::pbr_pdf(m, nf, a, b));
            if (!(pdf > 0.0)) return dvec3(0.0);
            return dvec3(tp::pbr_eval(m, nf, a, b)) * (std::abs(glm::dot(n, dvec3(b))) / pdf);
        };
        for (int k = 0; k < 100; ++k) {
            const tp::vec3 wo(view_direction(g, n));
            const float ul = g.unif(), u0 = g.unif(), u1 = g.unif();
            const tp::BsdfSample s = tp::pbr_sample(m, nf, wo, ul, tp::vec2(u0, u1));
            ++samples;
            if (s.lobe == tp::LOBE_NONE) {
                ++none;
                continue;
            }
            for (int c = 0; c < 3; ++c) REQUIRE(std::isfinite(s.weight[c]));
            REQUIRE(std::isfinite(s.pdf));
            if ((s.lobe & tp::LOBE_SPECULAR) != 0u) {
                ++dirac;
                continue;
            }
            ++checked;
            const dvec3 wod(wo), wid(s.wi);
            const double cos_i = glm::dot(n, wid);
            const double s_len = cos_i > 0.0 ? glm::length(wod + wid)
                                 : !p.volume ? glm::length(wod + wid - 2.0 * cos_i * n)
                                             : glm::length(wod + p.ior * wid);
            const double alpha = p.roughness * p.roughness;
            const bool ill =
                p.roughness >= ref::kSmoothRoughness && 2.0 * double(kRoundTrip) / s_len > alpha;
            ill_conditioned += ill;
            const double pdf = pdf_at(wo, s.wi).x;
            const double pdf_tol = sensitivity(pdf_at, wo, s.wi, 2.0f * kRoundTrip).x + 1e-5 * pdf;
            const double e_pdf = std::abs(double(s.pdf) - pdf);
            if (!ill) worst_pdf = std::max(worst_pdf, e_pdf / pdf_tol);
            if (!ill && !(e_pdf <= pdf_tol) && pdf_bad++ == 0)
                first_pdf = fmt::format("pdf {} vs pbr_pdf {} (tolerance {}; roughness {}, lobe "
                                        "{}, metallic {}, transmission {}, volume {}, ior {}, "
                                        "cos_o {})",
                                        s.pdf, pdf, pdf_tol, p.roughness, s.lobe, p.metallic,
                                        p.transmission, p.volume, p.ior, glm::dot(n, dvec3(wo)));
            const dvec3 expected = weight_at(wo, s.wi);
            const dvec3 w_tol =
                sensitivity(weight_at, wo, s.wi, 2.0f * kRoundTrip) + 1e-4 * expected;
            for (int c = 0; c < 3; ++c) {
                const double e = std::abs(double(s.weight[c]) - expected[c]);
                worst_weight = std::max(worst_weight, e / std::max(w_tol[c], 1e-30));
                if (!(e <= w_tol[c]) && weight_bad++ == 0)
                    first = fmt::format("weight {} vs f cos / pdf {} (tolerance {}; roughness {}, "
                                        "lobe {}, metallic {}, transmission {}, volume {}, ior {})",
                                        s.weight[c], expected[c], w_tol[c], p.roughness, s.lobe,
                                        p.metallic, p.transmission, p.volume, p.ior);
            }
        }
    }
    std::printf("pbr samples: %llu, %llu checked (%llu pdfs ill-conditioned), %llu none, %llu "
                "Dirac; worst pdf error / tolerance %.3f, worst weight error / tolerance %.3f\n",
                (unsigned long long)samples, (unsigned long long)checked,
                (unsigned long long)ill_conditioned, (unsigned long long)none,
                (unsigned long long)dirac, worst_pdf, worst_weight);
    INFO("first pdf disagreement: " << first_pdf);
    INFO("first weight disagreement: " << first);
    CHECK(checked > samples / 2);
    CHECK(ill_conditioned < checked / 30); // grazing views of roughness 0.0101: 1.7 %
    CHECK(pdf_bad == 0);
    CHECK(weight_bad == 0);
}

TEST_CASE("pbr_pdf is positive wherever pbr_eval is", "[pbr]") {
    Gen g(777);
    uint64_t positive = 0, uncovered = 0;
    std::string first;
    for (int mi = 0; mi < 2000; ++mi) {
        const ref::Params p = g.material();
        const tp::Material m = ref::to_material(p);
        const dvec3 n = g.unit();
        for (int k = 0; k < 100; ++k) {
            const dvec3 wo = view_direction(g, n);
            const dvec3 wi = probe_direction(g, p, n, wo);
            const tp::vec3 f = tp::pbr_eval(m, tp::vec3(n), tp::vec3(wo), tp::vec3(wi));
            if (!(tp::max3(f) > 0.0f)) continue;
            ++positive;
            const float pdf = tp::pbr_pdf(m, tp::vec3(n), tp::vec3(wo), tp::vec3(wi));
            if (!(pdf > 0.0f) && uncovered++ == 0)
                first = fmt::format("f = ({}, {}, {}) with pdf {}: roughness {}, metallic {}, "
                                    "transmission {}, volume {}, ior {}, cos_o {}, cos_i {}",
                                    f.x, f.y, f.z, pdf, p.roughness, p.metallic, p.transmission,
                                    p.volume, p.ior, glm::dot(n, wo), glm::dot(n, wi));
        }
    }
    std::printf("pbr support: %llu directions with f > 0, %llu with pdf = 0\n",
                (unsigned long long)positive, (unsigned long long)uncovered);
    INFO(first);
    CHECK(positive > 50000);
    CHECK(uncovered == 0);
}

TEST_CASE("pbr_pdf integrates to the measured probability of a non-Dirac sample", "[pbr]") {
    // The integral by the albedo test's quadrature (pbr_reference.h), its error estimate e
    // checked below 5e-5 (the narrowest lobe cut by the horizon, roughness 0.02 at 85 degrees,
    // ends at 2.9e-5); the probability P from 2^18 draws, whose binomial standard error SE is at
    // most 1e-3: |integral - P| <= 4 SE + e, and integral <= 1 + e.
    struct Case {
        const char* name;
        ref::Params p;
    };
    std::vector<Case> cases;
    const auto add = [&](const char* name, double metallic, double roughness, double transmission,
                         bool volume, double ior) {
        ref::Params p;
        p.base_color = dvec3(0.7, 0.5, 0.3);
        p.metallic = metallic;
        p.roughness = roughness;
        p.transmission = transmission;
        p.volume = volume;
        p.ior = ior;
        cases.push_back({name, p});
    };
    add("metal, roughness 0.02", 1.0, 0.02, 0.0, false, 1.5);
    add("metal, roughness 0.5", 1.0, 0.5, 0.0, false, 1.5);
    add("plastic, roughness 0.1", 0.0, 0.1, 0.0, false, 1.5);
    add("plastic, roughness 1", 0.0, 1.0, 0.0, false, 1.5);
    add("half metallic, roughness 0.3", 0.5, 0.3, 0.0, false, 1.5);
    add("smooth plastic (Dirac and diffuse)", 0.0, 0.0, 0.0, false, 1.5);
    add("thin transmission, roughness 0.2", 0.0, 0.2, 1.0, false, 1.5);
    add("thin transmission 0.5, roughness 0.7", 0.0, 0.7, 0.5, false, 1.5);
    add("volume from outside, roughness 0.3", 0.0, 0.3, 1.0, true, 1.5);
    add("volume from inside, roughness 0.3", 0.0, 0.3, 1.0, true, 1.0 / 1.5);
    add("volume from inside, roughness 0.05", 0.0, 0.05, 1.0, true, 1.0 / 1.33);
    const uint64_t n = uint64_t(1) << 18;
    uint64_t seed = 31000;
    for (const Case& c : cases) {
        const tp::Material m = ref::to_material(c.p);
        for (const double theta : {0.0, 60.0, 85.0}) {
            const dvec3 V(std::sin(glm::radians(theta)), 0.0, std::cos(glm::radians(theta)));
            const ref::QuadratureResult mass = ref::integrate_lobes(
                [&](const dvec3& L) {
                    return dvec3(double(
                        tp::pbr_pdf(m, tp::vec3(0.0f, 0.0f, 1.0f), tp::vec3(V), tp::vec3(L))));
                },
                ref::reflect_axis(V), ref::transmit_axis(c.p, V), ref::lobe_width(c.p), 1e-7);
            const glm::dvec3 normal = glm::normalize(glm::dvec3(-0.2, 0.6, 0.77));
            const tp::vec3 wo = tp::test::chi2::direction_at(normal, theta);
            tp::test::chi2::Uniform u(seed++);
            uint64_t none = 0, dirac = 0;
            for (uint64_t i = 0; i < n; ++i) {
                const float a = u.next(), b = u.next(), d = u.next();
                const tp::BsdfSample s = tp::pbr_sample(m, tp::vec3(normal), wo, a, tp::vec2(b, d));
                none += s.lobe == tp::LOBE_NONE;
                dirac += s.lobe != tp::LOBE_NONE && (s.lobe & tp::LOBE_SPECULAR) != 0u;
            }
            const double P = double(n - none - dirac) / double(n);
            const double se = std::sqrt(std::max(P * (1.0 - P), 1.0 / double(n)) / double(n));
            std::printf("pdf mass %-40s %2.0f deg: integral %.6f (error < %.1e), measured %.6f "
                        "+- %.6f (%.2f SE), rejected %.4f, Dirac %.4f\n",
                        c.name, theta, mass.value.x, mass.error, P, se, (mass.value.x - P) / se,
                        double(none) / double(n), double(dirac) / double(n));
            CAPTURE(c.name, theta, mass.value.x, mass.error, P, se);
            CHECK(mass.error <= 5e-5);
            CHECK(mass.value.x <= 1.0 + mass.error);
            CHECK(std::abs(mass.value.x - P) <= 4.0 * se + mass.error);
        }
    }
}

TEST_CASE("pbr_eval is reciprocal, and on a volume boundary f(wi, wo) = eta^2 f(wo, wi)", "[pbr]") {
    // Swapping the directions changes the frame (the thin-walled and volume cases turn the
    // normal to the new wo), so the two evaluations see local directions up to kRoundTrip apart:
    // the tolerance is both evaluations' sensitivity to such a move, plus 1e-5 of the value.
    // Roughness from 0.02 up (the smooth limit evaluates no microfacet lobe).
    Gen g(5150);
    uint64_t compared[3] = {0, 0, 0}, bad = 0;
    double worst = 0.0;
    std::string first;
    for (int mi = 0; mi < 3000; ++mi) {
        ref::Params p = g.material();
        p.roughness = g.log_uniform(0.02, 1.0);
        const tp::Material m = ref::to_material(p);
        const tp::Material inverted = tp::pbr_material_at_side(m, true); // 1 / ior on a volume
        const dvec3 n = g.unit();
        const tp::vec3 nf(n);
        for (int k = 0; k < 30; ++k) {
            const dvec3 wo = view_direction(g, n);
            const dvec3 wi = probe_direction(g, p, n, wo);
            const double side = glm::dot(n, wi);
            if (std::abs(side) < 1e-3) continue;
            const int kind = side > 0.0 ? 0 : !p.volume ? 1 : 2;
            // The reverse pair sees the surface from wi's side: the normal turned there, and a
            // volume's relative index inverted.
            const tp::Material& mb = kind == 2 ? inverted : m;
            const tp::vec3 nb = kind == 0 ? nf : -nf;
            const auto forward = [&](const tp::vec3& a, const tp::vec3& b) {
                return dvec3(tp::pbr_eval(m, nf, a, b));
            };
            const auto backward = [&](const tp::vec3& a, const tp::vec3& b) {
                return dvec3(tp::pbr_eval(mb, nb, a, b));
            };
            const double scale = kind == 2 ? double(m.ior) * double(m.ior) : 1.0;
            const tp::vec3 wof(wo), wif(wi);
            const dvec3 f = forward(wof, wif), back = backward(wif, wof);
            if (!(std::max({f.x, f.y, f.z}) > 0.0) && !(std::max({back.x, back.y, back.z}) > 0.0))
                continue;
            ++compared[kind];
            const dvec3 tol = scale * sensitivity(forward, wof, wif, kRoundTrip) +
                              sensitivity(backward, wif, wof, kRoundTrip) + 1e-5 * scale * f;
            for (int c = 0; c < 3; ++c) {
                const double expect = scale * f[c];
                const double e = std::abs(back[c] - expect);
                worst = std::max(worst, e / std::max(tol[c], 1e-30));
                if (!(e <= tol[c]) && bad++ == 0)
                    first = fmt::format("{}: f(wo, wi) = {}, swapped {} (expected {}, tolerance "
                                        "{}): roughness {}, ior {}, cos_o {}, cos_i {}",
                                        kind == 0   ? "reflection"
                                        : kind == 1 ? "thin transmission"
                                                    : "volume",
                                        f[c], back[c], expect, tol[c], p.roughness, p.ior,
                                        glm::dot(n, wo), side);
            }
        }
    }
    std::printf("pbr reciprocity: %llu reflection, %llu thin-walled, %llu volume pairs; worst "
                "relative error / tolerance %.3f\n",
                (unsigned long long)compared[0], (unsigned long long)compared[1],
                (unsigned long long)compared[2], worst);
    INFO(first);
    CHECK(compared[0] > 10000);
    CHECK(compared[1] > 1000);
    CHECK(compared[2] > 1000);
    CHECK(bad == 0);
}
