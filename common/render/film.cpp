#include "render/film.h"

#include <algorithm>
#include <limits>

namespace tp {

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
    BatchSum& b = batch_[size_t(p) * batches_ + sample_index % batches_];
    b.sum += x;
    ++b.count;
}

void Film::add_batch(uint32_t p, uint64_t nb, const glm::dvec3& sum, const glm::dvec3& sum_sq,
                     uint32_t batch) {
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
    if (batches_ == 0) return;
    BatchSum& b = batch_[size_t(p) * batches_ + batch % batches_];
    b.sum += sum;
    b.count += nb;
}

uint64_t Film::pixel_dof(uint32_t p) const {
    if (batches_ == 0) return count_[p] > 0 ? count_[p] - 1 : 0;
    uint64_t filled = 0;
    for (uint32_t b = 0; b < batches_; ++b) filled += batch_[size_t(p) * batches_ + b].count > 0;
    return filled > 0 ? filled - 1 : 0;
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
    const double k = double(pixel_dof(p) + 1);
    if (k < 2.0) return glm::dvec3(0.0);
    glm::dvec3 total(0.0);
    uint64_t total_n = 0;
    for (uint32_t b = 0; b < batches_; ++b) {
        total += batch_[size_t(p) * batches_ + b].sum;
        total_n += batch_[size_t(p) * batches_ + b].count;
    }
    const glm::dvec3 mean = total / double(total_n);
    glm::dvec3 v(0.0);
    for (uint32_t b = 0; b < batches_; ++b) {
        const BatchSum& s = batch_[size_t(p) * batches_ + b];
        if (s.count == 0) continue;
        const glm::dvec3 d = (s.sum / double(s.count) - mean) * (double(s.count) / double(total_n));
        v += d * d;
    }
    return v * (k / (k - 1.0));
}

uint64_t Film::variance_dof() const {
    uint64_t dof = std::numeric_limits<uint64_t>::max();
    for (uint32_t p = 0; p < width_ * height_; ++p)
        if (const uint64_t d = pixel_dof(p); d > 0) dof = std::min(dof, d);
    return dof == std::numeric_limits<uint64_t>::max() ? 0 : dof;
}

ExrImage Film::to_exr() const {
    ExrImage img;
    img.width = int(width_);
    img.height = int(height_);
    const size_t n = size_t(width_) * height_;
    const char* names[3] = {"R", "G", "B"};
    const char* var_names[3] = {"variance.R", "variance.G", "variance.B"};
    std::vector<float>*mean[3], *var[3];
    for (int c = 0; c < 3; ++c) {
        mean[c] = &img.channels[names[c]];
        var[c] = &img.channels[var_names[c]];
        mean[c]->resize(n);
        var[c]->resize(n);
    }
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3 v = variance_of_mean(uint32_t(i));
        for (int c = 0; c < 3; ++c) {
            (*mean[c])[i] = float(mean_[i][c]);
            (*var[c])[i] = float(v[c]);
        }
    }
    img.strings["twinpath:variance_estimator"] = batches_ ? "batches" : "samples";
    // For the samples estimator readers take spp - 1 (compare/rgb_image.h); without a pixel of
    // two filled batches there is no estimate and nothing to record.
    if (batches_ && variance_dof() > 0)
        img.integers["twinpath:variance_dof"] = int64_t(variance_dof());
    return img;
}

} // namespace tp
