// One rendering as compare sees it: the R, G, B means and, when the file has them, the
// variance.R/G/B channels (variance of the mean, docs/design.md "Image output"), in double.
// Loading validates everything the statistics rely on; every failure is an InputError that
// names the file (exit 2).
#pragma once

#include "render/stats.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tp {

using Planes = std::array<std::vector<double>, 3>; // R, G, B; row-major, top row first

struct RgbImage {
    std::string path;
    int width = 0, height = 0;
    Planes mean;
    Planes var; // empty planes when the file has no variance channels
    // sample_variance.R/G/B (render/film.h): the per-sample variance of a batch-estimated
    // image, whose n var understates it; empty planes when the file has none.
    Planes sample_var;
    std::optional<int64_t> spp; // twinpath:spp, when the header has it
    // twinpath:variance_dof: degrees of freedom of the variance estimate when it is not the
    // sample variance of spp samples (spp - 1), e.g. K - 1 from K batch means (render/film.h).
    std::optional<int64_t> variance_dof;
    // twinpath:sample_ranges and twinpath:sampler (render/render_header.h): which samples of
    // which seed's sequence the image holds; empty when the header does not say (or says it in
    // a form compare cannot read: only the independence warning uses them).
    std::vector<SampleRange> sample_ranges;
    std::string sampler;

    bool has_variance() const { return !var[0].empty(); }
    bool has_sample_variance() const { return !sample_var[0].empty(); }
    size_t pixels() const { return size_t(width) * size_t(height); }
};

struct ExrImage;

// Reads R, G, B, variance.R/G/B and sample_variance.R/G/B from a file (rgb_image_from_exr).
// Rejects: a missing colour channel, variance or sample variance channels present for only some
// colours, NaN/Inf anywhere (counted per channel in the message), negative variances, an spp
// attribute below 1.
RgbImage load_rgb_image(const std::string& path);

// The same checks on an image already in memory (a render in the same process); `path` names
// it in messages.
RgbImage rgb_image_from_exr(const ExrImage& img, const std::string& path);

// Both images must have the same size: throws InputError naming both files.
void require_same_size(const RgbImage& a, const RgbImage& b);

} // namespace tp
