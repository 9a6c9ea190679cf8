// The display transform of `--png` and of the viewer's window (shaders/display.comp): linear
// radiance times 2^exposure, clamped to [0, 1], encoded with the sRGB transfer function
// (IEC 61966-2-1) and rounded to 8 bits.
#ifndef TP_SHARED_TONEMAP_H
#define TP_SHARED_TONEMAP_H

#include "shared/lang.h"
#include "shared/math.h"

TP_NAMESPACE_BEGIN

inline float linear_to_srgb(float x) {
    x = clamp(x, 0.0f, 1.0f);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * pow(x, 1.0f / 2.4f) - 0.055f;
}

// One channel's 8-bit code for linear radiance `x` already scaled by 2^exposure. floor(v + 0.5)
// is round-half-up, the same as std::lround for v >= 0.
inline uint srgb8_code(float x) {
    return uint(floor(linear_to_srgb(x) * 255.0f + 0.5f));
}

// A pixel's three 8-bit codes for its linear radiance and the exposure factor 2^exposure.
// A non-finite channel makes the pixel magenta, so that a NaN or Inf shows rather than
// clamping to black or white.
inline uvec3 display_srgb8(vec3 radiance, float scale) {
    if (!is_finite3(radiance)) return uvec3(255u, 0u, 255u);
    return uvec3(srgb8_code(radiance.x * scale), srgb8_code(radiance.y * scale),
                 srgb8_code(radiance.z * scale));
}

TP_NAMESPACE_END

#endif // TP_SHARED_TONEMAP_H
