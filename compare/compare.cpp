#include "compare/compare.h"

#include "compare/display.h"
#include "compare/quality.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tp {

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
