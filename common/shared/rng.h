// Counter-based random numbers. A number is a pure function of (seed, pixel, sample, dimension),
// so both engines draw bit-identical numbers for the same path and any path can be replayed.
//
// Hash: pcg4d from Jarzynski & Olano, "Hash Functions for GPU Rendering", JCGT 9(3), 2020:
// the multidimensional hash they introduce for the high-quality end of their TestU01 ranking,
// a 4D-in/4D-out permutation built from PCG's LCG step with cross-lane mixing. Our four
// counters are its four inputs, so no counter has to be folded into another first.
//
// Dimension layout (a step that is skipped does not shift the numbers of later steps):
//   0, 1                 pixel jitter x, y (box filter)
//   2 + 10 b + k         bounce b (0 = the camera ray's hit), k = RNG_*:
//     k = 0 light slot (alias table), 1 alias coin, 2 and 3 point on the light,
//         4 and 5 environment-map pixel slot and coin, 6 lobe choice (Phong diffuse or
//         specular, dielectric reflect or refract), 7 and 8 scattered direction,
//         9 Russian roulette
// Every dimension is one 32-bit hash word: rng_get gives its top 24 bits as a float in [0, 1);
// the two alias-table slots (k = 0 and 4) take the whole word from rng_get_bits instead
// (sampling.h, alias_slot_from_bits), since 24 bits cannot split a large table evenly.
#ifndef TP_SHARED_RNG_H
#define TP_SHARED_RNG_H

#include "lang.h"

TP_NAMESPACE_BEGIN

const uint RNG_PIXEL_X = 0u;
const uint RNG_PIXEL_Y = 1u;
const uint RNG_BOUNCE_BASE = 2u;
const uint RNG_DIMS_PER_BOUNCE = 10u;

const uint RNG_LIGHT_SLOT = 0u;
const uint RNG_LIGHT_COIN = 1u;
const uint RNG_LIGHT_U = 2u;
const uint RNG_LIGHT_V = 3u;
const uint RNG_ENV_SLOT = 4u;
const uint RNG_ENV_COIN = 5u;
const uint RNG_LOBE = 6u;
const uint RNG_DIR_U = 7u;
const uint RNG_DIR_V = 8u;
const uint RNG_ROULETTE = 9u;

inline uvec4 pcg4d(uvec4 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    v = v ^ (v >> 16u);
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    return v;
}

// The top 24 bits as a float in [0, 1): every value is exact, 1.0 is never returned.
inline float uint_to_unit_float(uint h) {
    return float(h >> 8u) * (1.0f / 16777216.0f);
}

struct RngKey {
    uint seed;
    uint pixel; // y * width + x
    uint sample_index;
    uint pad0;
};

inline RngKey rng_key(uint seed, uint pixel, uint sample_index) {
    RngKey k;
    k.seed = seed;
    k.pixel = pixel;
    k.sample_index = sample_index;
    k.pad0 = 0u;
    return k;
}

// The 32-bit hash word of one dimension.
inline uint rng_get_bits(RngKey k, uint dimension) {
    return pcg4d(uvec4(k.pixel, k.sample_index, dimension, k.seed)).x;
}

inline float rng_get(RngKey k, uint dimension) {
    return uint_to_unit_float(rng_get_bits(k, dimension));
}

inline uint rng_bounce_dim(uint bounce, uint k) {
    return RNG_BOUNCE_BASE + bounce * RNG_DIMS_PER_BOUNCE + k;
}

inline float rng_bounce(RngKey key, uint bounce, uint k) {
    return rng_get(key, rng_bounce_dim(bounce, k));
}

inline uint rng_bounce_bits(RngKey key, uint bounce, uint k) {
    return rng_get_bits(key, rng_bounce_dim(bounce, k));
}

TP_NAMESPACE_END

#endif // TP_SHARED_RNG_H
