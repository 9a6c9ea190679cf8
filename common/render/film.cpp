#include "render/film.h"

#include "util/error.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tp {
namespace {

const char* const kColour[3] = {"R", "G", "B"};

} // namespace

FilmLayout film_layout_from_name(const std::string& name) {
    if (name == "lean") return FilmLayout::lean;
    if (name == "full") return FilmLayout::full;
    input_error("--film {}: expected lean or full", name);
}

const char* film_layout_name(FilmLayout layout) {
    return layout == FilmLayout::full ? "full" : "lean";
}

float lean_sample_variance(double s2) {
    if (!std::isfinite(s2) || s2 == 0.0) return float(s2);
    // s2 = m 2^e with m in [0.5, 1): keep m to 2^-11, round to nearest (ties to even).
    int e = 0;
    const double m = std::frexp(s2, &e);
    return float(std::ldexp(std::nearbyint(std::ldexp(m, 11)), e - 11));
}

std::string sample_variance_channel(int c) {
    return fmt::format("sample_variance.{}", kColour[c]);
}

std::string batch_channel(uint32_t batch, int c) {
    return fmt::format("batch{}.{}", batch, kColour[c]);
}

Film::Film(uint32_t width, uint32_t height, uint32_t batches)
    : width_(width), height_(height), batches_(batches), count_(size_t(width) * height, 0),
      mean_(size_t(width) * height, glm::dvec3(0.0)), m2_(size_t(width) * height, glm::dvec3(0.0)),
      batch_(size_t(width) * height * batches) {}

void Film::add_sample(uint32_t p, const glm::dvec3& x, uint32_t sample_index) {
    const uint64_t n = ++count_[p];
    const glm::dvec3 delta = x - mean_[p];
    mean_[p] += delta / double(n);
    m2_[p] += delta * (x - mean_[p]);
    if (batches_ == 0) return;
    BatchSum<glm::dvec3>& b = batch_[size_t(p) * batches_ + sample_index % batches_];
    b.sum += x;
    ++b.count;
}

void Film::add_batch(uint32_t p, uint64_t nb, const glm::dvec3& sum, const glm::dvec3& sum_sq,
                     uint32_t batch) {
    if (nb == 0) return;
    const glm::dvec3 mean_b = sum / double(nb);
    // The batch's own M2 from its sums; clamped because round-off can make it slightly < 0.
    const glm::dvec3 m2_b = glm::max(sum_sq - sum * mean_b, glm::dvec3(0.0));
    merge_moments(double(count_[p]), mean_[p], m2_[p], double(nb), mean_b, m2_b);
    count_[p] += nb;
    if (batches_ == 0) return;
    BatchSum<glm::dvec3>& b = batch_[size_t(p) * batches_ + batch % batches_];
    b.sum += sum;
    b.count += nb;
}

uint64_t Film::pixel_dof(uint32_t p) const {
    if (batches_ == 0) return count_[p] > 0 ? count_[p] - 1 : 0;
    const uint32_t filled = filled_batches(batches_of(p), batches_);
    return filled > 0 ? filled - 1 : 0;
}

void Film::merge(const Film& o) {
    for (size_t p = 0; p < count_.size(); ++p) {
        merge_moments(double(count_[p]), mean_[p], m2_[p], double(o.count_[p]), o.mean_[p],
                      o.m2_[p]);
        count_[p] += o.count_[p];
    }
    // Batch b of the union holds both films' samples of batch b (disjoint sample ranges).
    for (size_t i = 0; i < std::min(batch_.size(), o.batch_.size()); ++i) {
        batch_[i].sum += o.batch_[i].sum;
        batch_[i].count += o.batch_[i].count;
    }
}

glm::dvec3 Film::variance_of_mean(uint32_t p) const {
    const uint64_t n = count_[p];
    if (batches_ == 0) {
        if (n < 2) return glm::dvec3(0.0);
        return m2_[p] / (double(n - 1) * double(n));
    }
    return batch_variance_of_mean(batches_of(p), batches_);
}

uint64_t Film::variance_dof() const {
    uint64_t dof = std::numeric_limits<uint64_t>::max();
    for (uint32_t p = 0; p < width_ * height_; ++p)
        if (const uint64_t d = pixel_dof(p); d > 0) dof = std::min(dof, d);
    return dof == std::numeric_limits<uint64_t>::max() ? 0 : dof;
}

ExrImage Film::to_exr(FilmLayout layout) const {
    ExrImage img;
    img.width = int(width_);
    img.height = int(height_);
    const size_t n = size_t(width_) * height_;
    auto plane = [&](const std::string& name) {
        std::vector<float>& v = img.channels[name];
        v.resize(n);
        return v.data();
    };
    float *mean[3], *var[3];
    for (int c = 0; c < 3; ++c) {
        mean[c] = plane(kColour[c]);
        var[c] = plane(std::string("variance.") + kColour[c]);
    }
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3 v = variance_of_mean(uint32_t(i));
        for (int c = 0; c < 3; ++c) {
            mean[c][i] = float(mean_[i][c]);
            var[c][i] = float(v[c]);
        }
    }
    img.strings["twinpath:variance_estimator"] = batches_ ? "batches" : "samples";
    img.strings["twinpath:film"] = film_layout_name(layout);
    if (batches_ == 0) return img;
    // For the samples estimator readers take spp - 1 (compare/rgb_image.h); without a pixel of
    // two filled batches there is no estimate and nothing to record.
    if (variance_dof() > 0) img.integers["twinpath:variance_dof"] = int64_t(variance_dof());
    for (int c = 0; c < 3; ++c) {
        float* s2 = plane(sample_variance_channel(c));
        for (size_t i = 0; i < n; ++i) {
            const double v = count_[i] > 1 ? m2_[i][c] / double(count_[i] - 1) : 0.0;
            s2[i] = layout == FilmLayout::full ? float(v) : lean_sample_variance(v);
        }
        if (layout == FilmLayout::lean) continue;
        for (uint32_t b = 0; b < batches_; ++b) {
            float* mean_b = plane(batch_channel(b, c));
            for (size_t i = 0; i < n; ++i) {
                const BatchSum<glm::dvec3>& s = batches_of(uint32_t(i))[b];
                mean_b[i] = s.count > 0 ? float(s.sum[c] / double(s.count)) : 0.0f;
            }
        }
    }
    return img;
}

} // namespace tp
