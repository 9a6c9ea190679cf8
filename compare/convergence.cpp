#include "compare/convergence.h"

#include "compare/distributions.h"
#include "compare/metrics.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace tp {
namespace {

ConvergencePoint measure(const RgbImage& img, const RgbImage& ref, double& reference_noise) {
    ConvergencePoint p;
    p.path = img.path;
    p.spp = *img.spp;
    const size_t n = img.pixels();
    // Per pixel the sum over channels: pixels are independent, channels are not, so the
    // standard error comes from the spread over pixels.
    double sum = 0, sum_sq = 0, ref_noise = 0, predicted = 0;
    for (size_t i = 0; i < n; ++i) {
        double term = 0;
        for (size_t c = 0; c < 3; ++c) {
            const double r = ref.mean[c][i], d = img.mean[c][i] - r;
            const double w = 1.0 / (r * r + kRelativeEpsilon);
            term += w * d * d;
            if (ref.has_variance()) ref_noise += w * ref.var[c][i];
            if (img.has_variance()) predicted += w * img.var[c][i];
        }
        sum += term;
        sum_sq += term * term;
    }
    const double count = 3.0 * double(n);
    const double mean_term = sum / double(n);
    const double var_term = std::max(0.0, (sum_sq - sum * mean_term) / double(n - 1));
    reference_noise = ref_noise / count;
    p.relmse = sum / count;
    p.excess = p.relmse - reference_noise;
    p.excess_stderr = std::sqrt(var_term / double(n)) / 3.0;
    p.noise_predicted = predicted / count;
    return p;
}

} // namespace

double ConvergenceResult::relative_bias_rms() const {
    return std::sqrt(std::max(B, 0.0));
}

ConvergenceResult convergence(const RgbImage& reference, const std::vector<RgbImage>& series,
                              double alpha) {
    ConvergenceResult r;
    r.alpha = alpha;
    std::set<int64_t> distinct;
    for (const RgbImage& img : series) {
        if (!img.spp)
            input_error("{}: no twinpath:spp attribute; --convergence needs each image's spp",
                        img.path);
        require_same_size(img, reference);
        if (img.pixels() < 2) input_error("{}: --convergence needs at least 2 pixels", img.path);
        distinct.insert(*img.spp);
        r.points.push_back(measure(img, reference, r.reference_noise));
    }
    if (distinct.size() < 2)
        input_error("--convergence needs renderings at two or more different spp (got {})",
                    distinct.size());
    std::sort(r.points.begin(), r.points.end(),
              [](const ConvergencePoint& a, const ConvergencePoint& b) { return a.spp < b.spp; });

    // Weighted least squares for y = V x + B, x = 1/n. Under H0 the standard error of y(n)
    // falls like 1/n (y is a mean of squared errors ~ V/n), so the weights are n^2: fixed by
    // the design, not by the noisy per-point estimates, which with fireflies are correlated
    // with y itself (a point that missed a firefly has a small y and a small se, would get a
    // large weight and pull V down and B up). The one scale s, se(y(n)) = s/n, is pooled
    // over the points; kurtosis makes s*n larger at low spp, so pooling errs on the
    // conservative side at high spp, where B is decided.
    double s2 = 0;
    for (const ConvergencePoint& p : r.points) {
        const double sn = p.excess_stderr * double(p.spp);
        s2 += sn * sn / double(r.points.size());
    }
    if (s2 == 0) return r; // every rendering equals the reference: V = B = 0, p = 1
    double sw = 0, sx = 0, sxx = 0, sy = 0, sxy = 0;
    for (const ConvergencePoint& p : r.points) {
        const double n = double(p.spp), w = n * n / s2, x = 1.0 / n;
        sw += w;
        sx += w * x;
        sxx += w * x * x;
        sy += w * p.excess;
        sxy += w * x * p.excess;
    }
    // The inverse of the normal equations' matrix is the covariance of (V, B).
    const double det = sw * sxx - sx * sx;
    r.V = (sw * sxy - sx * sy) / det;
    r.B = (sxx * sy - sx * sxy) / det;
    r.V_stderr = std::sqrt(sw / det);
    r.B_stderr = std::sqrt(sxx / det);
    r.p_value = normal_upper(r.B / r.B_stderr);
    r.biased = r.p_value <= alpha;

    double n = 0, lx = 0, ly = 0, lxx = 0, lxy = 0;
    for (const ConvergencePoint& p : r.points)
        if (p.excess > 0) {
            const double x = std::log(double(p.spp)), y = std::log(p.excess);
            n += 1;
            lx += x;
            ly += y;
            lxx += x * x;
            lxy += x * y;
        }
    const double ldet = n * lxx - lx * lx;
    r.slope = ldet > 0 ? (n * lxy - lx * ly) / ldet : std::nan("");
    return r;
}

nlohmann::json convergence_json(const ConvergenceResult& r, const RgbImage& reference) {
    nlohmann::json j;
    j["verdict"] = r.biased ? "biased" : "unbiased";
    j["alpha"] = r.alpha;
    j["p_value"] = r.p_value;
    j["reference"] = {{"path", reference.path},
                      {"has_variance", reference.has_variance()},
                      {"relmse_noise", r.reference_noise}};
    j["model"] = "relMSE(n) - reference noise = V / n + B";
    j["fit"] = {{"V", r.V},
                {"V_stderr", r.V_stderr},
                {"B", r.B},
                {"B_stderr", r.B_stderr},
                {"relative_bias_rms", r.relative_bias_rms()},
                {"loglog_slope", std::isfinite(r.slope) ? nlohmann::json(r.slope) : nullptr}};
    j["epsilon"] = kRelativeEpsilon;
    nlohmann::json pts = nlohmann::json::array();
    for (const ConvergencePoint& p : r.points)
        pts.push_back({{"path", p.path},
                       {"spp", p.spp},
                       {"relmse", p.relmse},
                       {"excess", p.excess},
                       {"excess_stderr", p.excess_stderr},
                       {"relmse_noise_predicted", p.noise_predicted}});
    j["points"] = pts;
    return j;
}

std::string convergence_verdict_line(const ConvergenceResult& r) {
    const std::string shape =
        r.biased ? fmt::format("relMSE levels off at {:.3g} +- {:.2g}: relative RMS bias {:.3g}",
                               r.B, r.B_stderr, r.relative_bias_rms())
                 : fmt::format("no plateau (B = {:.3g} +- {:.2g})", r.B, r.B_stderr);
    return fmt::format("{}: p = {:.3g} at alpha {}; {} over {} renderings ({}..{} spp); "
                       "relMSE ~ spp^{:.2f}",
                       r.biased ? "biased" : "unbiased", r.p_value, r.alpha, shape, r.points.size(),
                       r.points.front().spp, r.points.back().spp, r.slope);
}

} // namespace tp
