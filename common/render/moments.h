// The moments of a pixel's samples that the film keeps and `merge` combines (docs/sampling.md):
// count, mean and sum of squared deviations M2, merged by the pairwise update, and the batch
// sums of the random-group estimator of the variance of the mean. T is double (one channel) or
// glm::dvec3 (R, G, B).
#pragma once

#include <cstdint>

namespace tp {

// Adds n_b samples with mean mean_b and sum of squared deviations m2_b to n_a samples with
// mean `mean` and `m2` (Chan, Golub & LeVeque, "Updating formulae and a pairwise algorithm for
// computing sample variances", 1979, eq. 2.1):
//   d = mean_b - mean,  mean += d n_b / n,  m2 += m2_b + d^2 n_a n_b / n,  n = n_a + n_b.
// The caller keeps the count.
template <class T>
void merge_moments(double n_a, T& mean, T& m2, double n_b, const T& mean_b, const T& m2_b) {
    if (n_b <= 0.0) return;
    const double n = n_a + n_b;
    const T d = mean_b - mean;
    mean += d * (n_b / n);
    m2 += m2_b + d * d * (n_a * n_b / n);
}

// The sum and count of the samples of one batch (sample s in batch s mod K).
template <class T>
struct BatchSum {
    T sum{};
    uint64_t count = 0;
};

// Batches that received samples: K'. The random-group estimator below has K' - 1 degrees of
// freedom.
template <class T>
uint32_t filled_batches(const BatchSum<T>* batches, uint32_t k) {
    uint32_t filled = 0;
    for (uint32_t b = 0; b < k; ++b) filled += batches[b].count > 0;
    return filled;
}

// The random-group estimator of the variance of the mean over the K' filled batches of n_b
// samples each, N in all (Wolter, "Introduction to Variance Estimation", 2nd ed., 2007, ch. 2):
//   Var(mean) = K' / (K' - 1) sum_b (n_b / N)^2 (mean_b - mean)^2,
// the sample variance of the batch means over K' when the n_b are equal. 0 below K' = 2.
template <class T>
T batch_variance_of_mean(const BatchSum<T>* batches, uint32_t k) {
    const double filled = double(filled_batches(batches, k));
    if (filled < 2.0) return T(0.0);
    T total(0.0);
    uint64_t n = 0;
    for (uint32_t b = 0; b < k; ++b) {
        total += batches[b].sum;
        n += batches[b].count;
    }
    const T mean = total / double(n);
    T v(0.0);
    for (uint32_t b = 0; b < k; ++b) {
        if (batches[b].count == 0) continue;
        const double w = double(batches[b].count) / double(n);
        const T d = (batches[b].sum / double(batches[b].count) - mean) * w;
        v += d * d;
    }
    return v * (filled / (filled - 1.0));
}

} // namespace tp
