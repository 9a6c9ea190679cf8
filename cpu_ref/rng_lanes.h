// The random numbers of one bounce on the CPU, computed together: the five pairs of rng.h's layout
// that a bounce may draw (the light slot and its coin, the point on the light, the environment
// slot and its coin, the lobe choice and the roulette, the scattered direction), each pair in a
// lane of one loop over rng.h's own functions. The lanes are independent and every step is an
// integer operation (multiplies, adds, xors, shifts, byte swaps), so the compiler vectorizes the
// loop (in the x86-64-v3 copy of the path loop, cpu_ref/integrator.h: eight lanes of AVX2, one
// vpmulld for eight of pcg4d's or Laine-Karras' multiplies, and the byte swap of bitfieldReverse
// as one vpshufb) and the numbers are rng.h's to the bit (tests/unit/rng_lanes_test.cpp). A path
// draws the pairs of a bounce one after another, each a dependent chain of about twenty multiplies
// (pcg4d, two Laine-Karras permutations) that the loop around it waits for; in lanes they are one
// chain for all five, and a bounce that skips a pair (a delta material draws no light numbers,
// most bounces no lobe choice) pays for it anyway, which is cheaper than a chain of its own.
#pragma once

#include "shared/rng.h"

namespace tp {

constexpr uint32_t kBouncePairs = 5; // pairs a bounce draws (rng.h's layout)
constexpr uint32_t kBounceLanes = 8; // a whole AVX2 register: lanes 5-7 compute pair 0 again

// The first dimension (k of rng.h's layout) of the pair in each lane.
constexpr uint32_t kBounceLaneFirst[kBounceLanes] = {RNG_LIGHT_SLOT, RNG_LIGHT_U,   RNG_ENV_SLOT,
                                                     RNG_LOBE,       RNG_DIR_U,     RNG_LIGHT_SLOT,
                                                     RNG_LIGHT_SLOT, RNG_LIGHT_SLOT};

// The lane of the pair whose first dimension is k (one of the five above).
constexpr uint32_t bounce_pair_lane(uint32_t k) {
    return k == RNG_LIGHT_SLOT ? 0u
           : k == RNG_LIGHT_U  ? 1u
           : k == RNG_ENV_SLOT ? 2u
           : k == RNG_LOBE     ? 3u
                               : 4u;
}

// The 32-bit words of a bounce's pairs: lane i holds rng_bounce2_bits(key, bounce,
// kBounceLaneFirst[i]) as (first[i], second[i]).
struct BounceWords {
    alignas(32) uint32_t first[kBounceLanes];
    alignas(32) uint32_t second[kBounceLanes];
};

// Sobol: sobol_pair_bits per lane, so the index shuffle and both coordinates' scrambles run
// lane-parallel.
inline void bounce_words_sobol(const RngKey& key, uint32_t bounce, BounceWords& out) {
    for (uint32_t i = 0; i < kBounceLanes; ++i) {
        const uvec2 w = sobol_pair_bits(key, rng_bounce_dim(bounce, kBounceLaneFirst[i]));
        out.first[i] = w.x;
        out.second[i] = w.y;
    }
}

// Random: rng_get2_bits per lane, its sampler test hoisted out of the loop by the caller.
inline void bounce_words_random(const RngKey& key, uint32_t bounce, BounceWords& out) {
    for (uint32_t i = 0; i < kBounceLanes; ++i) {
        const uvec2 w = rng_get2_bits(key, rng_bounce_dim(bounce, kBounceLaneFirst[i]));
        out.first[i] = w.x;
        out.second[i] = w.y;
    }
}

inline void bounce_words(const RngKey& key, uint32_t bounce, BounceWords& out) {
    if (key.sampler_id == SAMPLER_SOBOL)
        bounce_words_sobol(key, bounce, out);
    else
        bounce_words_random(key, bounce, out);
}

} // namespace tp
