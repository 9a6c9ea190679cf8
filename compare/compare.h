// compare's verdict: do two renderings estimate the same image? (docs/compare.md)
//
// Two-sample mode (both images have variance channels): the local pixel test (pixel_test.h)
// at level alpha/2 and the global tile test (tile_test.h) at alpha/2; by Bonferroni the
// family-wise false-alarm rate is at most alpha, and the combined p-value is
// min(1, 2 min(p_local, p_global)).
//
// Reference mode (one image without variance, taken as exact): the verdict is the global
// tile test alone at level alpha, with tiles of at least kReferenceTileSamples samples. With
// one sample the statistic is no longer symmetric: for right-skewed radiance (fireflies) a mean
// below the truth comes with a variance estimate that is too small, and the lower tail of t
// is far heavier than Student's; the error term of its Edgeworth expansion is gamma/sqrt(N)
// for skewness gamma and N samples (Hall 1987, "Edgeworth expansion for Student's t statistic
// under minimal moment conditions"). Per pixel (N = spp) that error is hopeless at Holm's
// thresholds, so the pixel test is computed for the report but marked advisory; per tile, N
// grows with the tile's area until the error is small.
#pragma once

#include "compare/differences.h"
#include "compare/metrics.h"
#include "compare/pixel_test.h"
#include "compare/tile_test.h"

#include <optional>
#include <string>
#include <vector>

namespace tp {

// Samples per tile in reference mode: 2^16 keeps gamma / sqrt(N) <= 0.04 up to a skewness of
// gamma ~ 10 (the firefly mixture of the tests; lognormal sigma = 1 has 6.2). The tile side
// grows to ceil(sqrt(2^16 / spp)) when spp is known: the whole of a 64x64 image at 16 spp,
// 8x8 from 1024 spp on.
constexpr double kReferenceTileSamples = 65536.0;

struct CompareOptions {
    double alpha = 0.01;
    int tile = kDefaultTile;
    double relative_floor = kDefaultRelativeFloor;
};

enum class CompareMode { TwoSample, Reference };

struct CompareResult {
    CompareMode mode = CompareMode::TwoSample;
    double alpha = 0.01;
    Differences diff;
    PixelTest local; // Holm at local_level
    TileTest global;
    double local_level = 0, global_level = 0;
    double floor_relative = 0;
    bool reference_is_a = false; // the image relative metrics divide by: the exact one, else B
    ErrorMetrics metrics;
    float exposure = 0; // display exposure (stops) shared by the report and the PSNR
    std::optional<double> psnr;
    double p_value = 1.0;
    bool different = false;
    std::vector<std::string> warnings; // what weakens the test (missing spp), for stderr + JSON

    bool local_in_verdict() const { return mode == CompareMode::TwoSample; }
};

// Throws InputError when neither image has variance channels or the sizes differ.
CompareResult compare_images(const RgbImage& a, const RgbImage& b, const CompareOptions& opt);

} // namespace tp
