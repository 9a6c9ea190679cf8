// Double-precision film: per pixel and channel the sample count, running mean and sum of
// squared deviations (Welford 1962), so that mean and variance keep full precision at 10^6
// samples. Batches from another accumulator (the GPU's per-pixel sums) merge with the
// pairwise update of Chan, Golub & LeVeque (1979), render/moments.h.
//
// The variance of the mean comes from one of two estimators (docs/sampling.md):
// - samples: the unbiased sample variance over n, n - 1 degrees of freedom; valid when a
//   pixel's samples are independent (the random sampler).
// - batches: sample s goes to batch s mod K, each batch an independent randomization of a
//   low-discrepancy sequence (the Sobol sampler, shared/rng.h). Within a batch the samples are
//   not independent, so their spread says nothing about the error of their mean; the batch
//   means are independent, and the random-group estimator (render/moments.h) over the K'
//   batches that have samples estimates it with K' - 1 degrees of freedom.
#pragma once

#include "image/exr_io.h"
#include "render/moments.h"
#include "shared/lang.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tp {

// What a batch-estimated film writes besides R, G, B, variance.R/G/B and
// sample_variance.R/G/B (docs/design.md, "Files"; docs/sampling.md, "What the file keeps"):
// - lean (the default): nothing more, and sample_variance.* rounded to 11 significant bits:
//   what `compare` reads, at 1.4x the bytes of a random-sampler file;
// - full: sample_variance.* in float32 and the mean of every batch, batchB.R/G/B, which
//   `merge` needs to rebuild the batch estimate of several parts exactly.
// A samples-estimated film (the random sampler) writes the same channels in both.
enum class FilmLayout { lean, full };

// "lean", "full"; anything else is an InputError naming --film.
FilmLayout film_layout_from_name(const std::string& name);
const char* film_layout_name(FilmLayout layout);

// A sample variance as the lean film stores it: rounded to nearest with 11 significant bits
// (half precision's), kept in float32's range. Its relative error, at most 2^-11, is below the
// statistical error of a sample variance, sqrt(2 / (n - 1)) for Gaussian samples, up to
// n = 8 * 10^6 samples.
float lean_sample_variance(double s2);

// The channels a batch-estimated film writes besides R, G, B and variance.R/G/B
// (docs/design.md, "Files"; docs/sampling.md): the unbiased sample variance of the pixel's samples,
// an estimate of the variance of one sample's marginal distribution, and the mean of each
// batch. c is 0, 1, 2 for R, G, B.
std::string sample_variance_channel(int c);       // "sample_variance.R"
std::string batch_channel(uint32_t batch, int c); // "batch3.G"

class Film {
  public:
    Film() = default;
    // batches = 0: the samples estimator; K > 0: the batch estimator with K batches.
    Film(uint32_t width, uint32_t height, uint32_t batches = 0);

    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    uint32_t batches() const { return batches_; }

    // Sample `sample_index` of pixel p. Pixels are independent, so threads may add to
    // different pixels.
    void add_sample(uint32_t p, const glm::dvec3& value, uint32_t sample_index = 0);

    // n samples of pixel p with the given sum and sum of squares per channel, all of them in
    // batch `batch` (read only by the batch estimator).
    void add_batch(uint32_t p, uint64_t n, const glm::dvec3& sum, const glm::dvec3& sum_sq,
                   uint32_t batch = 0);

    // Every pixel of another film of the same size (its samples are added to this one's), by
    // the same pairwise update.
    void merge(const Film& other);

    uint64_t count(uint32_t p) const { return count_[p]; }
    glm::dvec3 mean(uint32_t p) const { return mean_[p]; }
    // Variance of the mean by the film's estimator; 0 below 2 samples (2 filled batches).
    glm::dvec3 variance_of_mean(uint32_t p) const;
    // Degrees of freedom of that estimate over the image: the smallest n - 1 (K' - 1) of the
    // pixels that have an estimate, 0 when none has.
    uint64_t variance_dof() const;

    // R, G, B and variance.R/G/B channels, float32 (docs/design.md, "Files"), the estimator in
    // twinpath:variance_estimator ("samples" or "batches") and the layout in twinpath:film; for
    // batches also twinpath:variance_dof and sample_variance.R/G/B, so that compare can borrow
    // a per-sample variance, and in the full layout batchB.R/G/B for B < K, so that merge can
    // rebuild the batch estimate of several parts exactly (docs/sampling.md).
    ExrImage to_exr(FilmLayout layout = FilmLayout::lean) const;

  private:
    uint64_t pixel_dof(uint32_t p) const;
    const BatchSum<glm::dvec3>* batches_of(uint32_t p) const {
        return &batch_[size_t(p) * batches_];
    }

    uint32_t width_ = 0, height_ = 0, batches_ = 0;
    std::vector<uint64_t> count_;
    std::vector<glm::dvec3> mean_;
    std::vector<glm::dvec3> m2_;
    std::vector<BatchSum<glm::dvec3>> batch_; // width * height * batches, pixel-major
};

} // namespace tp
