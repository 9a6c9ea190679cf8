#include "compare/compare.h"

#include "compare/display.h"
#include "compare/quality.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace tp {
namespace {

// Two renderings that share samples of one seed's sequence with the same sampler trace the same
// paths there (shared/rng.h): their difference is not that of independent estimates, which
// every test here assumes, and at the extreme (a file against itself) it is 0 whatever the
// images hold.
std::optional<std::string> shared_samples(const RgbImage& a, const RgbImage& b) {
    if (a.sampler.empty() || a.sampler != b.sampler) return std::nullopt;
    for (const SampleRange& ra : a.sample_ranges)
        for (const SampleRange& rb : b.sample_ranges)
            if (ra.seed == rb.seed && ra.begin < rb.end && rb.begin < ra.end)
                return fmt::format(
                    "{} and {} share samples {} to {} of seed {} ({} sampler): they trace the "
                    "same paths there, so the test's independence does not hold and "
                    "\"consistent\" proves nothing; render one of them with another --seed",
                    a.path, b.path, std::max(ra.begin, rb.begin), std::min(ra.end, rb.end) - 1,
                    ra.seed, a.sampler);
    return std::nullopt;
}

} // namespace

CompareResult compare_images(const RgbImage& a, const RgbImage& b, const CompareOptions& opt) {
    require_same_size(a, b);
    if (!a.has_variance() && !b.has_variance())
        input_error("neither {} nor {} has variance.R/G/B channels: a statistical comparison "
                    "needs the variance of at least one image (use --exact for deterministic "
                    "images)",
                    a.path, b.path);
    CompareResult r;
    r.alpha = opt.alpha;
    r.mode = a.has_variance() && b.has_variance() ? CompareMode::TwoSample : CompareMode::Reference;
    const bool two = r.mode == CompareMode::TwoSample;
    r.local_level = two ? opt.alpha / 2.0 : opt.alpha;
    r.global_level = two ? opt.alpha / 2.0 : opt.alpha;
    r.floor_relative = opt.relative_floor;
    r.diff = compute_differences(a, b, opt.relative_floor);
    r.local = pixel_test(r.diff, r.local_level);
    for (const RgbImage* img : {&a, &b})
        if (img->has_variance() && !img->spp)
            r.warnings.push_back(fmt::format(
                "{} has no twinpath:spp: its variance is taken as exact (normal p-values{})",
                img->path, two ? "" : ", tiles not enlarged"));
    if (std::optional<std::string> w = shared_samples(a, b)) r.warnings.push_back(*w);
    int tile = opt.tile;
    const RgbImage& noisy = a.has_variance() ? a : b;
    if (!two && noisy.spp)
        tile =
            std::max(tile, int(std::ceil(std::sqrt(kReferenceTileSamples / double(*noisy.spp)))));
    r.global = tile_test(r.diff, std::min(tile, std::max(a.width, a.height)));
    r.p_value = two ? std::min(1.0, 2.0 * std::min(r.local.holm.p_value, r.global.p_value))
                    : r.global.p_value;
    r.different = r.p_value <= opt.alpha;

    r.reference_is_a = !a.has_variance();
    const RgbImage& ref = r.reference_is_a ? a : b;
    r.metrics = error_metrics(a, b, ref);
    r.exposure = auto_exposure(ref);
    r.psnr = display_psnr(r.reference_is_a ? b : a, ref, r.exposure);
    return r;
}

} // namespace tp
