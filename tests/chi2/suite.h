// The chi-square suite's significance level and its two assertions.
//
// Every goodness-of-fit test of a correct sampler is one hypothesis test; with m of them at
// level alpha each, a correct implementation would fail the suite with probability
// 1 - (1 - alpha)^m. Sidak's correction picks the per-test level that makes the suite-wide rate
// 0.01 (pbrt-v4 bsdfs_test.cpp and Mitsuba 3 chi2.py do the same). The samples come from fixed
// seeds, so a run is reproducible: the 1 % is the chance that the seeds chosen are unlucky.
#pragma once

#include "support/chi2.h"

#include <catch2/catch.hpp>

#include <cstdio>

namespace tp::test::chi2 {

// The acceptance tests of the suite, counted by file:
//   sampling_chi2_test.cpp   cosine 1, Phong lobe 6, uniform sphere 1, triangle 1, rng 1
//   bsdf_chi2_test.cpp       Phong mixture 8, dielectric choice 6
//   lights_chi2_test.cpp     triangle light 1, environment map 1
//   discrete_chi2_test.cpp   alias tables 2
//   pbr_chi2_test.cpp        the glTF material, kPbrCases (pbr_cases.h)
// sobol_chi2_test.cpp tests the Sobol sampler's uniformity as a family of its own. The GPU suite
// (tests/gpu/chi2_gpu_test.cpp) repeats a subset at the same per-test level, which is
// conservative for it.
// The deliberately wrong pairs in power_chi2_test.cpp must be rejected at the same level; they
// are not part of the family (a rejection there is the expected outcome).
constexpr int kPbrCases = 23;
constexpr int kFamilySize = 28 + kPbrCases;
constexpr double kSuiteAlpha = 0.01;

inline double alpha_per_test() {
    return sidak_alpha(kSuiteAlpha, kFamilySize);
}

inline void report(const char* name, const Result& r) {
    std::printf("chi2 %-40s %s\n", name, r.summary().c_str());
}

// A correct sampler/pdf pair: the samples must be accepted.
inline void check_accepted(const char* name, const Result& r) {
    report(name, r);
    INFO(name << ": " << r.summary() << " (alpha per test " << alpha_per_test() << ")");
    CHECK(r.accepted(alpha_per_test()));
}

// A deliberately wrong pair: the same test must reject it, or it has no power.
inline void check_rejected(const char* name, const Result& r) {
    report(name, r);
    INFO(name << ": " << r.summary() << " (alpha per test " << alpha_per_test() << ")");
    CHECK_FALSE(r.accepted(alpha_per_test()));
}

} // namespace tp::test::chi2
