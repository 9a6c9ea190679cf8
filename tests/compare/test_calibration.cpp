// Size of the test: false alarms under H0, from synthetic renderings with known noise
// (synthetic.h). Every trial is an independent pair of images (or an image and the exact
// truth); the number of rejections at level alpha must lie in the central 99% interval of
// Binomial(n, alpha) where the test is exact, and below its upper end where it is only valid.
#include "rates.h"
#include "synthetic.h"

#include "compare/compare.h"

#include <catch2/catch.hpp>

#include <array>
#include <vector>

using namespace tp;
using namespace tp::test;

namespace {

struct TrialPValues {
    std::vector<double> overall, local, global;
};

// `spp_b`: B's samples per pixel (0: the same as A's).
TrialPValues run_trials(const SyntheticSpec& spec, size_t n, bool reference_mode, uint64_t seed,
                        uint32_t spp_b = 0) {
    TrialPValues t;
    const RgbImage truth = synthetic_reference(spec);
    SyntheticSpec spec_b = spec;
    if (spp_b) spec_b.spp = spp_b;
    for (size_t i = 0; i < n; ++i) {
        const RgbImage a = synthetic_render(spec, seed + 2 * i);
        const RgbImage b = reference_mode ? truth : synthetic_render(spec_b, seed + 2 * i + 1);
        const CompareResult r = compare_images(a, b, CompareOptions{});
        t.overall.push_back(r.p_value);
        t.local.push_back(r.local.holm.p_value);
        t.global.push_back(r.global.p_value);
    }
    return t;
}

size_t rejections(const std::vector<double>& p, double alpha) {
    size_t k = 0;
    for (double v : p) k += v <= alpha;
    return k;
}

void check_exact(const std::string& name, const std::vector<double>& p, double alpha) {
    const size_t k = rejections(p, alpha);
    const CountInterval ci = binomial_interval99(p.size(), alpha);
    INFO(describe_rate(name, k, p.size(), alpha));
    CHECK(k >= ci.lo);
    CHECK(k <= ci.hi);
}

void check_valid(const std::string& name, const std::vector<double>& p, double alpha) {
    const size_t k = rejections(p, alpha);
    INFO(describe_rate(name, k, p.size(), alpha));
    CHECK(k <= binomial_interval99(p.size(), alpha).hi);
}

struct Ratio {
    uint32_t spp_a, spp_b;
    size_t trials;
};

// A at ratio.spp_a against B at ratio.spp_b, both with `batches` (0: the samples estimator):
// every part of the test at or below alpha.
void check_unequal_spp(Noise noise, const Ratio& ratio, uint32_t batches, uint64_t seed) {
    SyntheticSpec spec;
    spec.noise = noise;
    spec.spp = ratio.spp_a;
    spec.batches = batches;
    spec.correlated_channels = noise != Noise::Gaussian;
    const TrialPValues t = run_trials(spec, ratio.trials, false, seed, ratio.spp_b);
    INFO("noise model " << int(noise) << ", " << ratio.spp_a << " against " << ratio.spp_b
                        << " spp, " << batches << " batches");
    for (double alpha : {0.05, 0.01}) {
        check_valid("whole test", t.overall, alpha);
        check_valid("local (Holm over pixel-channels)", t.local, alpha);
        check_valid("global (tile chi-square)", t.global, alpha);
    }
}

} // namespace

TEST_CASE("size, two-sample, Gaussian noise: the whole test and both parts are exact",
          "[compare][calibration]") {
    // Independent channels: Holm over the pixel-channels is then as sharp as Bonferroni gets,
    // and the whole test rejects at 1 - (1 - alpha/2)^2, within 0.3% of alpha.
    SyntheticSpec spec;
    spec.noise = Noise::Gaussian;
    const TrialPValues t = run_trials(spec, 1000, false, 1000);
    for (double alpha : {0.05, 0.01}) {
        check_exact("whole test", t.overall, alpha);
        check_exact("local (Holm over pixel-channels)", t.local, alpha);
        check_exact("global (tile chi-square)", t.global, alpha);
    }
}

TEST_CASE("size, two-sample, Gaussian noise with identical channels: the global test stays "
          "exact",
          "[compare][calibration]") {
    // One draw for R, G and B (correlation 1): the scaled chi-square (tile_test.h) keeps its
    // level; Holm counts each pixel three times and rejects at ~alpha/3, so the whole test is
    // valid but below alpha.
    SyntheticSpec spec;
    spec.noise = Noise::Gaussian;
    spec.correlated_channels = true;
    const TrialPValues t = run_trials(spec, 400, false, 20000);
    for (double alpha : {0.05, 0.01}) {
        check_exact("global (tile chi-square)", t.global, alpha);
        check_valid("whole test", t.overall, alpha);
    }
}

TEST_CASE("size, two-sample, heavy-tailed noise: the global test keeps its level, the whole "
          "test stays valid",
          "[compare][calibration]") {
    // Skewed samples (lognormal, Pareto with infinite third moment, rare 100x fireflies) with
    // one draw per sample for R, G and B, as a path gives. A and B enter symmetrically, so a
    // firefly in either image inflates its own variance estimate as much as the difference:
    // the self-normalised statistics get lighter tails than the normal (Efron 1969, "Student's
    // t-test under symmetry conditions"). Per pixel (N = spp) that makes Holm's deep-tail
    // test far more conservative; per tile (N = 64 spp) the tile chi-square stays near its
    // level; the whole test is valid but rejects less often than alpha.
    for (Noise noise : {Noise::Lognormal, Noise::Pareto, Noise::Firefly}) {
        SyntheticSpec spec;
        spec.noise = noise;
        spec.correlated_channels = true;
        const TrialPValues t = run_trials(spec, 400, false, 50000 + 10000 * uint64_t(noise));
        INFO("noise model " << int(noise));
        for (double alpha : {0.05, 0.01}) {
            check_exact("global (tile chi-square)", t.global, alpha);
            check_valid("whole test", t.overall, alpha);
        }
    }
}

TEST_CASE("size, two-sample at unequal spp (1:8, 1:64), heavy-tailed noise: valid",
          "[compare][calibration][unequal-spp]") {
    // The case of docs/compare.md "Unequal sample counts": A at 16 spp against B at 128, and A
    // at 8 spp against B at 512. The sample mean of a skewed pixel is, at few samples, usually
    // low with a variance estimate that is far too small, and at unequal spp the difference no
    // longer cancels that to first order. Caustic noise is the hard case: half of each pixel's
    // light arrives in samples of probability 1e-4 to 1e-1, so most pixels of A have met none
    // of theirs while B has met several; with each side's own variance (Welch) the whole test
    // rejected in 100% of these trials. Gaussian noise is checked too, where the borrowed
    // variance (differences.h) only makes the test conservative. The bound is the upper end of
    // the 99% binomial interval (valid: at or below alpha).
    for (Noise noise :
         {Noise::Gaussian, Noise::Lognormal, Noise::Pareto, Noise::Firefly, Noise::Caustic})
        for (const Ratio ratio : {Ratio{16, 128, 100}, Ratio{8, 512, 60}})
            check_unequal_spp(noise, ratio, 0, 130000 + 10000 * uint64_t(noise) + ratio.spp_b);
}

TEST_CASE("size, reference mode: exact for Gaussian and heavy-tailed noise",
          "[compare][calibration]") {
    // 32x32 at 64 spp: 2^16 samples, so one tile per channel (kReferenceTileSamples).
    for (Noise noise : {Noise::Gaussian, Noise::Lognormal, Noise::Pareto, Noise::Firefly}) {
        SyntheticSpec spec;
        spec.noise = noise;
        spec.spp = 64;
        const TrialPValues t = run_trials(spec, 300, true, 90000 + 10000 * uint64_t(noise));
        INFO("noise model " << int(noise));
        for (double alpha : {0.05, 0.01}) check_exact("whole test (global)", t.overall, alpha);
        if (noise != Noise::Gaussian) {
            // Why the per-pixel test is advisory here: one-sample t under skew (compare.h).
            const size_t k = rejections(t.local, 0.01);
            INFO(describe_rate("advisory per-pixel test", k, t.local.size(), 0.01));
            CHECK(k > t.local.size() / 2);
        }
    }
}

TEST_CASE("size with the batch estimator (8 stratified batches): Gaussian exact, heavy tails "
          "valid",
          "[compare][calibration][batches]") {
    // The Sobol sampler's variance (render/film.h): samples stratified within each of 8
    // independent batches, the variance of the mean from the batch means with 7 degrees of
    // freedom (twinpath:variance_dof), which compare's t statistics must then use. At 16 spp
    // every batch holds 2 samples. Gaussian noise: the global test is exact; the per-pixel t
    // with Welch-Satterthwaite's 14 dof is conservative (stratified batch means have lighter
    // tails than the t assumes), so the local and whole tests are valid. Heavy tails: the
    // global test and the whole test stay valid, as with the sample variance.
    for (Noise noise : {Noise::Gaussian, Noise::Lognormal, Noise::Pareto, Noise::Firefly}) {
        SyntheticSpec spec;
        spec.noise = noise;
        spec.batches = 8;
        spec.correlated_channels = noise != Noise::Gaussian;
        const size_t trials = noise == Noise::Gaussian ? 600 : 300;
        const TrialPValues t = run_trials(spec, trials, false, 230000 + 10000 * uint64_t(noise));
        INFO("noise model " << int(noise));
        for (double alpha : {0.05, 0.01}) {
            if (noise == Noise::Gaussian) {
                check_valid("whole test", t.overall, alpha);
                check_valid("local (Holm over pixel-channels)", t.local, alpha);
                check_exact("global (tile chi-square)", t.global, alpha);
            } else {
                check_valid("whole test", t.overall, alpha);
                check_valid("global (tile chi-square)", t.global, alpha);
            }
        }
    }
}

TEST_CASE("size with the batch estimator at unequal spp (1:8, 1:64), heavy-tailed noise: valid",
          "[compare][calibration][batches][unequal-spp]") {
    // The unequal-spp case above with 8 stratified batches on both sides: A at 16 spp (2
    // samples per batch) against B at 128, and A at 8 against B at 512. B's n Var(mean) falls
    // with n for stratified batches, so A borrows B's sample_variance instead (differences.h),
    // the spread of B's samples, which estimates the variance of one sample however the
    // samples are stratified. Caustic noise is the hard case: B's batches meet their rare
    // samples so regularly that n Var(mean) is far below that spread; borrowing n Var(mean)
    // rejects every trial. The bound is the upper end of the 99% binomial interval.
    for (Noise noise :
         {Noise::Gaussian, Noise::Lognormal, Noise::Pareto, Noise::Firefly, Noise::Caustic})
        for (const Ratio ratio : {Ratio{16, 128, 100}, Ratio{8, 512, 60}})
            check_unequal_spp(noise, ratio, 8, 330000 + 10000 * uint64_t(noise) + ratio.spp_b);
}
