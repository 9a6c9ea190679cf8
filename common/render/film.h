// Double-precision film: per pixel and channel the sample count, running mean and sum of
// squared deviations (Welford 1962), so that mean and variance keep full precision at 10^6
// samples. Batches from another accumulator (the GPU's per-pixel sums) merge with the
// pairwise update of Chan, Golub & LeVeque (1979).
#pragma once

#include "image/exr_io.h"
#include "shared/lang.h"

#include <cstdint>
#include <vector>

namespace tp {

class Film {
  public:
    Film() = default;
    Film(uint32_t width, uint32_t height);

    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }

    // One sample of pixel p. Pixels are independent, so threads may add to different pixels.
    void add_sample(uint32_t p, const glm::dvec3& value);

    // n samples of pixel p with the given sum and sum of squares per channel.
    void add_batch(uint32_t p, uint64_t n, const glm::dvec3& sum, const glm::dvec3& sum_sq);

    // Every pixel of another film of the same size (its samples are added to this one's), by
    // the same pairwise update.
    void merge(const Film& other);

    uint64_t count(uint32_t p) const { return count_[p]; }
    glm::dvec3 mean(uint32_t p) const { return mean_[p]; }
    // Variance of the mean: the unbiased sample variance divided by n; 0 below 2 samples.
    glm::dvec3 variance_of_mean(uint32_t p) const;

    // R, G, B and variance.R/G/B channels, float32 (DESIGN.md, "Image output").
    ExrImage to_exr() const;

  private:
    uint32_t width_ = 0, height_ = 0;
    std::vector<uint64_t> count_;
    std::vector<glm::dvec3> mean_;
    std::vector<glm::dvec3> m2_;
};

} // namespace tp
