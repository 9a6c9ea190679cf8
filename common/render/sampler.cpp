#include "render/sampler.h"

#include "shared/rng.h"
#include "util/error.h"

namespace tp {

uint32_t sampler_from_name(const std::string& name) {
    if (name == "random") return SAMPLER_RANDOM;
    if (name == "sobol") return SAMPLER_SOBOL;
    input_error("--sampler {}: expected random or sobol", name);
}

const char* sampler_name(uint32_t sampler) {
    return sampler == SAMPLER_SOBOL ? "sobol" : "random";
}

uint32_t film_batches(uint32_t sampler) {
    return sampler == SAMPLER_SOBOL ? SOBOL_BATCHES : 0;
}

} // namespace tp
