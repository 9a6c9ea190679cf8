// Sampling routines. Each sampler maps uniform numbers u in [0,1)^2 to a point or direction
// and has a matching pdf function; directions are in a local frame with the lobe axis as +z.
#ifndef TP_SHARED_SAMPLING_H
#define TP_SHARED_SAMPLING_H

#include "math.h"

TP_NAMESPACE_BEGIN

// Cosine-weighted hemisphere, thesis eq. 2.37: (theta, phi) = (acos(sqrt(u1)), 2 pi u2),
// written without the acos: cos(theta) = sqrt(1 - u1') with u1' = 1 - u1 keeps the same
// distribution and puts the exact value 0 of u at the pole instead of the horizon.
// pdf = cos(theta) / pi.
inline vec3 sample_cosine_hemisphere(vec2 u) {
    float cos_theta = sqrt(1.0f - u.x);
    float sin_theta = sqrt(u.x);
    float phi = TWO_PI * u.y;
    return vec3(cos(phi) * sin_theta, sin(phi) * sin_theta, cos_theta);
}

inline float cosine_hemisphere_pdf(float cos_theta) {
    return max(cos_theta, 0.0f) * INV_PI;
}

// max(cos(alpha), 0)^n for the Phong lobe: 0 outside the lobe's hemisphere for every
// exponent, n = 0 included, because sample_phong_lobe never leaves it (cos(alpha) =
// u^(1/(n+1)) > 0), and the pdf must be the sampler's density. Defined for every n >= 0
// (GLSL's pow(0, 0) is undefined) and computed as exp2(n log2 c) like every GPU does.
inline float phong_power(float cos_alpha, float n) {
    if (cos_alpha <= 0.0f) return 0.0f;
    if (n == 0.0f) return 1.0f;
    return exp2(n * log2(cos_alpha));
}

// Phong lobe around +z, thesis eq. 2.38: cos(alpha) = u1^(1/(n+1)), phi = 2 pi u2, with
// pdf = (n+1)/(2 pi) cos^n(alpha). For large n, 1 - cos(alpha) is tiny and float cannot hold
// cos(alpha) near 1 finely enough (at n = 1e6 the lobe is ~1e-3 rad wide, 1 - cos ~ 5e-7,
// float spacing below 1 is 6e-8), so we compute 1 - cos(alpha) = -expm1(ln(u)/(n+1))
// directly and take sin(alpha) from it. u1 is replaced by 1 - u1 so that ln never sees 0.
inline vec3 sample_phong_lobe(vec2 u, float n) {
    float t = log(1.0f - u.x) / (n + 1.0f);
    float one_minus_cos = -expm1_precise(t);
    float cos_alpha = 1.0f - one_minus_cos;
    float sin_alpha = safe_sqrt(one_minus_cos * (2.0f - one_minus_cos));
    float phi = TWO_PI * u.y;
    return vec3(cos(phi) * sin_alpha, sin(phi) * sin_alpha, cos_alpha);
}

inline float phong_lobe_pdf(float cos_alpha, float n) {
    return (n + 1.0f) * INV_TWO_PI * phong_power(cos_alpha, n);
}

// Uniform direction on the unit sphere (Archimedes: z uniform in [-1, 1]); pdf = 1 / (4 pi).
inline vec3 sample_uniform_sphere(vec2 u) {
    float z = 1.0f - 2.0f * u.x;
    float r = safe_sqrt(1.0f - z * z);
    float phi = TWO_PI * u.y;
    return vec3(r * cos(phi), r * sin(phi), z);
}

// Uniform point on a triangle by area (Osada et al., "Shape Distributions", ACM TOG 21(4),
// 2002, sec. 4.2): P = (1 - sqrt(u1)) A + sqrt(u1)(1 - u2) B + sqrt(u1) u2 C.
// Returns the barycentrics of B and C; pdf = 1 / area.
inline vec2 sample_uniform_triangle(vec2 u) {
    float su = sqrt(u.x);
    return vec2(su * (1.0f - u.y), su * u.y);
}

// ---- discrete choice: Walker's alias method (Vose's construction on the host) ----------
// The table slot comes from a 32-bit uniform integer h (rng_get_bits) as floor(h n / 2^32),
// the high word of the 64-bit product. Slot s then receives exactly the h in
// [ceil(s 2^32 / n), ceil((s + 1) 2^32 / n)), floor(2^32 / n) or ceil(2^32 / n) of them, so
// its probability is 1/n to within a relative n 2^-32 (5e-4 for the 2 * 10^6 pixels of a
// 2000 x 1000 environment map). A 24-bit float u would not do: floor(u n) gives each slot
// 2^24 / n values rounded to an integer, off by up to n 2^-24 relative, an error that goes
// straight into the estimate, which divides by the table's pdf.
// A second, independent number decides between the slot and its alias.
inline uint alias_slot_from_bits(uint h, uint n) {
    return umul_hi(h, n);
}

inline uint alias_resolve(uint slot, float slot_prob, uint slot_alias, float coin) {
    return coin < slot_prob ? slot : slot_alias;
}

TP_NAMESPACE_END

#endif // TP_SHARED_SAMPLING_H
