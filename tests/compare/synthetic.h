// Synthetic renderings with known noise: every pixel's samples are drawn from a chosen
// distribution around a known mean image and accumulated by the renderer's own Film (Welford
// mean and variance of the mean, float32 output), so the images carry exactly the estimates a
// real render carries, while the truth is known.
#pragma once

#include "compare/rgb_image.h"

#include <cstdint>

namespace tp::test {

enum class Noise {
    Gaussian,  // Y = 1 + 0.5 N(0,1)
    Lognormal, // Y = exp(s N - s^2/2), s = 1: skewness 6.2, a heavy right tail
    Pareto,    // Y = 0.6 (1-U)^(-1/2.5): tail index 2.5, infinite third moment
    Firefly,   // Y = 0.5 (1 + 0.3 N) + 50 Bernoulli(0.01): rare huge samples
    Caustic,   // Y = 0.5 (1 + 0.3 N) + (0.5 / q) Bernoulli(q), q from 1e-4 to 1e-1 by pixel
               // (caustic_probability): half of every pixel's light comes in rare samples,
               // some of them far rarer than 1 / spp
};

struct SyntheticSpec {
    int width = 32, height = 32;
    uint32_t spp = 16;
    Noise noise = Noise::Gaussian;
    bool correlated_channels = false; // one Y for R, G, B (same path), else one per channel
    // > 0: the film's batch estimator with this many batches (render/film.h), and the uniform
    // that drives each sample's distribution (its quantile, or the rare sample's coin)
    // stratified within its batch, u = (j + U) / n_b for the batch's j-th of n_b samples: a
    // randomized quasi-Monte Carlo stand-in whose sample variance overstates the error.
    uint32_t batches = 0;
};

// Caustic noise: the probability q of a pixel's rare sample, log-uniform in [1e-4, 1e-1] over
// the pixels in a fixed scattered order (the same in every rendering of the spec).
double caustic_probability(int x, int y);

// The true mean image: a smooth colour gradient, black (exactly 0, no noise) in the 2 leftmost
// columns so that zero-variance pixels are part of every test.
double true_mean(const SyntheticSpec& s, int channel, int x, int y);

// A rendering of the true mean with the given noise; spp recorded as twinpath:spp (and
// twinpath:variance_dof by the film, with batches).
// `scale` multiplies the true mean inside the rectangle [x0, x1) x [y0, y1) (a known bias).
struct Bias {
    double scale = 1.0;
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
RgbImage synthetic_render(const SyntheticSpec& s, uint64_t seed, const Bias& bias = {});

// The true mean as an exact image without variance channels (a perfect reference).
RgbImage synthetic_reference(const SyntheticSpec& s);

} // namespace tp::test
