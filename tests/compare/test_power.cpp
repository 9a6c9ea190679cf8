// Power: differences the test must find. The global test's power is checked against the
// noncentral chi-square it should follow; the stated detections on real renders are the ones
// docs/compare.md, "Power", states (spp and resolution in each test's name).
#include "rates.h"
#include "renders.h"
#include "synthetic.h"

#include "compare/compare.h"
#include "compare/distributions.h"
#include "compare/power.h"
#include "shared/rng.h"
#include "support/test_paths.h"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/non_central_chi_squared.hpp>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace tp;
using namespace tp::test;

namespace {

// How many of n synthetic pairs, image A with a uniform bias 1 + b (seeds seed + 2i and
// seed + 2i + 1), the global test rejects at `level`.
size_t global_detections(const SyntheticSpec& spec, double b, double level, size_t n,
                         uint64_t seed) {
    Bias bias;
    bias.scale = 1 + b;
    bias.x1 = spec.width;
    bias.y1 = spec.height;
    size_t detected = 0;
    for (size_t i = 0; i < n; ++i) {
        const CompareResult r = compare_images(synthetic_render(spec, seed + 2 * i, bias),
                                               synthetic_render(spec, seed + 2 * i + 1), {});
        detected += r.global.p_value <= level;
    }
    return detected;
}

} // namespace

TEST_CASE("power of the global test follows the noncentral chi-square", "[compare][power]") {
    // A uniform +1.5% bias, Gaussian noise, independent channels (so the scale g ~ 1). Under
    // H1 X ~ chi2'(3K, lambda) with lambda = sum over tile-channels of (sum_i b mu_i)^2 /
    // sum_i Var(d_i); Var(d_i) = (0.5 mu_i)^2 ((1 + b)^2 + 1) / spp (synthetic.h). The
    // predicted power at level alpha/2 must match the observed one within the binomial 99%
    // interval; the remaining model error (t dof mapped to the normal, the estimated
    // correlation) is far below that interval's half-width of ~0.09.
    SyntheticSpec spec;
    const double b = 0.015, level = 0.025;
    const int tile = 8, k = (spec.width / tile) * (spec.height / tile);
    double lambda = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int ty = 0; ty < spec.height / tile; ++ty)
            for (int tx = 0; tx < spec.width / tile; ++tx) {
                double sum = 0.0, var = 0.0;
                for (int y = ty * tile; y < (ty + 1) * tile; ++y)
                    for (int x = tx * tile; x < (tx + 1) * tile; ++x) {
                        const double mu = true_mean(spec, c, x, y);
                        sum += b * mu;
                        var += 0.25 * mu * mu * ((1 + b) * (1 + b) + 1) / spec.spp;
                    }
                if (var > 0) lambda += sum * sum / var;
            }
    const double crit =
        boost::math::quantile(boost::math::complement(boost::math::chi_squared(3.0 * k), level));
    const double predicted = boost::math::cdf(
        boost::math::complement(boost::math::non_central_chi_squared(3.0 * k, lambda), crit));
    const size_t n = 200;
    const size_t detected = global_detections(spec, b, level, n, 7000);
    const CountInterval ci = binomial_interval99(n, predicted);
    INFO("lambda " << lambda << ", predicted power " << predicted << ", detected " << detected
                   << " of " << n << ", 99% interval [" << ci.lo << ", " << ci.hi << "]");
    CHECK(detected >= ci.lo);
    CHECK(detected <= ci.hi);
}

TEST_CASE("the power model of verify predicts the global test's power, with independent and "
          "with identical channels",
          "[compare][power]") {
    // The same uniform +1.5% as above: compare/power.h from the true means and per-sample
    // variances (their average over the two images, 0.25 mu^2 ((1 + b)^2 + 1) / 2) against the
    // rejections observed. Identical channels (one Y for R, G, B: the same path) make the
    // channels' correlation 1, the null 3 chi2_K instead of chi2_3K, and the power lower: that
    // case checks the model's use of R. The noncentral chi-square of the case above is the exact
    // answer for independent channels; the model's two-moment fit must be within 0.02 of it.
    const double b = 0.015, level = 0.025;
    for (const bool identical : {false, true}) {
        SyntheticSpec spec;
        spec.correlated_channels = identical;
        Planes mean, var;
        for (size_t c = 0; c < 3; ++c)
            for (int y = 0; y < spec.height; ++y)
                for (int x = 0; x < spec.width; ++x) {
                    const double mu = true_mean(spec, int(c), x, y);
                    mean[c].push_back(mu);
                    var[c].push_back(0.25 * mu * mu * ((1 + b) * (1 + b) + 1) / 2);
                }
        const double r = identical ? 1.0 : 0.0;
        const PowerModel model = power_model(spec.width, spec.height, mean, var, {r, r, r}, 8);
        const double n_eff = effective_spp(spec.spp, spec.spp);
        const double predicted = global_test_power(model, b, n_eff, level);
        if (!identical) {
            const double lambda = b * b * n_eff * model.signal, k = model.null_mean;
            const double crit = chi2_upper_quantile(level, k);
            const double exact = boost::math::cdf(
                boost::math::complement(boost::math::non_central_chi_squared(k, lambda), crit));
            CHECK(predicted == Approx(exact).margin(0.02));
        }
        const size_t n = 200;
        const size_t detected = global_detections(spec, b, level, n, 9000);
        const CountInterval ci = binomial_interval99(n, predicted);
        INFO((identical ? "identical" : "independent")
             << " channels: model power " << predicted << ", detected " << detected << " of " << n
             << ", 99% interval [" << ci.lo << ", " << ci.hi << "]");
        CHECK(detected >= ci.lo);
        CHECK(detected <= ci.hi);
    }
}

TEST_CASE("power: a 1% change of the white albedo in cornell, 64x64 at 256 spp",
          "[compare][power]") {
    // White covers floor, ceiling, back wall and both blocks; +1% there brightens most pixels
    // by 1% or more (interreflection). Seeds differ; a control pair without the change must
    // stay consistent so that the detection is the change's doing.
    // Both samplers (docs/sampling.md): Sobol's batch variance has fewer degrees of freedom but
    // a smaller variance of the mean.
    const std::string dir = temp_dir("power-albedo");
    const std::string brighter = scene_with_scaled_albedo("cornell", "white", 1.01, dir);
    for (uint32_t sampler : {SAMPLER_RANDOM, SAMPLER_SOBOL}) {
        RenderSpec base;
        base.spp = 256;
        base.seed = 1;
        base.sampler = sampler;
        RenderSpec changed = base;
        changed.scene = brighter;
        changed.seed = 2;
        RenderSpec control = base;
        control.seed = 3;
        const RgbImage a = render_cpu_image(base);
        const CompareResult r = compare_images(a, render_cpu_image(changed), {});
        INFO("sampler " << sampler << ": p = " << r.p_value << ", global p = " << r.global.p_value);
        CHECK(r.different);
        for (const ChannelMetrics& m : r.metrics.channel) CHECK(m.bias < 0.0); // A is darker
        CHECK_FALSE(compare_images(a, render_cpu_image(control), {}).different);
    }
}

TEST_CASE("power: a 3% change inside a 32x32 patch, cornell 64x64 at 128 spp", "[compare][power]") {
    // Two independent renders; B's pixels in [16, 48)^2 scaled by 1.03, their variance of the
    // mean and sample variance by 1.03^2, as a renderer that is 3% too bright there would write
    // them. The tile with the largest |z| must lie in the patch: the report shows where, not
    // only whether.
    RenderSpec sa;
    sa.spp = 128;
    sa.seed = 5;
    RenderSpec sb = sa;
    sb.seed = 6;
    const RgbImage a = render_cpu_image(sa);
    RgbImage b = render_cpu_image(sb);
    CHECK_FALSE(compare_images(a, b, {}).different);
    for (size_t c = 0; c < 3; ++c)
        for (int y = 16; y < 48; ++y)
            for (int x = 16; x < 48; ++x) {
                const size_t i = size_t(y * b.width + x);
                b.mean[c][i] *= 1.03;
                b.var[c][i] *= 1.03 * 1.03;
                if (b.has_sample_variance()) b.sample_var[c][i] *= 1.03 * 1.03;
            }
    const CompareResult r = compare_images(a, b, {});
    INFO("p = " << r.p_value << ", global p = " << r.global.p_value);
    CHECK(r.different);
    size_t worst = 0;
    double worst_z = 0;
    for (size_t c = 0; c < 3; ++c)
        for (size_t j = 0; j < r.global.z[c].size(); ++j)
            if (std::fabs(r.global.z[c][j]) > worst_z) {
                worst_z = std::fabs(r.global.z[c][j]);
                worst = j;
            }
    const int tx = int(worst) % r.global.tiles_x, ty = int(worst) / r.global.tiles_x;
    CHECK((tx >= 2 && tx < 6 && ty >= 2 && ty < 6));
}

TEST_CASE("power: the camera moved by half a pixel, cornell 64x64 at 64 spp", "[compare][power]") {
    // A pixel spans 2 d tan(fov/2) / H at the target distance d = 0.8 m (fov 39.3077 deg,
    // H = 64); eye and target move sideways by half of that. Edges (blocks, light, wall
    // corners) change by up to the full contrast, so single pixels become significant.
    // With the Sobol sampler the per-pixel t has only 7 degrees of freedom (docs/sampling.md),
    // but the stratified pixel jitter shrinks the variance at edges most.
    const double half_pixel = 0.8 * std::tan(39.3077 / 2 * M_PI / 180) / 64;
    for (uint32_t sampler : {SAMPLER_RANDOM, SAMPLER_SOBOL}) {
        RenderSpec sa;
        sa.spp = 64;
        sa.seed = 7;
        sa.sampler = sampler;
        RenderSpec sb = sa;
        sb.seed = 8;
        sb.eye = vec3(float(0.278 + half_pixel), 0.273f, -0.8f);
        sb.target = vec3(float(0.278 + half_pixel), 0.273f, 0.0f);
        const CompareResult r = compare_images(render_cpu_image(sa), render_cpu_image(sb), {});
        INFO("sampler " << sampler << ": p = " << r.p_value << ", significant pixels "
                        << r.local.significant_pixels);
        CHECK(r.different);
        CHECK(r.local.significant_pixels > 0);
        CHECK(r.global.p_value <= r.global_level);
    }
}

TEST_CASE("power at unequal spp: a 1% change of the white albedo in cornell, 64x64, 128 spp "
          "against 1024",
          "[compare][power][unequal-spp]") {
    // The albedo case above at 1:8 with A at half the spp it needs at 1:1 (256): B's
    // 8x samples shrink the variance of the difference, and the borrowed variance
    // (differences.h) costs little where nothing is heavy-tailed. The change is tried in
    // either image, since under skew the two directions need not be equally easy; a control
    // pair without the change stays consistent. Both samplers: with Sobol's, A borrows B's
    // sample_variance, which its stratified batches make larger than n Var(mean).
    const uint32_t sampler = GENERATE(SAMPLER_RANDOM, SAMPLER_SOBOL);
    const std::string dir = temp_dir("power-albedo-unequal-" + std::to_string(sampler));
    const std::string brighter = scene_with_scaled_albedo("cornell", "white", 1.01, dir);
    RenderSpec low;
    low.sampler = sampler;
    low.spp = 128;
    low.seed = 21;
    RenderSpec high = low;
    high.spp = 1024;
    high.seed = 22;
    const RgbImage a = render_cpu_image(low), b = render_cpu_image(high);
    CHECK_FALSE(compare_images(a, b, {}).different);
    RenderSpec low_changed = low, high_changed = high;
    low_changed.scene = high_changed.scene = brighter;
    low_changed.seed = 23;
    high_changed.seed = 24;
    const CompareResult in_b = compare_images(a, render_cpu_image(high_changed), {});
    const CompareResult in_a = compare_images(render_cpu_image(low_changed), b, {});
    INFO("sampler " << sampler << ", in B: p = " << in_b.p_value << "; in A: p = " << in_a.p_value);
    CHECK(in_b.different);
    CHECK(in_a.different);
}

TEST_CASE("power at unequal spp: a 5% change confined to the caustic, 1024 against 8192 spp",
          "[compare][power][unequal-spp]") {
    // cornell_spheres framed on the caustic the glass sphere throws on the floor (32x32, 16
    // degrees): about 200 of the 1024 pixels are caustic, more than 3x the median luminance of
    // B. Their samples are the heaviest-tailed of the bundled scenes (light found only by
    // BSDF samples through the glass), so the per-sample relative standard deviation is ~5
    // and a 5% change needs ~1000 spp of A even at 1:1 (docs/compare.md, "Power at unequal
    // spp"). The change (mean x 1.05, variance and sample variance x 1.05^2) is applied to the
    // caustic pixels of either image. The random sampler: with Sobol's (the default) A borrows
    // B's sample variance, which leaves out the stratification's gain, and the change in A gave
    // p = 0.02 here (in B 3e-9; docs/compare.md, "Power").
    RenderSpec low;
    low.sampler = SAMPLER_RANDOM;
    low.scene = "cornell_spheres";
    low.width = low.height = 32;
    low.spp = 1024;
    low.seed = 31;
    low.eye = vec3(0.16f, 0.16f, -0.12f);
    low.target = vec3(0.149f, 0.0115f, 0.128f);
    low.fov = 16.0f;
    RenderSpec high = low;
    high.spp = 8192;
    high.seed = 32;
    const RgbImage a = render_cpu_image(low), b = render_cpu_image(high);
    std::vector<double> luminance(b.pixels());
    for (size_t i = 0; i < b.pixels(); ++i)
        luminance[i] = b.mean[0][i] + b.mean[1][i] + b.mean[2][i];
    std::vector<double> sorted = luminance;
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2),
                     sorted.end());
    const double median = sorted[sorted.size() / 2];
    size_t caustic = 0;
    auto changed = [&](RgbImage img) {
        for (size_t i = 0; i < img.pixels(); ++i)
            if (luminance[i] > 3.0 * median)
                for (size_t c = 0; c < 3; ++c) {
                    img.mean[c][i] *= 1.05;
                    img.var[c][i] *= 1.05 * 1.05;
                    if (img.has_sample_variance()) img.sample_var[c][i] *= 1.05 * 1.05;
                }
        return img;
    };
    for (double l : luminance) caustic += l > 3.0 * median;
    INFO(caustic << " caustic pixels");
    CHECK(caustic > 100);
    CHECK_FALSE(compare_images(a, b, {}).different);
    const CompareResult in_b = compare_images(a, changed(b), {});
    const CompareResult in_a = compare_images(changed(a), b, {});
    INFO("in B: p = " << in_b.p_value << "; in A: p = " << in_a.p_value);
    CHECK(in_b.different);
    CHECK(in_a.different);
}
