// Same-seed comparisons: both engines draw bit-identical random numbers for a path (rng.h) and
// apply the same shared per-vertex rules, so two renders of one scene with one seed and spp
// follow the same paths. A pixel then differs only by float rounding (the hit point and t of
// Embree and of the compute traversal differ in the last bits), unless a path takes a different
// discrete decision: a ray that hits on one engine and misses on the other, a shadow ray
// occluded on one only. Such a pixel moves by about one sample's value / spp; the case reports
// how many pixels differ by more than `kTolerance` relative and the first of them, which is the
// starting point for a path log (--debug-pixel, twinpath pathdiff).
#include "stress/common.h"

#include <fmt/format.h>

#include <cmath>

namespace tp::stress {
namespace {

// Relative difference above which a pixel counts as diverged. Float rounding of the same paths
// stays orders of magnitude below; one diverged sample of a 64-spp pixel moves it by ~1/64.
constexpr double kTolerance = 2e-3;

void expect_twins(CaseResult& c, const Rendered& a, const Rendered& b, uint64_t allowed) {
    c.nan +=
        a.r.stats.nan_samples + a.nonfinite_pixels + b.r.stats.nan_samples + b.nonfinite_pixels;
    c.checked = a.r.stats.samples + b.r.stats.samples;
    const Film& fa = a.r.film;
    const Film& fb = b.r.film;
    uint64_t diverged = 0;
    double worst = 0.0;
    std::string first;
    for (uint32_t p = 0; p < fa.width() * fa.height(); ++p) {
        const glm::dvec3 ma = fa.mean(p), mb = fb.mean(p);
        double rel = 0.0;
        for (int ch = 0; ch < 3; ++ch)
            rel = std::max(rel, std::abs(ma[ch] - mb[ch]) /
                                    std::max(1e-3, std::max(std::abs(ma[ch]), std::abs(mb[ch]))));
        worst = std::max(worst, rel);
        if (rel > kTolerance) {
            if (diverged == 0)
                first = fmt::format("first at pixel ({}, {}): {:.6g} vs {:.6g}", p % fa.width(),
                                    p / fa.width(), ma.x, mb.x);
            ++diverged;
        }
    }
    c.pass = c.nan == 0 && diverged <= allowed;
    c.measured = fmt::format("{} of {} pixels differ by more than {:.0e} relative (allowed {}), "
                             "worst {:.3g}{}{}",
                             diverged, fa.width() * fa.height(), kTolerance, allowed, worst,
                             first.empty() ? "" : "; ", first);
}

} // namespace

std::vector<CaseResult> twin_cases(const Engine& a, const Engine& b, const Size& s) {
    std::vector<CaseResult> out;
    auto make = [&](const std::string& name) {
        CaseResult c =
            make_case("twin", name, a,
                      fmt::format("the same pixels as {}/{} for the same seed", b.backend, b.mode));
        c.mode = a.mode + " vs " + b.backend + "/" + b.mode;
        return c;
    };
    const Scene base = reference_scene(s.image, s.spp);
    // Where the closed box's leak showed: every pixel the same (no allowance: the box and
    // walls are far from grazing configurations that could legitimately diverge).
    out.push_back(timed(make("lights inside a closed box"), [&](CaseResult& c) {
        const FlatScene f = flatten(closed_box_scene(base, true));
        expect_twins(c, render(a, f, 203), render(b, f, 203), 0);
    }));
    out.push_back(timed(make("smooth low-poly furnace"), [&](CaseResult& c) {
        double cos_min = 1.0;
        const FlatScene f = flatten(smooth_furnace_scene(s, 0.8f, cos_min));
        expect_twins(c, render(a, f, 301), render(b, f, 301), 0);
    }));
    return out;
}

} // namespace tp::stress
