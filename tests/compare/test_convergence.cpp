// --convergence: relMSE against spp. Synthetic series check the fit against the V and B
// computed from the known truth; rendered series check the command line on an unbiased
// and a biased (depth-truncated) renderer.
#include "renders.h"
#include "synthetic.h"

#include "compare/convergence.h"
#include "compare/metrics.h"
#include "render/sampler.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <fstream>

using namespace tp;
using namespace tp::test;

namespace {

// The true V = mean(w s^2) and B = mean(w b^2) of a synthetic series against its exact truth
// (w = 1/(mu^2 + eps); Gaussian samples have s = 0.5 mu; a scale k gives b = (k - 1) mu and
// s = 0.5 k mu).
void true_fit(const SyntheticSpec& s, double k, double& v, double& b) {
    v = b = 0;
    for (int c = 0; c < 3; ++c)
        for (int y = 0; y < s.height; ++y)
            for (int x = 0; x < s.width; ++x) {
                const double mu = true_mean(s, c, x, y), w = 1 / (mu * mu + kRelativeEpsilon);
                v += w * 0.25 * k * k * mu * mu;
                b += w * (k - 1) * (k - 1) * mu * mu;
            }
    v /= 3.0 * s.width * s.height;
    b /= 3.0 * s.width * s.height;
}

ConvergenceResult synthetic_series(double scale, double& v_true, double& b_true) {
    SyntheticSpec spec;
    Bias bias;
    bias.scale = scale;
    bias.x1 = spec.width;
    bias.y1 = spec.height;
    std::vector<RgbImage> series;
    for (uint32_t spp : {4u, 16u, 64u, 256u}) {
        spec.spp = spp;
        series.push_back(synthetic_render(spec, 300 + spp, bias));
    }
    true_fit(spec, scale, v_true, b_true);
    return convergence(synthetic_reference(spec), series, 0.01);
}

} // namespace

TEST_CASE("convergence of an unbiased synthetic series: 1/spp, no plateau, V as predicted",
          "[compare][convergence]") {
    double v, b;
    const ConvergenceResult r = synthetic_series(1.0, v, b);
    INFO("V " << r.V << " +- " << r.V_stderr << " (true " << v << "), B " << r.B << " +- "
              << r.B_stderr << ", slope " << r.slope);
    CHECK_FALSE(r.biased);
    // 4 standard errors: a 6e-5 chance of a false failure for a normal estimate.
    CHECK(std::fabs(r.V - v) < 4 * r.V_stderr);
    CHECK(std::fabs(r.B) < 4 * r.B_stderr);
    // y(n) has ~3% relative error per point (3072 terms), so over a 64x range of n the
    // log-log slope is within +-0.05 of -1 at 4 sigma.
    CHECK(r.slope == Approx(-1.0).margin(0.05));
}

TEST_CASE("convergence of a 2% biased synthetic series: the plateau and its size",
          "[compare][convergence]") {
    double v, b;
    const ConvergenceResult r = synthetic_series(1.02, v, b);
    INFO("V " << r.V << " (true " << v << "), B " << r.B << " +- " << r.B_stderr << " (true " << b
              << "), slope " << r.slope);
    CHECK(r.biased);
    CHECK(std::fabs(r.B - b) < 4 * r.B_stderr);
    CHECK(std::fabs(r.V - v) < 4 * r.V_stderr);
    // sqrt(B) is the relative RMS bias: 2% on pixels much brighter than sqrt(eps) = 0.1.
    CHECK(r.relative_bias_rms() == Approx(std::sqrt(b)).epsilon(0.1));
}

TEST_CASE("twinpath compare --convergence on CPU renders: full depth converges, depth 1 "
          "levels off",
          "[compare][convergence][cli]") {
    // cornell 32x32: renders at 4..256 spp (one seed each) against a 2048-spp reference
    // with variance channels (its own noise is subtracted). --max-depth 1 drops all indirect
    // light: a bias of tens of percent that no spp removes.
    const std::string dir = temp_dir("convergence");
    RenderSpec ref;
    ref.width = ref.height = 32;
    ref.spp = 2048;
    ref.seed = 100;
    render_cpu_file(ref, dir + "/ref.exr");
    std::string full[2], direct;
    const uint32_t samplers[2] = {SAMPLER_RANDOM, SAMPLER_SOBOL};
    for (uint32_t spp : {4u, 16u, 64u, 256u}) {
        RenderSpec s = ref;
        s.spp = spp;
        s.seed = spp;
        for (int k = 0; k < 2; ++k) {
            s.sampler = samplers[k];
            const std::string file =
                fmt::format("{}/full_{}_{}.exr", dir, sampler_name(samplers[k]), spp);
            render_cpu_file(s, file);
            full[k] += " " + shell_quote(file);
        }
        s.max_depth = 1;
        render_cpu_file(s, fmt::format("{}/direct_{}.exr", dir, spp));
        direct += " " + shell_quote(fmt::format("{}/direct_{}.exr", dir, spp));
    }
    const std::string cmd = shell_quote(twinpath_bin()) + " compare --convergence --reference " +
                            shell_quote(dir + "/ref.exr") + " --json ";

    // Independent samples (random): y = V/n, a log-log slope of -1, within 0.15 for 4 points of
    // one seed each. Sobol (the default): scrambled nets make Var(mean) = o(1/n) (Owen 1997,
    // docs/sampling.md), so y falls at least as fast, a slope below -1 + 0.15; fitting V/n + B
    // to a faster fall puts B below 0, so the verdict is still "unbiased".
    for (int k = 0; k < 2; ++k) {
        const std::string json = fmt::format("{}/full_{}.json", dir, sampler_name(samplers[k]));
        const ProcessResult ok = run(cmd + shell_quote(json) + full[k]);
        INFO(sampler_name(samplers[k]) << ": " << ok.out);
        CHECK(ok.exit_code == 0);
        CHECK(ok.out.rfind("unbiased:", 0) == 0);
        const auto jf = nlohmann::json::parse(std::ifstream(json));
        const double slope = jf["fit"]["loglog_slope"].get<double>();
        if (samplers[k] == SAMPLER_RANDOM)
            CHECK(slope == Approx(-1.0).margin(0.15));
        else
            CHECK(slope < -1.0 + 0.15);
        CHECK(jf["points"].size() == 4);
    }

    const ProcessResult bad = run(cmd + shell_quote(dir + "/direct.json") + direct);
    INFO(bad.out);
    CHECK(bad.exit_code == 1);
    CHECK(bad.out.rfind("biased:", 0) == 0);
    const auto jd = nlohmann::json::parse(std::ifstream(dir + "/direct.json"));
    // Indirect light is a large share of a closed box: the RMS relative bias is > 10%.
    CHECK(jd["fit"]["relative_bias_rms"].get<double>() > 0.1);
    CHECK(jd["fit"]["loglog_slope"].get<double>() > -0.5);
}
