// The building blocks of compare against values computed independently: printed tables of
// the t, normal and chi-square distributions, Holm's procedure worked by hand, tile sums and
// metrics written out for tiny images.
#include "compare/compare.h"
#include "compare/distributions.h"
#include "compare/holm.h"
#include "compare/metrics.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace tp;

namespace {

// A w x h image with every pixel-channel equal to `mean` (and `var` if >= 0).
RgbImage flat_image(int w, int h, double mean, double var, std::optional<int64_t> spp = {}) {
    RgbImage img;
    img.path = "flat";
    img.width = w;
    img.height = h;
    for (size_t c = 0; c < 3; ++c) {
        img.mean[c].assign(img.pixels(), mean);
        if (var >= 0) img.var[c].assign(img.pixels(), var);
    }
    img.spp = spp;
    return img;
}

} // namespace

TEST_CASE("distribution tails match printed tables", "[compare][units]") {
    // Student's t, 10 dof: t_0.975 = 2.228139 (e.g. Abramowitz & Stegun table 26.10).
    CHECK(two_sided_p(2.228139, 10.0) == Approx(0.05).epsilon(1e-5));
    CHECK(two_sided_p(-2.228139, 10.0) == Approx(0.05).epsilon(1e-5));
    // Normal: z_0.975 = 1.959964; infinite dof is the normal.
    CHECK(two_sided_p(1.959964, HUGE_VAL) == Approx(0.05).epsilon(1e-5));
    // The t quantile maps to the normal quantile of the same tail.
    CHECK(equivalent_normal(2.228139, 10.0) == Approx(1.959964).epsilon(1e-5));
    CHECK(equivalent_normal(-2.228139, 10.0) == Approx(-1.959964).epsilon(1e-5));
    // Chi-square, 10 dof: the 0.95 quantile is 18.307.
    CHECK(chi2_upper(18.307, 10.0) == Approx(0.05).epsilon(1e-3));
}

TEST_CASE("the chi-square tail far below its mean at the dof of a 1080p tile test",
          "[compare][units]") {
    // Two equal 1920x1080 images give 32,400 tiles with statistic 0; Boost alone throws there
    // (Gamma overflow) for k above about 5000. For large k chi-square ~ N(k, 2k): 20 standard
    // deviations below the mean the upper tail is 1 - 3e-89, i.e. 1 in double.
    for (const double k : {1e4, 32400.0, 1e6, 1e9}) {
        CHECK(chi2_upper(0.0, k) == 1.0);
        CHECK(chi2_upper(1e-300, k) == 1.0);
        CHECK(chi2_upper(k - 20.0 * std::sqrt(2.0 * k), k) == 1.0);
    }
    // Above the mean Boost still answers: 2 standard deviations up is the normal tail 0.02275,
    // to within the skewness sqrt(8/k) = 0.3 % at k = 1e6 (allow 2 %).
    CHECK(chi2_upper(1e6 + 2.0 * std::sqrt(2e6), 1e6) == Approx(0.02275).epsilon(0.02));
}

TEST_CASE("Holm's step-down procedure, worked by hand", "[compare][units]") {
    // m = 4, level 0.05. Sorted: 0.005 <= 0.05/4 reject; 0.01 <= 0.05/3 reject;
    // 0.03 > 0.05/2 stop, so 0.04 is kept although 0.04 <= 0.05/1.
    const HolmResult r = holm({0.01, 0.04, 0.03, 0.005}, 0.05);
    CHECK(r.count == 2);
    CHECK(r.rejected == std::vector<uint8_t>{1, 0, 0, 1});
    CHECK(r.p_value == Approx(4 * 0.005));
    // Nothing below level/m: nothing rejected, the family p-value is m min p capped at 1.
    const HolmResult none = holm({0.5, 0.02, 0.9}, 0.05);
    CHECK(none.count == 0);
    CHECK(none.p_value == Approx(0.06));
}

TEST_CASE("Welch-Satterthwaite dof and the tile chi-square, by hand", "[compare][units]") {
    // Equal variances v and spp n in both images: nu = (2v)^2 / (2 v^2/(n-1)) = 2(n-1).
    const RgbImage a = flat_image(4, 4, 1.0, 0.01, 9), b = flat_image(4, 4, 1.0, 0.01, 9);
    const Differences d = compute_differences(a, b, 0.0);
    CHECK(d.dof(0, 0) == Approx(16.0));

    // d = 0.1 everywhere, var 0.02 per pixel, tiles of 2x2 (4 pixels): z_T = 0.4 / sqrt(0.08)
    // with nu_T = 4 * 16 = 64 mapped to the normal, K = 4 tiles per channel.
    RgbImage shifted = flat_image(4, 4, 1.1, 0.01, 9);
    const Differences d2 = compute_differences(shifted, b, 0.0);
    const TileTest t = tile_test(d2, 2);
    const double z = equivalent_normal(0.4 / std::sqrt(0.08), 64.0);
    REQUIRE(t.tiles() == 4);
    CHECK(t.counted == std::array<size_t, 3>{4, 4, 4});
    CHECK(t.chi2[1] == Approx(4 * z * z));
    CHECK(t.p[1] == Approx(chi2_upper(4 * z * z, 4.0)));
    // Channel correlation from the products d_c d_c' per tile: 4 * 0.01 / sqrt(0.08 * 0.08)
    // = 0.5 for every pair, tr(R^2) = 3 + 6 * 0.25 = 4.5, g = 1.5, h = 12 / 1.5 = 8.
    CHECK(t.correlation[0] == Approx(0.5));
    CHECK(t.scale == Approx(1.5));
    CHECK(t.dof == Approx(8.0));
    CHECK(t.p_value == Approx(chi2_upper(3 * 4 * z * z / 1.5, 8.0)));
}

TEST_CASE("zero-variance pixels: equal is consistent, float rounding is tolerated, a real "
          "difference is found",
          "[compare][units]") {
    CompareOptions opt;
    const RgbImage a = flat_image(16, 16, 0.5, 0.0, 64);
    CompareResult same = compare_images(a, flat_image(16, 16, 0.5, 0.0, 64), opt);
    CHECK_FALSE(same.different);
    CHECK(same.diff.at_floor == 3 * 16 * 16);

    // 2^-20 relative (16 float32 ulps) is rounding, far inside the 1e-4 floor: z ~ 0.01.
    const double ulp16 = 0.5 * std::ldexp(1.0, -20);
    CHECK_FALSE(compare_images(a, flat_image(16, 16, 0.5 + ulp16, 0.0, 64), opt).different);

    // 1% in every pixel with no noise at all: z = 0.005 / (1e-4 * 0.505 * sqrt 2) ~ 70.
    CompareResult off = compare_images(a, flat_image(16, 16, 0.505, 0.0, 64), opt);
    CHECK(off.different);
    CHECK(off.local.holm.count == 3 * 16 * 16);
}

TEST_CASE("zero variance never makes a difference: black, constant and partly black images "
          "against themselves",
          "[compare][units]") {
    // A scene with nothing that emits renders black on both engines: every pixel-channel 0 with
    // variance 0, so neither the noise nor the floor gives a scale (the tile test's channel
    // correlation was 0 / 0). A file against itself is consistent whatever it holds.
    CompareOptions opt;
    for (const double level : {0.0, 0.5}) {
        const RgbImage img = flat_image(32, 32, level, 0.0, 64);
        const CompareResult r = compare_images(img, img, opt);
        INFO("level " << level << ", p " << r.p_value << ", global p " << r.global.p_value);
        CHECK_FALSE(r.different);
        CHECK(r.p_value == 1.0);
        CHECK(r.global.p_value == 1.0);
        CHECK(std::isfinite(r.global.scale));
    }
    // Noise in the right half, black (no variance, no floor in the blue channel) in the left.
    RgbImage part = flat_image(32, 32, 0.5, 0.01, 64);
    for (size_t i = 0; i < part.pixels(); ++i)
        if (i % 32 < 16)
            for (size_t c = 0; c < 3; ++c) part.mean[c][i] = part.var[c][i] = 0.0;
    for (size_t i = 0; i < part.pixels(); ++i) part.mean[2][i] = part.var[2][i] = 0.0;
    const CompareResult r = compare_images(part, part, opt);
    CHECK_FALSE(r.different);
    CHECK(r.p_value == 1.0);
    CHECK(std::isfinite(r.global.scale));
}

TEST_CASE("tiles without estimated variance stay in the statistic but not in the dof",
          "[compare][units]") {
    // 4x4, tiles of 2x2: the left two tiles are constant (an emitter), the right two noisy
    // with d = 0. K_c = 2, so X = 0 is compared with chi2 on 2 (scaled) dof, not 4.
    RgbImage a = flat_image(4, 4, 1.0, 0.01, 9), b = flat_image(4, 4, 1.0, 0.01, 9);
    for (size_t c = 0; c < 3; ++c)
        for (size_t i = 0; i < 16; ++i)
            if (i % 4 < 2) a.var[c][i] = b.var[c][i] = 0.0;
    TileTest t = tile_test(compute_differences(a, b, kDefaultRelativeFloor), 2);
    CHECK(t.counted == std::array<size_t, 3>{2, 2, 2});
    CHECK(t.statistic == 0.0);
    // The constant half differing by 1% is still found: z_T = 0.04 / (2e-4 sqrt(4 * 1.0201))
    for (size_t c = 0; c < 3; ++c)
        for (size_t i = 0; i < 16; ++i)
            if (i % 4 < 2) a.mean[c][i] = 1.01;
    t = tile_test(compute_differences(a, b, kDefaultRelativeFloor), 2);
    CHECK(t.p_value < 1e-100);
}

TEST_CASE("error metrics of a two-pixel image, by hand", "[compare][units]") {
    RgbImage a = flat_image(2, 1, 0.0, 0.01), b = flat_image(2, 1, 0.0, 0.03);
    for (size_t c = 0; c < 3; ++c) {
        a.mean[c] = {1.1, 0.0};
        b.mean[c] = {1.0, 0.1};
    }
    const ErrorMetrics m = error_metrics(a, b, b);
    // d = (0.1, -0.1), r = (1, 0.1): MSE 0.01; relMSE (0.01/1.01 + 0.01/0.02) / 2;
    // MAPE (0.1/1.01 + 0.1/0.11) / 2; bias 0; noise MSE 0.04; stderr sqrt(0.08)/2.
    CHECK(m.channel[0].mse == Approx(0.01));
    CHECK(m.channel[1].relmse == Approx((0.01 / 1.01 + 0.01 / 0.02) / 2));
    CHECK(m.channel[2].mape == Approx((0.1 / 1.01 + 0.1 / 0.11) / 2));
    CHECK(m.channel[0].bias == Approx(0.0).margin(1e-15));
    CHECK(m.all.mse_noise == Approx(0.04));
    CHECK(m.channel[0].bias_stderr == Approx(std::sqrt(0.08) / 2));
}

TEST_CASE("reference mode enlarges tiles to 2^16 samples and leaves pixels advisory",
          "[compare][units]") {
    const RgbImage noisy = flat_image(64, 64, 0.5, 0.001, 64);
    const RgbImage exact = flat_image(64, 64, 0.5, -1.0);
    const CompareResult r = compare_images(noisy, exact, CompareOptions{});
    CHECK(r.mode == CompareMode::Reference);
    // ceil(sqrt(65536 / 64)) = 32.
    CHECK(r.global.tile == 32);
    CHECK_FALSE(r.local_in_verdict());
    CHECK(r.reference_is_a == false);
}

TEST_CASE("unequal spp: the image with fewer samples borrows the larger per-sample variance",
          "[compare][units][unequal-spp]") {
    // A: 16 spp, variance of the mean 0.01 (s^2 = 0.16); B: 128 spp. Where B's s^2 = 128 vB
    // exceeds 0.16, A's variance of the mean becomes s^2_B / 16 = 8 vB with B's dof (127);
    // where it does not, A keeps its own (dof 15). B's side never changes.
    const RgbImage a = flat_image(2, 1, 1.0, 0.01, 16);
    RgbImage b = flat_image(2, 1, 0.9, 0.0, 128);
    for (size_t c = 0; c < 3; ++c) b.var[c] = {0.004, 0.0005}; // s^2_B = 0.512 and 0.064
    const Differences d = compute_differences(a, b, 0.0);
    CHECK(d.rule.borrower == VarianceRule::A);
    CHECK(d.rule.ratio == 8.0);
    // Pixel 0 borrows: 8 * 0.004 + 0.004; Welch term (0.032^2) / 127 + 0.004^2 / 127.
    CHECK(d.noise[0][0] == Approx(0.036));
    CHECK(d.welch[0][0] == Approx((0.032 * 0.032 + 0.004 * 0.004) / 127.0));
    // Pixel 1 keeps A's own: 0.01 + 0.0005; Welch 0.01^2 / 15 + 0.0005^2 / 127.
    CHECK(d.noise[0][1] == Approx(0.0105));
    CHECK(d.welch[0][1] == Approx(0.01 * 0.01 / 15.0 + 0.0005 * 0.0005 / 127.0));
    CHECK(d.variance_borrowed == 3);
    CHECK(d.borrowed == std::vector<uint8_t>{1, 0});
    // Swapped, B is the borrower with the same numbers.
    const Differences s = compute_differences(b, a, 0.0);
    CHECK(s.rule.borrower == VarianceRule::B);
    CHECK(s.noise[0][0] == Approx(0.036));
    CHECK(s.noise[0][1] == Approx(0.0105));
    // Equal spp, or an spp missing: nothing is borrowed.
    CHECK(compute_differences(a, flat_image(2, 1, 0.9, 0.004, 16), 0.0).rule.borrower ==
          VarianceRule::None);
    CHECK(compute_differences(a, flat_image(2, 1, 0.9, 0.004), 0.0).rule.borrower ==
          VarianceRule::None);
    // The tile test applies the rule to the tile's sums: one 2x1 tile, A's summed variance
    // 0.02 against 8 (0.004 + 0.0005) = 0.036, so A borrows: 0.036 + 0.0045 = 0.0405 (the sum
    // of the per-pixel results would be 0.0465). Both of A's terms then carry B's dof.
    const TileTest t = tile_test(d, 2);
    const double welch =
        (64.0 * (0.004 * 0.004 + 0.0005 * 0.0005) + 0.004 * 0.004 + 0.0005 * 0.0005) / 127.0;
    CHECK(t.z[0][0] == Approx(equivalent_normal(0.2 / std::sqrt(0.0405), 0.0405 * 0.0405 / welch)));
}

TEST_CASE("unequal spp: a batch-estimated image lends its sample variance, not n var",
          "[compare][units][unequal-spp][batches]") {
    // B: 128 spp of a stratified sampler, variance of the mean 0.0005 from 8 batches (dof 7),
    // so n var = 0.064, while the spread of its samples, sample_variance, is 0.512. A (16 spp,
    // variance 0.01) borrows 0.512 / 16 = 0.032 with B's n - 1 = 127 dof, as in the case
    // above where B's samples are independent and n var = 0.512. Without sample_variance B
    // would lend 8 * 0.0005 = 0.004 < 0.01 and A would keep its own.
    const RgbImage a = flat_image(1, 1, 1.0, 0.01, 16);
    RgbImage b = flat_image(1, 1, 0.9, 0.0005, 128);
    b.variance_dof = 7;
    const Differences own = compute_differences(a, b, 0.0);
    CHECK(own.noise[0][0] == Approx(0.0105));
    CHECK(own.variance_borrowed == 0);
    for (size_t c = 0; c < 3; ++c) b.sample_var[c] = {0.512};
    const Differences d = compute_differences(a, b, 0.0);
    CHECK(d.rule.borrower == VarianceRule::A);
    CHECK(d.noise[0][0] == Approx(0.032 + 0.0005));
    CHECK(d.welch[0][0] == Approx(0.032 * 0.032 / 127.0 + 0.0005 * 0.0005 / 7.0));
    CHECK(d.variance_borrowed == 3);
    // B's own side keeps its batch estimate with its 7 dof; swapped, the same numbers.
    const Differences s = compute_differences(b, a, 0.0);
    CHECK(s.noise[0][0] == Approx(0.032 + 0.0005));
    CHECK(s.welch[0][0] == Approx(0.032 * 0.032 / 127.0 + 0.0005 * 0.0005 / 7.0));
}
