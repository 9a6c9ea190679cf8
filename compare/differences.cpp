#include "compare/differences.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace tp {

double Differences::dof(int c, size_t i) const {
    const double w = welch[size_t(c)][i];
    if (w <= 0.0) return std::numeric_limits<double>::infinity();
    const double v = var[size_t(c)][i];
    return v * v / w;
}

double floor_variance(double a, double b, double channel_scale, double relative_floor) {
    const double m = std::max(std::fabs(a), std::fabs(b));
    return relative_floor * relative_floor * (m * m + channel_scale * channel_scale);
}

std::string borrowing_sentence(const Differences& d) {
    if (d.rule.borrower == VarianceRule::None) return "equal spp: each image's own variance";
    const bool a = d.rule.borrower == VarianceRule::A;
    return fmt::format("{} ({}x fewer samples) took {}'s per-sample variance where it was larger: "
                       "{} of {} pixel-channels, {} of {} pixels",
                       a ? "A" : "B", d.rule.ratio, a ? "B" : "A", d.variance_borrowed,
                       3 * d.borrowed.size(), d.pixels_borrowed, d.borrowed.size());
}

PairVariance pair_variance(const VarianceRule& rule, const SideVariance& a, const SideVariance& b) {
    PairVariance out;
    double va = a.var, vb = b.var, va2 = a.var2, vb2 = b.var2;
    double ka = rule.inv_dof_a, kb = rule.inv_dof_b;
    if (rule.borrower == VarianceRule::A && b.lend * rule.ratio > va) {
        va = b.lend * rule.ratio;
        va2 = b.lend2 * rule.ratio * rule.ratio;
        ka = rule.inv_dof_lend_b;
        out.borrowed = true;
    } else if (rule.borrower == VarianceRule::B && a.lend * rule.ratio > vb) {
        vb = a.lend * rule.ratio;
        vb2 = a.lend2 * rule.ratio * rule.ratio;
        kb = rule.inv_dof_lend_a;
        out.borrowed = true;
    }
    out.var = va + vb;
    out.welch = va2 * ka + vb2 * kb;
    return out;
}

Differences compute_differences(const RgbImage& a, const RgbImage& b, double relative_floor) {
    Differences out;
    out.width = a.width;
    out.height = a.height;
    const size_t n = a.pixels();
    // Degrees of freedom of each variance estimate: the header's twinpath:variance_dof (K - 1
    // for K batch means), else n - 1 for the unbiased sample variance. Without either the
    // estimate is taken as exact (normal p-values).
    auto inv_dof = [](const RgbImage& img) {
        if (img.variance_dof) return 1.0 / double(*img.variance_dof);
        return img.spp ? 1.0 / double(std::max<int64_t>(*img.spp - 1, 1)) : 0.0;
    };
    // What an image lends: its sample_variance over its own n with n - 1 degrees of freedom
    // where it has one, else its variance of the mean with that estimate's.
    auto inv_dof_lend = [&](const RgbImage& img) {
        return img.has_sample_variance() && img.spp
                   ? 1.0 / double(std::max<int64_t>(*img.spp - 1, 1))
                   : inv_dof(img);
    };
    auto lend = [](const RgbImage& img, size_t c, size_t i) {
        if (!img.has_variance()) return 0.0;
        if (img.has_sample_variance() && img.spp) return img.sample_var[c][i] / double(*img.spp);
        return img.var[c][i];
    };
    VarianceRule& rule = out.rule;
    rule.inv_dof_a = inv_dof(a);
    rule.inv_dof_b = inv_dof(b);
    rule.inv_dof_lend_a = inv_dof_lend(a);
    rule.inv_dof_lend_b = inv_dof_lend(b);
    // The side with strictly fewer samples borrows, when both images have variance and spp.
    if (a.has_variance() && b.has_variance() && a.spp && b.spp && *a.spp != *b.spp) {
        rule.borrower = *a.spp < *b.spp ? VarianceRule::A : VarianceRule::B;
        rule.ratio = rule.borrower == VarianceRule::A ? double(*b.spp) / double(*a.spp)
                                                      : double(*a.spp) / double(*b.spp);
    }
    out.borrowed.assign(n, 0);
    for (size_t c = 0; c < 3; ++c) {
        double scale = 0.0;
        for (size_t i = 0; i < n; ++i)
            scale += std::max(std::fabs(a.mean[c][i]), std::fabs(b.mean[c][i]));
        scale /= double(n);
        for (Planes* p : {&out.d, &out.var_a, &out.var_b, &out.lend_a, &out.lend_b, &out.floor,
                          &out.noise, &out.var, &out.welch})
            (*p)[c].resize(n);
        for (size_t i = 0; i < n; ++i) {
            const double va = a.has_variance() ? a.var[c][i] : 0.0;
            const double vb = b.has_variance() ? b.var[c][i] : 0.0;
            const double la = lend(a, c, i), lb = lend(b, c, i);
            const PairVariance pv =
                pair_variance(rule, {va, va * va, la, la * la}, {vb, vb * vb, lb, lb * lb});
            out.d[c][i] = a.mean[c][i] - b.mean[c][i];
            out.var_a[c][i] = va;
            out.var_b[c][i] = vb;
            out.lend_a[c][i] = la;
            out.lend_b[c][i] = lb;
            out.floor[c][i] = floor_variance(a.mean[c][i], b.mean[c][i], scale, relative_floor);
            out.noise[c][i] = pv.var;
            out.var[c][i] = pv.var + out.floor[c][i];
            out.welch[c][i] = pv.welch;
            out.at_floor += (va + vb == 0.0);
            out.variance_borrowed += pv.borrowed;
            out.borrowed[i] |= uint8_t(pv.borrowed);
        }
    }
    out.pixels_borrowed = size_t(std::count(out.borrowed.begin(), out.borrowed.end(), 1));
    return out;
}

} // namespace tp
