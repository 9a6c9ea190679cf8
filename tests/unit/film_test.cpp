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
    // --device all merges the devices' films (vulkan_rt/device_group.cpp). Two films of 700
    // and 1300 samples with different means (0.5 and 2: the between-film term matters) against
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
