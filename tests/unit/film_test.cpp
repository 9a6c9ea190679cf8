// render/film.h: Welford's running mean and M2 against a two-pass computation in long double,
// the Chan-Golub-LeVeque merge of batches and of whole films against sample-by-sample
// accumulation, and the variance of the mean the EXR carries.
#include "render/film.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

struct TwoPass {
    long double mean = 0, m2 = 0;
};

TwoPass two_pass(const std::vector<double>& x) {
    TwoPass r;
    for (double v : x) r.mean += v;
    r.mean /= (long double)x.size();
    for (double v : x) r.m2 += (v - r.mean) * (v - r.mean);
    return r;
}

std::vector<double> samples(size_t n, double mean, double sd, unsigned seed) {
    std::mt19937_64 g(seed);
    std::normal_distribution<double> d(mean, sd);
    std::vector<double> x(n);
    for (double& v : x) v = d(g);
    return x;
}

constexpr double kEps = std::numeric_limits<double>::epsilon();

} // namespace

TEST_CASE("film: Welford's mean and variance match two-pass long double", "[film]") {
    // Radiance-like data and data with a large offset (mean 10^4, sd 1), where the naive
    // sum-of-squares formula loses 8 digits. Chan, Golub & LeVeque (1983) bound the relative
    // error of updated M2 by about n kappa eps with kappa = sqrt(1 + mean^2 / var) the
    // condition number; the mean's relative error is below n eps.
    for (const auto& [mean, sd] : {std::pair{1.0, 1.0}, {1e4, 1.0}, {0.0, 1e-3}}) {
        const size_t n = 100000;
        const std::vector<double> x = samples(n, mean, sd, 5);
        tp::Film film(1, 1);
        for (double v : x) film.add_sample(0, glm::dvec3(v, 2.0 * v, -v));
        const TwoPass ref = two_pass(x);
        const double kappa = std::sqrt(1.0 + mean * mean / (sd * sd));
        const double var_of_mean = double(ref.m2 / ((long double)(n - 1) * (long double)n));
        CAPTURE(mean, sd);
        CHECK(film.count(0) == n);
        CHECK(std::abs(film.mean(0).x - double(ref.mean)) <=
              double(n) * kEps * std::abs(double(ref.mean)) + 1e-300);
        CHECK(std::abs(film.variance_of_mean(0).x - var_of_mean) <=
              double(n) * kappa * kEps * var_of_mean);
        // Channels are independent: G = 2R has four times the variance, B = -R the same.
        CHECK(film.variance_of_mean(0).y ==
              Approx(4.0 * film.variance_of_mean(0).x).epsilon(1e-12));
        CHECK(film.variance_of_mean(0).z == Approx(film.variance_of_mean(0).x).epsilon(1e-12));
    }
}

TEST_CASE("film: add_batch equals repeated add_sample", "[film]") {
    // A batch arrives as (n, sum, sum of squares), as the GPU accumulates it. Its own M2 is
    // sum_sq - sum^2 / n, which cancels: its relative error is about kappa^2 eps with
    // kappa^2 = 1 + mean^2 / var (here 1 + 0.5^2 / 0.2^2 = 7.25). The pairwise merge then adds
    // n eps. Tolerance: 8 (kappa^2 + n) eps.
    const std::vector<double> x = samples(3000, 0.5, 0.2, 7);
    tp::Film one(1, 1), batched(1, 1);
    for (double v : x) one.add_sample(0, glm::dvec3(v));
    // The first 1000 one by one, then batches of 1500 and 500 merged on top.
    for (size_t i = 0; i < 1000; ++i) batched.add_sample(0, glm::dvec3(x[i]));
    for (const auto& [begin, end] :
         {std::pair{size_t(1000), size_t(2500)}, {size_t(2500), size_t(3000)}}) {
        glm::dvec3 sum(0.0), sum_sq(0.0);
        for (size_t i = begin; i < end; ++i) {
            sum += glm::dvec3(x[i]);
            sum_sq += glm::dvec3(x[i] * x[i]);
        }
        batched.add_batch(0, end - begin, sum, sum_sq);
    }
    const double kappa2 = 1.0 + 0.5 * 0.5 / (0.2 * 0.2);
    const double tol = 8.0 * (kappa2 + double(x.size())) * kEps;
    CHECK(batched.count(0) == one.count(0));
    CHECK(batched.mean(0).x == Approx(one.mean(0).x).epsilon(tol));
    CHECK(batched.variance_of_mean(0).x == Approx(one.variance_of_mean(0).x).epsilon(tol));

    SECTION("a batch into an empty pixel, and batches of 0 and 1 samples") {
        tp::Film f(2, 1);
        f.add_batch(1, 0, glm::dvec3(5.0), glm::dvec3(25.0)); // nothing
        CHECK(f.count(1) == 0);
        f.add_batch(1, 1, glm::dvec3(3.0), glm::dvec3(9.0));
        CHECK(f.count(1) == 1);
        CHECK(f.mean(1) == glm::dvec3(3.0));
        CHECK(f.variance_of_mean(1) == glm::dvec3(0.0)); // undefined below 2 samples: 0
        f.add_batch(1, 2, glm::dvec3(0.0 + 6.0), glm::dvec3(0.0 + 36.0));
        // Samples {3, 0, 6}: mean 3, unbiased variance 9, variance of the mean 3.
        CHECK(f.mean(1).x == Approx(3.0));
        CHECK(f.variance_of_mean(1).x == Approx(3.0));
        CHECK(f.count(0) == 0);
    }
}

TEST_CASE("film: merge of two films equals one film of all their samples", "[film]") {
    // --device all merges the devices' films (vulkan_rt/renderer/device_group.cpp). Two films of
    // 700 and 1300 samples with different means (0.5 and 2: the between-film term matters) against
    // the two-pass mean and M2 of all 2000 in long double. Welford's and the merge's rounding
    // grow like n eps: tolerance 8 n eps. A pixel empty in the merged-in film is unchanged.
    std::vector<double> a = samples(700, 0.5, 0.2, 11), b = samples(1300, 2.0, 0.3, 12);
    tp::Film fa(2, 1), fb(2, 1);
    for (double v : a) fa.add_sample(0, glm::dvec3(v));
    for (double v : b) fb.add_sample(0, glm::dvec3(v));
    fa.add_sample(1, glm::dvec3(4.0));
    fa.add_sample(1, glm::dvec3(6.0));
    fa.merge(fb);
    std::vector<double> all = a;
    all.insert(all.end(), b.begin(), b.end());
    const TwoPass t = two_pass(all);
    const double n = double(all.size()), tol = 8.0 * n * kEps;
    CHECK(fa.count(0) == all.size());
    CHECK(fa.mean(0).y == Approx(double(t.mean)).epsilon(tol));
    CHECK(fa.variance_of_mean(0).y == Approx(double(t.m2 / ((n - 1) * n))).epsilon(tol));
    CHECK(fa.count(1) == 2);
    CHECK(fa.mean(1).z == 5.0);
    CHECK(fa.variance_of_mean(1).z == 1.0); // {4, 6}: variance 2, of the mean 1
}

TEST_CASE("film: variance of the mean and the EXR channels", "[film]") {
    tp::Film f(2, 1);
    f.add_sample(0, glm::dvec3(0.0, 1.0, 2.0));
    f.add_sample(0, glm::dvec3(2.0, 1.0, 6.0));
    // Two samples {0, 2}: unbiased variance 2, of the mean 1.
    CHECK(f.mean(0) == glm::dvec3(1.0, 1.0, 4.0));
    CHECK(f.variance_of_mean(0) == glm::dvec3(1.0, 0.0, 4.0));
    const tp::ExrImage img = f.to_exr();
    CHECK(img.width == 2);
    CHECK(img.height == 1);
    for (const char* c : {"R", "G", "B", "variance.R", "variance.G", "variance.B"})
        CHECK(img.has(c));
    CHECK(img.channel("B")[0] == 4.0f);
    CHECK(img.channel("variance.R")[0] == 1.0f);
    CHECK(img.channel("variance.B")[0] == 4.0f);
    CHECK(img.channel("R")[1] == 0.0f); // no samples: mean 0
    CHECK(img.channel("variance.R")[1] == 0.0f);
}

TEST_CASE("film: the batch estimator is the variance of the batch means", "[film]") {
    // 8 batches of 5 samples (sample s in batch s mod 8): Var(mean) = s^2(batch means) / 8,
    // computed here in long double from the batch means; the film's random-group form reduces
    // to it at equal batch sizes, to rounding (a few eps relative).
    const uint32_t k = 8, per = 5;
    const std::vector<double> x = samples(k * per, 1.0, 0.5, 11);
    tp::Film f(1, 1, k);
    for (uint32_t s = 0; s < x.size(); ++s) f.add_sample(0, glm::dvec3(x[s]), s);
    std::vector<long double> m(k, 0.0L);
    for (uint32_t s = 0; s < x.size(); ++s) m[s % k] += x[s] / (long double)per;
    long double mean = 0.0L, ss = 0.0L;
    for (long double v : m) mean += v / k;
    for (long double v : m) ss += (v - mean) * (v - mean);
    const double expected = double(ss / (k - 1) / k);
    CHECK(f.count(0) == x.size());
    CHECK(f.variance_of_mean(0).x == Approx(expected).epsilon(64 * kEps));
    const tp::ExrImage img = f.to_exr(tp::FilmLayout::full);
    CHECK(img.strings.at("twinpath:variance_estimator") == "batches");
    CHECK(img.strings.at("twinpath:film") == "full");
    CHECK(img.integers.at("twinpath:variance_dof") == k - 1);
    // What compare borrows and merge rebuilds from (docs/sampling.md): the sample variance of
    // all 40 samples, M2 / (n - 1), and each batch's mean, both rounded once to float32.
    const TwoPass all = two_pass(x);
    const double s2 = double(all.m2 / (x.size() - 1));
    CHECK(img.channel(tp::sample_variance_channel(0))[0] == Approx(s2).epsilon(1e-7));
    for (uint32_t b = 0; b < k; ++b)
        CHECK(img.channel(tp::batch_channel(b, 2))[0] == Approx(double(m[b])).epsilon(1e-7));
    CHECK(img.channels.size() == 6 + 3 + 3 * k);
    CHECK_FALSE(tp::Film(1, 1).to_exr().has(tp::sample_variance_channel(0)));

    SECTION("the lean layout: no batch means, the sample variance to 11 significant bits") {
        // What render writes by default (render/film.h): the same mean, variance and degrees of
        // freedom, and the sample variance within half an 11-bit step, 2^-11 relative.
        const tp::ExrImage lean = f.to_exr();
        CHECK(lean.strings.at("twinpath:film") == "lean");
        CHECK(lean.channels.size() == 6 + 3);
        for (const char* c : {"R", "G", "B", "variance.R", "variance.G", "variance.B"})
            CHECK(lean.channel(c) == img.channel(c));
        CHECK(lean.integers.at("twinpath:variance_dof") == k - 1);
        CHECK(std::abs(double(lean.channel(tp::sample_variance_channel(1))[0]) - s2) <=
              std::ldexp(s2, -11) * (1 + 1e-6));
    }

    SECTION("the GPU's per-batch sums give the same film") {
        tp::Film g(1, 1, k);
        for (uint32_t b = 0; b < k; ++b) {
            glm::dvec3 sum(0.0), sum_sq(0.0);
            uint64_t n = 0;
            for (uint32_t s = b; s < x.size(); s += k, ++n) {
                sum += glm::dvec3(x[s]);
                sum_sq += glm::dvec3(x[s] * x[s]);
            }
            g.add_batch(0, n, sum, sum_sq, b);
        }
        CHECK(g.mean(0).x == Approx(f.mean(0).x).epsilon(64 * kEps));
        CHECK(g.variance_of_mean(0).x == Approx(f.variance_of_mean(0).x).epsilon(64 * kEps));
    }
    SECTION("fewer samples than batches: one sample per batch is the sample variance") {
        // 3 samples in 3 batches: K' = 3, n_b / N = 1/3, so 3/2 * sum (x_i - mean)^2 / 9 =
        // s^2 / 3, the samples estimator; 2 degrees of freedom.
        tp::Film one(1, 1, k), plain(1, 1);
        for (uint32_t s = 0; s < 3; ++s) {
            one.add_sample(0, glm::dvec3(x[s]), s);
            plain.add_sample(0, glm::dvec3(x[s]));
        }
        CHECK(one.variance_of_mean(0).x == Approx(plain.variance_of_mean(0).x).epsilon(16 * kEps));
        CHECK(one.variance_dof() == 2);
    }
    SECTION("unequal batch sizes weigh each batch mean by its share of the samples") {
        // 9 samples: batch 0 holds samples 0 and 8, the others one each. Independent
        // computation of K'/(K'-1) sum (n_b/N)^2 (m_b - mean)^2.
        tp::Film u(1, 1, k);
        for (uint32_t s = 0; s < 9; ++s) u.add_sample(0, glm::dvec3(x[s]), s);
        long double total = 0.0L;
        for (uint32_t s = 0; s < 9; ++s) total += x[s];
        const long double mu = total / 9;
        long double v = 0.0L;
        for (uint32_t b = 0; b < k; ++b) {
            const long double mb = b == 0 ? (x[0] + (long double)x[8]) / 2 : x[b];
            const long double w = (b == 0 ? 2.0L : 1.0L) / 9;
            v += w * w * (mb - mu) * (mb - mu);
        }
        CHECK(u.variance_of_mean(0).x == Approx(double(v * 8 / 7)).epsilon(64 * kEps));
    }
}

TEST_CASE("film: the lean sample variance keeps 11 significant bits, rounded to nearest",
          "[film]") {
    // 1 + 2^-10 has 11 significant bits and is kept; 1 + 2^-11 lies halfway between 1 and
    // 1 + 2^-10 and goes to the even one, 1; 1 + 3 * 2^-12 rounds up to 1 + 2^-10. The same at
    // any binary exponent (variances of 10^-20 and 10^20 stay in float32's range), the carry
    // into the next power of two, and the values that are kept as they are.
    using tp::lean_sample_variance;
    for (const int e : {0, -66, 66}) {
        CHECK(lean_sample_variance(std::ldexp(1.0 + 0x1p-10, e)) ==
              float(std::ldexp(1.0 + 0x1p-10, e)));
        CHECK(lean_sample_variance(std::ldexp(1.0 + 0x1p-11, e)) == float(std::ldexp(1.0, e)));
        CHECK(lean_sample_variance(std::ldexp(1.0 + 3 * 0x1p-12, e)) ==
              float(std::ldexp(1.0 + 0x1p-10, e)));
        CHECK(lean_sample_variance(std::ldexp(2.0 - 0x1p-12, e)) == float(std::ldexp(2.0, e)));
    }
    CHECK(lean_sample_variance(0.0) == 0.0f);
    CHECK(std::isinf(lean_sample_variance(std::numeric_limits<double>::infinity())));
    // Every value within 2^-11 relative: 10^5 log-uniform values against the bound.
    std::mt19937_64 g(3);
    std::uniform_real_distribution<double> u(-30.0, 30.0);
    for (int i = 0; i < 100000; ++i) {
        const double v = std::pow(10.0, u(g));
        REQUIRE(std::abs(double(lean_sample_variance(v)) - v) <= std::ldexp(v, -11));
    }
    CHECK(tp::film_layout_from_name("full") == tp::FilmLayout::full);
    CHECK_THROWS_WITH(tp::film_layout_from_name("half"), Catch::Contains("--film half"));
}

TEST_CASE("film: merging films of disjoint sample ranges keeps the batch estimate", "[film]") {
    // --device all renders disjoint ranges on each device and merges the films: batch b of
    // the union must hold both parts' samples of batch b, so the merged film equals one film
    // of all the samples (to rounding).
    const uint32_t k = 8;
    const std::vector<double> x = samples(40, 1.0, 0.5, 13);
    tp::Film whole(1, 1, k), a(1, 1, k), b(1, 1, k);
    for (uint32_t s = 0; s < x.size(); ++s) {
        whole.add_sample(0, glm::dvec3(x[s]), s);
        (s < 17 ? a : b).add_sample(0, glm::dvec3(x[s]), s);
    }
    a.merge(b);
    CHECK(a.count(0) == whole.count(0));
    CHECK(a.mean(0).x == Approx(whole.mean(0).x).epsilon(64 * kEps));
    CHECK(a.variance_of_mean(0).x == Approx(whole.variance_of_mean(0).x).epsilon(64 * kEps));
}
