// Random inputs for the shared-function comparison: each generator draws arguments from the
// domain the engines call the function on (unit vectors where they are unit, uniform numbers
// in [0, 1), valid materials and transforms), with the edge cases of that domain mixed in.
#pragma once

#include "shaders/function_table.h"

#include <random>

namespace tp::test {

class InputGen {
  public:
    explicit InputGen(uint64_t seed) : rng_(seed) {}

    uint32_t u32() { return uint32_t(rng_() >> 32); }
    float uni() { return float(u32() >> 8) * 0x1p-24f; } // [0, 1), 24 bits like rng_get
    float uniform(float lo, float hi) { return lo + (hi - lo) * uni(); }
    float log_uniform(float lo, float hi) {
        return float(std::exp(std::log(double(lo)) + (std::log(double(hi / lo))) * double(uni())));
    }
    uint32_t below(uint32_t n) { return uint32_t((uint64_t(u32()) * n) >> 32); }
    bool chance(float p) { return uni() < p; }
    float any_bits(); // any float bit pattern: NaN, Inf, denormals included
    vec3 box(float r) { return vec3(uniform(-r, r), uniform(-r, r), uniform(-r, r)); }
    vec3 unit();          // uniform on the sphere, normalized in double
    vec3 towards(vec3 n); // unit, on n's side
    vec3 color(float hi) { return vec3(uniform(0, hi), uniform(0, hi), uniform(0, hi)); }

    // kd + ks <= 1 per channel; ns 0 or log-uniform in [1, 1e4].
    void phong(vec3& kd, vec3& ks, float& ns);
    // Rows of a random rotation x scale (0.2..5 per axis) + translation and of its inverse.
    void transform(vec4 rows[3], vec4 inverse_rows[3]);

  private:
    std::mt19937_64 rng_;
};

// Fills the input record for function `id`.
void make_input(uint32_t id, InputGen& g, FnIn& x);

} // namespace tp::test
