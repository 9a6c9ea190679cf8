// The sampler a render draws its numbers from (shared/rng.h, docs/sampling.md), by name, and
// the film estimator of the variance of the mean that goes with it.
#pragma once

#include <cstdint>
#include <string>

namespace tp {

// "random" or "sobol"; anything else is an InputError naming --sampler.
uint32_t sampler_from_name(const std::string& name);
const char* sampler_name(uint32_t sampler);

// Film batches (render/film.h): SOBOL_BATCHES independent randomizations for the Sobol
// sampler, whose samples within a pixel are not independent; 0 (the sample variance) for the
// random sampler.
uint32_t film_batches(uint32_t sampler);

} // namespace tp
