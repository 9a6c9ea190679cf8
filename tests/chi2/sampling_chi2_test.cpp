// Chi-square goodness-of-fit of the sampling routines of shared/sampling.h against their pdfs,
// and of the counter-based random numbers of shared/rng.h against the uniform distribution.
#include "chi2/suite.h"

#include "shared/rng.h"
#include "shared/sampling.h"

#include <fmt/format.h>

using namespace tp::test::chi2;

namespace {

const glm::dvec3 kZ(0.0, 0.0, 1.0);

} // namespace

TEST_CASE("cosine-weighted hemisphere follows cos(theta)/pi", "[chi2]") {
    // Rows uniform in cos(theta): the lower half of the sphere expects nothing, so a sample
    // there rejects outright.
    const SphereChart chart = SphereChart::uniform(kZ, 64, 64);
    const DirectionSamples s = draw_directions(
        [](const glm::vec4& u) { return tp::sample_cosine_hemisphere(tp::vec2(u.x, u.y)); },
        kSamples, 101);
    const Result r = test_directions(
        chart, s, [](const glm::dvec3& w) { return tp::cosine_hemisphere_pdf(float(w.z)); });
    check_accepted("cosine hemisphere", r);
    CHECK(r.mass == Approx(1.0).epsilon(1e-6));
}

TEST_CASE("Phong lobe sampling follows (n+1)/(2 pi) cos^n", "[chi2]") {
    // Exponents from 1 to 10^4 (the range of cornell_glossy), and n = 0 (a uniform hemisphere: MTL
    // files often say Ns 0). The chart's rows start at 1 - cos = 0.05 / (n + 1), a twentieth of the
    // lobe's width, so that even at n = 10^4 some 20 rows lie inside the lobe.
    for (const float n : {0.0f, 1.0f, 10.0f, 100.0f, 1000.0f, 10000.0f}) {
        DYNAMIC_SECTION("n = " << n) {
            const SphereChart chart = SphereChart::lobe(kZ, 0.05 / (double(n) + 1.0), 48, 64);
            const DirectionSamples s = draw_directions(
                [n](const glm::vec4& u) { return tp::sample_phong_lobe(tp::vec2(u.x, u.y), n); },
                kSamples, 200 + uint64_t(n));
            const Result r = test_directions(
                chart, s, [n](const glm::dvec3& w) { return tp::phong_lobe_pdf(float(w.z), n); });
            check_accepted(fmt::format("Phong lobe n = {}", n).c_str(), r);
            // The float pdf sees cos(alpha) rounded to 2^-25, a relative error of up to
            // n 2^-25 in cos^n (pdf_normalization_test.cpp); the cubature adds < 1e-6.
            CHECK(r.mass == Approx(1.0).epsilon(double(n) * 0x1p-25 + 1e-6));
        }
    }
}

TEST_CASE("uniform sphere sampling follows 1/(4 pi)", "[chi2]") {
    // A tilted chart, so the rows do not line up with the sampler's z = 1 - 2 u strata.
    const SphereChart chart = SphereChart::uniform(glm::normalize(glm::dvec3(1, 2, 3)), 48, 96);
    const DirectionSamples s = draw_directions(
        [](const glm::vec4& u) { return tp::sample_uniform_sphere(tp::vec2(u.x, u.y)); }, kSamples,
        301);
    const Result r =
        test_directions(chart, s, [](const glm::dvec3&) { return double(tp::INV_FOUR_PI); });
    check_accepted("uniform sphere", r);
}

TEST_CASE("uniform triangle sampling is uniform by area", "[chi2]") {
    // The barycentrics (b1, b2) of a uniform point fill the half square b1 + b2 <= 1 with
    // density 2; any triangle is an affine image of it, which keeps uniformity.
    const Grid grid = Grid::uniform(0.0, 1.0, 64, 0.0, 1.0, 64);
    const PointSamples s = draw_points(
        [](const glm::vec4& u) { return tp::sample_uniform_triangle(tp::vec2(u.x, u.y)); },
        kSamples, 401);
    const Result r =
        test_points(grid, s, [](double x, double y) { return x + y <= 1.0 ? 2.0 : 0.0; });
    check_accepted("uniform triangle", r);
}

TEST_CASE("rng.h numbers of two dimensions are jointly uniform", "[chi2]") {
    // The two direction numbers of bounce 3 over consecutive samples of a few pixels: the
    // pairs a sampler consumes must fill the unit square evenly.
    PointSamples s;
    for (uint32_t pixel = 0; pixel < 1000; ++pixel)
        for (uint32_t sample = 0; sample < 1000; ++sample) {
            const tp::RngKey key = tp::rng_key(tp::SAMPLER_RANDOM, 7u, pixel, sample);
            const tp::vec2 u = tp::rng_bounce2(key, 3u, tp::RNG_DIR_U);
            s.points.emplace_back(u.x, u.y);
        }
    const Result r = test_points(Grid::uniform(0.0, 1.0, 64, 0.0, 1.0, 64), s,
                                 [](double, double) { return 1.0; });
    check_accepted("rng pairs", r);
}
