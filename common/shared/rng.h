// Counter-based random numbers. A number is a pure function of (sampler, seed, pixel, sample,
// dimension), so both engines draw bit-identical numbers for the same path, any path can be
// replayed, and sample ranges split and merge exactly. Two samplers, chosen at run time
// (RenderParams::sampler_id):
//
// SAMPLER_RANDOM, independent numbers. Hash: pcg4d from Jarzynski & Olano, "Hash Functions for
// GPU Rendering", JCGT 9(3), 2020: the multidimensional hash they introduce for the
// high-quality end of their TestU01 ranking, a 4D-in/4D-out permutation built from PCG's LCG
// step with cross-lane mixing. Our four counters are its four inputs, so no counter has to be
// folded into another first.
//
// SAMPLER_SOBOL, Owen-scrambled Sobol points with hash-based scrambling (Burley, "Practical
// Hash-based Owen Scrambling", JCGT 9(4), 2020), padded as pbrt-v4's PaddedSobolSampler does:
// every dimension belongs to a pair (listed below), and every pair takes Sobol's first two
// dimensions, which form a (0, 2)-sequence (Sobol 1967; Niederreiter 1992, sec. 4.5), with its
// own random shuffle of the sample index and its own Owen scramble of each coordinate, all
// three seeded by one hash of (pixel, batch, pair, seed). So pairs and pixels are
// decorrelated, and within a pair the first 2^m points of a batch are a (0, m, 2)-net: one
// point in every elementary interval of area 2^-m; each coordinate alone is stratified into
// 2^m equal intervals. The two coordinates of a pair share the hash and the shuffled index,
// so one call (rng_get2) computes both, and a single draw (rng_get) the one it needs.
// Sample s belongs to batch s mod SOBOL_BATCHES and is point s / SOBOL_BATCHES of that batch's
// sequence; the batches are independent randomizations, so the variance of a pixel's mean is
// estimated from the spread of its batch means (render/film.h) where the points of one batch
// are not independent. Interleaving keeps every batch equally filled at any spp and any
// sample range.
//
// Dimension layout (a step that is skipped does not shift the numbers of later steps):
//   0, 1                 pixel jitter x, y (box filter)
//   2 + 10 b + k         bounce b (0 = the camera ray's hit), k = RNG_*:
//     k = 0 light slot (alias table), 1 alias coin, 2 and 3 point on the light,
//         4 and 5 environment-map pixel slot and coin, 6 lobe choice (Phong diffuse or
//         specular, dielectric reflect or refract), 7 and 8 scattered direction,
//         9 Russian roulette
// Sobol pairs (first, second): the pixel jitter (0, 1) and, in every bounce, k = (0, 1),
// (2, 3), (4, 5), (7, 8) and (6, 9): the lobe choice and the roulette share a pair because
// neither has a partner of its own, and a pair costs little more than one of its coordinates.
// Every dimension is one 32-bit word: rng_get gives its top 24 bits as a float in [0, 1);
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

const uint SAMPLER_RANDOM = 0u;
const uint SAMPLER_SOBOL = 1u;
// Independent randomizations of the Sobol sampler: the variance estimate from K batch means
// has K - 1 degrees of freedom, and each batch holds spp / K points of one net. 8 is the
// fewest the t statistics of compare can live with (docs/sampling.md).
const uint SOBOL_BATCHES = 8u;

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
    uint sampler_id; // SAMPLER_*
    // Sobol: the point's index within its batch, bit-reversed (the first step of the index
    // shuffle in sobol_pair_bits, the same for every pair of the sample).
    uint index_reversed;
};

inline RngKey rng_key(uint sampler_id, uint seed, uint pixel, uint sample_index) {
    RngKey k;
    k.seed = seed;
    k.pixel = pixel;
    k.sample_index = sample_index;
    k.sampler_id = sampler_id;
    k.index_reversed = bitfieldReverse(sample_index / SOBOL_BATCHES);
    return k;
}

// Burley's hash-based Owen scramble (sec. 3, his improved Laine-Karras permutation): every step
// is a bijection in which output bit i depends only on input bits 0..i (an addition, and
// x ^= x * c for even c), so applied to the bit-reversed value it flips each digit of the
// binary fraction by a hash of the digits above it, as Owen's nested uniform scramble does.
inline uint laine_karras_permutation(uint x, uint seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

inline uint nested_uniform_scramble(uint x, uint seed) {
    return bitfieldReverse(laine_karras_permutation(bitfieldReverse(x), seed));
}

// Sobol's second dimension, bit-reversed. Its primitive polynomial is x + 1 with m_1 = 1 (the
// first entry of Joe & Kuo's table, "Constructing Sobol sequences with better two-dimensional
// projections", SIAM J. Sci. Comput. 30(5), 2008), so the direction numbers follow from
// v_0 = 1/2 by v_(k+1) = v_k xor (v_k >> 1): v_k has the binary digit 2^-(j+1) set iff
// binomial(k, j) is odd, i.e. (Lucas) iff the bits of j are a subset of those of k. The point
// is the xor of v_k over the set bits k of the index (Bratley & Fox 1988, Algorithm 659), so
// its digit j is the xor of index bits k over the supersets k of j: the superset transform
// over the 5 address bits of a bit position, one shift-and-mask step per address bit. Bit j
// of the result is digit 2^-(j+1) of the point. (The first dimension is the van der Corput
// sequence, whose reversed form is the index itself.)
inline uint sobol_dim1_reversed(uint index) {
    index ^= (index >> 1u) & 0x55555555u;
    index ^= (index >> 2u) & 0x33333333u;
    index ^= (index >> 4u) & 0x0F0F0F0Fu;
    index ^= (index >> 8u) & 0x00FF00FFu;
    index ^= (index >> 16u) & 0x0000FFFFu;
    return index;
}

// Sobol's second dimension as a 32-bit binary fraction.
inline uint sobol_dim1(uint index) {
    return bitfieldReverse(sobol_dim1_reversed(index));
}

// The first dimension of the Sobol pair (see the layout above) that `dimension` belongs to.
inline uint rng_group_first(uint dimension) {
    if (dimension < RNG_BOUNCE_BASE) return RNG_PIXEL_X;
    uint k = (dimension - RNG_BOUNCE_BASE) % RNG_DIMS_PER_BOUNCE;
    if (k == RNG_ROULETTE) return dimension - (RNG_ROULETTE - RNG_LOBE);
    bool second = k == RNG_LIGHT_COIN || k == RNG_LIGHT_V || k == RNG_ENV_COIN || k == RNG_DIR_V;
    return second ? dimension - 1u : dimension;
}

// The second dimension of the Sobol pair whose first dimension is `first`.
inline uint rng_group_second(uint first) {
    if (first < RNG_BOUNCE_BASE) return RNG_PIXEL_Y;
    uint k = (first - RNG_BOUNCE_BASE) % RNG_DIMS_PER_BOUNCE;
    return k == RNG_LOBE ? first + (RNG_ROULETTE - RNG_LOBE) : first + 1u;
}

// Both coordinates of the scrambled Sobol point of sample k.sample_index in the pair whose
// first dimension is `first`.
inline uvec2 sobol_pair_bits(RngKey k, uint first) {
    uvec4 h = pcg4d(uvec4(k.pixel, k.sample_index % SOBOL_BATCHES, first, k.seed));
    // Burley sec. 4: a nested uniform scramble of the index is a random permutation that maps
    // each aligned block of 2^m indices onto one such block, so every prefix of 2^m points
    // stays a net. This is nested_uniform_scramble(k.sample_index / SOBOL_BATCHES, h.x), with
    // its inner reversal taken from the key.
    uint index = bitfieldReverse(laine_karras_permutation(k.index_reversed, h.x));
    // The Owen scramble of a point, nested_uniform_scramble(point, seed), reverses the point's
    // bits to scramble them; both dimensions are reversals of simple functions of the index,
    // so the reversed points are computed directly.
    return uvec2(bitfieldReverse(laine_karras_permutation(index, h.y)),
                 bitfieldReverse(laine_karras_permutation(sobol_dim1_reversed(index), h.z)));
}

// The 32-bit words of the pair whose first dimension is `first`: (first, rng_group_second(first)).
inline uvec2 rng_get2_bits(RngKey k, uint first) {
    if (k.sampler_id == SAMPLER_SOBOL) return sobol_pair_bits(k, first);
    return uvec2(pcg4d(uvec4(k.pixel, k.sample_index, first, k.seed)).x,
                 pcg4d(uvec4(k.pixel, k.sample_index, rng_group_second(first), k.seed)).x);
}

// The 32-bit word of one dimension.
inline uint rng_get_bits(RngKey k, uint dimension) {
    if (k.sampler_id == SAMPLER_SOBOL) {
        uint first = rng_group_first(dimension);
        uvec2 pair = sobol_pair_bits(k, first);
        return dimension == first ? pair.x : pair.y;
    }
    return pcg4d(uvec4(k.pixel, k.sample_index, dimension, k.seed)).x;
}

inline vec2 rng_get2(RngKey k, uint first) {
    uvec2 w = rng_get2_bits(k, first);
    return vec2(uint_to_unit_float(w.x), uint_to_unit_float(w.y));
}

inline float rng_get(RngKey k, uint dimension) {
    return uint_to_unit_float(rng_get_bits(k, dimension));
}

inline uint rng_bounce_dim(uint bounce, uint k) {
    return RNG_BOUNCE_BASE + bounce * RNG_DIMS_PER_BOUNCE + k;
}

// The pair of bounce `bounce` whose first dimension is k: (k, its partner) as in the layout.
inline vec2 rng_bounce2(RngKey key, uint bounce, uint k) {
    return rng_get2(key, rng_bounce_dim(bounce, k));
}

inline uvec2 rng_bounce2_bits(RngKey key, uint bounce, uint k) {
    return rng_get2_bits(key, rng_bounce_dim(bounce, k));
}

TP_NAMESPACE_END

#endif // TP_SHARED_RNG_H
