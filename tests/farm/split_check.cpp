#include "split_check.h"

#include "image/exr_io.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace tp::test {
namespace {

// One float32 rounding: relative error at most 2^-24 (unit roundoff, round to nearest).
constexpr double kRound = 5.9604644775390625e-08;

// The batch means and the batch variance of pixel i, channel c, merged against single (bounds
// in check_merged_equals_single); returns the largest bound.
double check_batches(const ExrImage& merged, const ExrImage& single, const char* c, size_t i) {
    std::vector<double> mean_b;
    for (uint32_t b = 0; single.has(fmt::format("batch{}.{}", b, c)); ++b)
        mean_b.push_back(single.channel(fmt::format("batch{}.{}", b, c))[i]);
    REQUIRE(mean_b.size() == 8);
    const double n = double(single.integers.at("twinpath:spp")), k = double(mean_b.size());
    double max_m = 0, mean = 0;
    for (double x : mean_b) {
        max_m = std::max(max_m, std::fabs(x));
        mean += x / k; // every batch holds n / 8 samples in the tests that call this
    }
    REQUIRE(std::fmod(n, k) == 0.0);
    double largest = 0;
    for (uint32_t b = 0; b < mean_b.size(); ++b) {
        const double tol = 2 * 3 * kRound * std::fabs(mean_b[b]);
        CHECK(std::fabs(double(merged.channel(fmt::format("batch{}.{}", b, c))[i]) - mean_b[b]) <=
              tol);
        largest = std::max(largest, tol);
    }
    const double e = 2 * 3 * kRound * max_m, var = single.channel(std::string("variance.") + c)[i];
    double moved = 0;
    for (double x : mean_b) moved += 2 * std::fabs(x - mean) * 2 * e / (k * k);
    const double tol_var = 2 * (k / (k - 1) * moved + 2 * kRound * var);
    CHECK(std::fabs(double(merged.channel(std::string("variance.") + c)[i]) - var) <= tol_var);
    return std::max(largest, tol_var);
}

} // namespace

std::string render_part(const std::string& dir, const std::string& name, const std::string& args) {
    const std::string out = dir + "/" + name;
    const auto r = run(twinpath("render cornell --width 16 --height 16 --max-depth 4 " + args +
                                " -o " + shell_quote(out)));
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    return out;
}

void check_offset_shifts_samples(const std::string& dir, const std::string& backend) {
    const ExrImage s0 = read_exr(render_part(dir, "s0.exr", backend + " --spp 1"));
    const ExrImage s1 =
        read_exr(render_part(dir, "s1.exr", backend + " --spp 1 --sample-offset 1"));
    const ExrImage s01 = read_exr(render_part(dir, "s01.exr", backend + " --spp 2"));
    CHECK(s1.strings.at("twinpath:sample_ranges") == "0:1-2");
    CHECK(s01.strings.at("twinpath:sample_ranges") == "0:0-2");
    size_t differ = 0, pixels = 0;
    for (const char* c : {"R", "G", "B"}) {
        const auto &x0 = s0.channel(c), &x1 = s1.channel(c), &m = s01.channel(c);
        const auto& v = s01.channel(std::string("variance.") + c);
        for (size_t i = 0; i < x0.size(); ++i) {
            // 2m - x0 carries the roundings of m (doubled), x0 and x1: 2^-24 of each magnitude,
            // and the variance its own and those of its two inputs.
            const double a = x0[i], b = x1[i], mean = m[i];
            const double tol = 4 * kRound * (2 * std::fabs(mean) + std::fabs(a) + std::fabs(b));
            CHECK(std::fabs(2 * mean - a - b) <= tol);
            const double var = (a - b) * (a - b) / 4;
            CHECK(std::fabs(double(v[i]) - var) <= kRound * var + tol * std::fabs(a - b));
            differ += a != b;
            ++pixels;
        }
    }
    // The scene's light and diffuse walls make most samples of a pixel differ.
    CHECK(differ > pixels / 2);
    std::filesystem::remove_all(dir);
}

double check_merge_equals_single(const std::string& dir, const std::vector<std::string>& parts,
                                 const std::string& single) {
    const std::string merged = dir + "/merged.exr";
    std::string args;
    for (const std::string& p : parts) args += shell_quote(p) + " ";
    const auto r = run(twinpath("merge " + args + "-o " + shell_quote(merged)));
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    return check_merged_equals_single(merged, parts, single);
}

double check_merged_equals_single(const std::string& merged, const std::vector<std::string>& parts,
                                  const std::string& single) {
    const ExrImage m = read_exr(merged), s = read_exr(single);
    std::vector<ExrImage> p;
    for (const std::string& path : parts) p.push_back(read_exr(path));
    CHECK(m.integers.at("twinpath:spp") == s.integers.at("twinpath:spp"));
    CHECK(m.strings.at("twinpath:sample_ranges") == s.strings.at("twinpath:sample_ranges"));

    // Both films accumulate in double (Welford per sample, Chan per batch), whose rounding is
    // ~1e-16 relative here; what differs is float32 rounding. The single render rounds its mean
    // and variance once. The merge reads each part's mean m_i and variance v_i rounded once
    // (2^-24 relative), combines them in double and rounds once more. So:
    //   mean: a weighted average of values each off by 2^-24 relative, +1 rounding, +1 for
    //         the single render: 3 * 2^-24 |mean|;
    //   variance: M2 = sum v_i n_i (n_i - 1) + sum n_i (m_i - m)^2 moves by 2^-24 of the first
    //         sum, and by sum n_i 2 |m_i - m| (|e_i| + |e_m|) with e <= 2^-24 max |m_j| through
    //         the means; divided by N (N - 1), plus one rounding of each file.
    // Doubled for the second-order terms and the double accumulation.
    //
    // Batch-estimated renders (--sampler sobol, docs/sampling.md) pool sample_variance.* the
    // same way with M2 = s^2 (n - 1) and no division by N. Their batch means are weighted
    // averages like the mean (3 * 2^-24 relative). variance.* comes from the batch means: each
    // off by e <= 2 * 3 * 2^-24 max_b |m_b| and their mean by as much, it moves by at most
    // K'/(K'-1) sum_b w_b^2 2 |m_b - m| 2e, plus one rounding of each file.
    const bool batches = s.strings.at("twinpath:variance_estimator") == "batches";
    CHECK(m.strings.at("twinpath:variance_estimator") ==
          s.strings.at("twinpath:variance_estimator"));
    if (batches)
        CHECK(m.integers.at("twinpath:variance_dof") == s.integers.at("twinpath:variance_dof"));
    double largest = 0;
    for (const char* c : {"R", "G", "B"}) {
        const std::string vc = std::string(batches ? "sample_variance." : "variance.") + c;
        for (size_t i = 0; i < s.channel(c).size(); ++i) {
            double N = 0, within = 0, max_m = 0, sum_nm = 0;
            for (const ExrImage& part : p) {
                const double n = double(part.integers.at("twinpath:spp"));
                N += n;
                within += double(part.channel(vc)[i]) * (batches ? n - 1 : n * (n - 1));
                max_m = std::max(max_m, std::fabs(double(part.channel(c)[i])));
                sum_nm += n * double(part.channel(c)[i]);
            }
            double spread = 0;
            for (const ExrImage& part : p)
                spread += double(part.integers.at("twinpath:spp")) *
                          std::fabs(double(part.channel(c)[i]) - sum_nm / N);
            const double mean = s.channel(c)[i], var = s.channel(vc)[i];
            const double tol_mean = 2 * 3 * kRound * std::fabs(mean);
            const double tol_var = 2 * ((kRound * within + 4 * kRound * max_m * spread) /
                                            ((batches ? 1 : N) * (N - 1)) +
                                        2 * kRound * var);
            CHECK(std::fabs(double(m.channel(c)[i]) - mean) <= tol_mean);
            CHECK(std::fabs(double(m.channel(vc)[i]) - var) <= tol_var);
            largest = std::max({largest, tol_mean, tol_var});
            if (batches) largest = std::max(largest, check_batches(m, s, c, i));
        }
    }
    const auto e =
        run(twinpath("compare --exact " + shell_quote(merged) + " " + shell_quote(single) +
                     " --tolerance " + fmt::format("{:.17g}", largest)));
    INFO(e.out);
    CHECK(e.exit_code == 0);
    return largest;
}

} // namespace tp::test
