// The chi-square tests have power: the same harness, grids and sample counts as the acceptance
// tests, run on sampler/pdf pairs that are wrong in the ways such code goes wrong, must reject
// at the suite's per-test level. A test that accepted these would pass a broken sampler.
#include "chi2/lights.h"
#include "chi2/suite.h"

#include "scene/alias_table.h"
#include "shared/brdf.h"
#include "shared/rng.h"

#include <cmath>
#include <numeric>

using namespace tp::test::chi2;
using namespace tp::test::lights;

namespace {
const glm::dvec3 kZ(0.0, 0.0, 1.0);
}

TEST_CASE("power: Phong lobe with the wrong exponent is rejected", "[chi2][power]") {
    // Off by one at n = 10 (the lobe is 9 % narrower), and 10 % off at n = 10^4, where only a
    // chart that resolves the 0.01 rad lobe can tell.
    const struct { float sampled, pdf; } cases[] = {{11.0f, 10.0f}, {11000.0f, 10000.0f}};
    for (const auto& c : cases) {
        DYNAMIC_SECTION("sampled " << c.sampled << " tested against " << c.pdf) {
            const SphereChart chart = SphereChart::lobe(kZ, 0.05 / (double(c.pdf) + 1.0), 48, 64);
            const DirectionSamples s = draw_directions(
                [&](const glm::vec4& u) {
                    return tp::sample_phong_lobe(tp::vec2(u.x, u.y), c.sampled);
                },
                kSamples, 901);
            check_rejected("wrong Phong exponent",
                           test_directions(chart, s, [&](const glm::dvec3& w) {
                               return tp::phong_lobe_pdf(float(w.z), c.pdf);
                           }));
        }
    }
}

TEST_CASE("power: cosine samples against the uniform hemisphere pdf are rejected",
          "[chi2][power]") {
    const DirectionSamples s = draw_directions(
        [](const glm::vec4& u) { return tp::sample_cosine_hemisphere(tp::vec2(u.x, u.y)); },
        kSamples, 902);
    check_rejected("cosine vs uniform hemisphere",
                   test_directions(SphereChart::uniform(kZ, 64, 64), s, [](const glm::dvec3& w) {
                       return w.z > 0.0 ? 0.5 * double(tp::INV_PI) : 0.0;
                   }));
}

TEST_CASE("power: uniform-in-theta sphere samples are rejected", "[chi2][power]") {
    // The classic mistake: theta uniform in [0, pi] crowds the poles.
    const DirectionSamples s = draw_directions(
        [](const glm::vec4& u) {
            const float z = std::cos(tp::PI * u.x), r = std::sqrt(std::max(0.0f, 1.0f - z * z));
            return glm::vec3(r * std::cos(tp::TWO_PI * u.y), r * std::sin(tp::TWO_PI * u.y), z);
        },
        kSamples, 903);
    check_rejected(
        "uniform theta vs uniform sphere",
        test_directions(SphereChart::uniform(glm::normalize(glm::dvec3(1, 2, 3)), 48, 96), s,
                        [](const glm::dvec3&) { return double(tp::INV_FOUR_PI); }));
}

TEST_CASE("power: triangle sampling without the square root is rejected", "[chi2][power]") {
    // b1 = u1, b2 = u2 (1 - u1): inside the triangle, but crowded towards the vertex b1 = 1.
    const PointSamples s = draw_points(
        [](const glm::vec4& u) { return glm::vec2(u.x, u.y * (1.0f - u.x)); }, kSamples, 904);
    check_rejected("triangle without sqrt",
                   test_points(Grid::uniform(0.0, 1.0, 64, 0.0, 1.0, 64), s,
                               [](double x, double y) { return x + y <= 1.0 ? 2.0 : 0.0; }));
}

TEST_CASE("power: correlated random dimensions are rejected", "[chi2][power]") {
    // The same dimension twice instead of two: the pairs lie on the diagonal.
    PointSamples s;
    for (uint32_t pixel = 0; pixel < 1000; ++pixel)
        for (uint32_t sample = 0; sample < 1000; ++sample) {
            const float a = tp::rng_bounce2(tp::rng_key(tp::SAMPLER_RANDOM, 7u, pixel, sample), 3u,
                                            tp::RNG_DIR_U)
                                .x;
            s.points.emplace_back(a, a);
        }
    check_rejected("correlated rng dimensions",
                   test_points(Grid::uniform(0.0, 1.0, 64, 0.0, 1.0, 64), s,
                               [](double, double) { return 1.0; }));
}

TEST_CASE("power: Phong mixture with the wrong lobe probability is rejected", "[chi2][power]") {
    // Directions drawn with P_d = 0.5 (kd = ks = 0.45) tested against the pdf of kd = 0.2,
    // ks = 0.7 (P_d = 2/9): the balance between the lobes is wrong, each lobe is right.
    const tp::vec3 n(0.0f, 0.0f, 1.0f);
    const tp::vec3 wo = glm::normalize(tp::vec3(0.5f, 0.0f, 0.866f));
    const float ns = 30.0f;
    const DirectionSamples s = draw_directions(
        [&](const glm::vec4& u) -> std::optional<glm::vec3> {
            const tp::BsdfSample b = tp::phong_sample(tp::vec3(0.45f), tp::vec3(0.45f), ns, n, wo,
                                                      u.x, tp::vec2(u.y, u.z));
            if (b.lobe == tp::LOBE_NONE) return std::nullopt;
            return b.wi;
        },
        kSamples, 905);
    const glm::dvec3 mirror(-0.5, 0.0, 0.866);
    check_rejected("Phong mixture, wrong P_d",
                   test_directions(
                       SphereChart::lobe(glm::normalize(mirror), 0.05 / (double(ns) + 1.0), 48, 64),
                       s, [&](const glm::dvec3& w) {
                           return tp::phong_pdf(tp::vec3(0.2f), tp::vec3(0.7f), ns, n, wo,
                                                tp::vec3(w));
                       }));
}

TEST_CASE("power: Schlick's approximation is told apart from Fresnel", "[chi2][power]") {
    // At cos = 0.3, eta = 1.5: Fresnel 0.2079, Schlick 0.2013, 16 standard deviations apart
    // at 10^6 draws.
    const double cos_i = 0.3, eta = 1.5;
    const double f0 = (eta - 1.0) * (eta - 1.0) / ((eta + 1.0) * (eta + 1.0));
    const double schlick = f0 + (1.0 - f0) * std::pow(1.0 - cos_i, 5.0);
    const double fresnel = double(tp::fresnel_dielectric(float(cos_i), float(eta)));
    Uniform u(906);
    uint64_t reflected = 0;
    for (uint64_t i = 0; i < kSamples; ++i) reflected += double(u.next()) < schlick ? 1 : 0;
    const double p = binomial_p_value(reflected, kSamples, fresnel);
    INFO("Schlick " << schlick << ", Fresnel " << fresnel << ", p = " << p);
    CHECK(p < alpha_per_test());
}

TEST_CASE("power: an alias table 5 % off on one weight is rejected", "[chi2][power]") {
    const std::vector<double> w = {1.0, 0.0, 3.0, 0.5, 10.0, 2.0, 7.0, 0.01, 4.0, 0.0};
    std::vector<double> built = w;
    built[2] *= 1.05;
    const std::vector<tp::AliasEntry> table = tp::build_alias_table(built);
    Uniform u(907);
    std::vector<uint64_t> counts(w.size(), 0);
    for (uint64_t i = 0; i < kSamples; ++i) {
        const uint32_t slot = tp::alias_slot_from_bits(u.bits(), uint32_t(w.size()));
        ++counts[tp::alias_resolve(slot, table[slot].prob, table[slot].alias, u.next())];
    }
    const double sum = std::accumulate(w.begin(), w.end(), 0.0);
    std::vector<double> probs;
    for (double x : w) probs.push_back(x / sum);
    check_rejected("alias table, perturbed weight", test_discrete(counts, probs));
}

TEST_CASE("power: triangle light pdf without the cosine is rejected", "[chi2][power]") {
    // p = d^2 / A instead of d^2 / (A cos): the area-to-solid-angle Jacobian half done.
    const tp::Light l = test_triangle_light();
    const tp::vec3 p = test_shading_point();
    const DirectionSamples s = draw_directions(
        [&](const glm::vec4& u) -> std::optional<glm::vec3> {
            const tp::LightSample ls = tp::sample_triangle_light(l, p, tp::vec2(u.x, u.y), false);
            if (ls.pdf <= 0.0f) return std::nullopt;
            return ls.wi;
        },
        kSamples, 908);
    check_rejected("triangle light without cosine",
                   test_directions(SphereChart::lobe(to_centroid(l, p), 0.01, 48, 64), s,
                                   [&](const glm::dvec3& w) {
                                       const auto h = hit_triangle(l, p, w);
                                       return h ? h->t * h->t / double(l.area) : 0.0;
                                   }));
}

TEST_CASE("power: environment pdf without the sin(theta) Jacobian is rejected", "[chi2][power]") {
    const EnvMap env = test_environment_map();
    const DirectionSamples s = draw_directions(
        [&](const glm::vec4& u) -> std::optional<glm::vec3> {
            const tp::LightSample ls = sample_environment(env, u);
            if (ls.pdf <= 0.0f) return std::nullopt;
            return ls.wi;
        },
        kSamples, 909);
    check_rejected("environment without Jacobian",
                   test_directions(environment_chart(env), s, [&](const glm::dvec3& w) {
                       const tp::vec2 st = tp::environment_map_coords(tp::vec3(w), env.rotation);
                       const uint32_t px = tp::environment_map_pixel(st, env.width, env.height);
                       return double(env.table[px].pdf) * env.width * env.height /
                              (2.0 * double(tp::PI) * double(tp::PI));
                   }));
}
