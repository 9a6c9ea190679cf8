#include "render/film.h"

namespace tp {

Film::Film(uint32_t width, uint32_t height)
    : width_(width), height_(height), count_(size_t(width) * height, 0),
      mean_(size_t(width) * height, glm::dvec3(0.0)), m2_(size_t(width) * height, glm::dvec3(0.0)) {
}

void Film::add_sample(uint32_t p, const glm::dvec3& x) {
    const uint64_t n = ++count_[p];
    const glm::dvec3 delta = x - mean_[p];
    mean_[p] += delta / double(n);
    m2_[p] += delta * (x - mean_[p]);
}

void Film::add_batch(uint32_t p, uint64_t nb, const glm::dvec3& sum, const glm::dvec3& sum_sq) {
    if (nb == 0) return;
    const glm::dvec3 mean_b = sum / double(nb);
    // The batch's own M2 from its sums; clamped because round-off can make it slightly < 0.
    const glm::dvec3 m2_b = glm::max(sum_sq - sum * mean_b, glm::dvec3(0.0));
    const uint64_t na = count_[p];
    const double n = double(na + nb);
    const glm::dvec3 delta = mean_b - mean_[p];
    mean_[p] += delta * (double(nb) / n);
    m2_[p] += m2_b + delta * delta * (double(na) * double(nb) / n);
    count_[p] = na + nb;
}

void Film::merge(const Film& o) {
    for (size_t p = 0; p < count_.size(); ++p) {
        const uint64_t na = count_[p], nb = o.count_[p];
        if (nb == 0) continue;
        const double n = double(na + nb);
        const glm::dvec3 delta = o.mean_[p] - mean_[p];
        mean_[p] += delta * (double(nb) / n);
        m2_[p] += o.m2_[p] + delta * delta * (double(na) * double(nb) / n);
        count_[p] = na + nb;
    }
}

glm::dvec3 Film::variance_of_mean(uint32_t p) const {
    const uint64_t n = count_[p];
    if (n < 2) return glm::dvec3(0.0);
    return m2_[p] / (double(n - 1) * double(n));
}

ExrImage Film::to_exr() const {
    ExrImage img;
    img.width = int(width_);
    img.height = int(height_);
    const size_t n = size_t(width_) * height_;
    const char* names[3] = {"R", "G", "B"};
    const char* var_names[3] = {"variance.R", "variance.G", "variance.B"};
    for (int c = 0; c < 3; ++c) {
        auto& mean = img.channels[names[c]];
        auto& var = img.channels[var_names[c]];
        mean.resize(n);
        var.resize(n);
        for (size_t i = 0; i < n; ++i) {
            mean[i] = float(mean_[i][c]);
            var[i] = float(variance_of_mean(uint32_t(i))[c]);
        }
    }
    return img;
}

} // namespace tp
