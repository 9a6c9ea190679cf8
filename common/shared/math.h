// Constants and small numeric helpers used by the other shared headers.
#ifndef TP_SHARED_MATH_H
#define TP_SHARED_MATH_H

#include "lang.h"

TP_NAMESPACE_BEGIN

const float PI = 3.14159265358979323846f;
const float TWO_PI = 6.28318530717958647692f;
const float INV_PI = 0.31830988618379067154f;
const float INV_TWO_PI = 0.15915494309189533577f;
const float INV_FOUR_PI = 0.07957747154594766788f;
const float FLOAT_MAX = 3.402823466e38f;
const float ONE_MINUS_EPSILON = 0.99999994f; // the largest float below 1

inline float max3(vec3 v) {
    return max(v.x, max(v.y, v.z));
}
inline float average(vec3 v) {
    return (v.x + v.y + v.z) * (1.0f / 3.0f);
}

// Rec. 709 / sRGB primaries luminance weights.
inline float luminance(vec3 c) {
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

// Tested on the bit pattern (exponent all ones: Inf or NaN) rather than with isnan/isinf,
// which a GPU compiler may fold to false unless the shader declares SignedZeroInfNanPreserve.
inline bool is_finite(float x) {
    return (floatBitsToUint(x) & 0x7F800000u) != 0x7F800000u;
}
inline bool is_finite3(vec3 v) {
    return is_finite(v.x) && is_finite(v.y) && is_finite(v.z);
}
inline bool is_black(vec3 v) {
    return v.x == 0.0f && v.y == 0.0f && v.z == 0.0f;
}

inline float safe_sqrt(float x) {
    return sqrt(max(x, 0.0f));
}

// exp(x) - 1 without the cancellation of the naive form for |x| << 1: below 1e-3 the Taylor
// polynomial to x^3 has relative error < x^3/24 < 5e-11, far under float epsilon.
inline float expm1_precise(float x) {
    if (abs(x) < 1e-3f) return x * (1.0f + x * (0.5f + x * (1.0f / 6.0f)));
    return exp(x) - 1.0f;
}

// Orthonormal basis around a unit vector n: Duff et al., "Building an Orthonormal Basis,
// Revisited", JCGT 6(1), 2017, listing 3. copysign is written out because GLSL's sign(0) = 0.
inline void orthonormal_basis(vec3 n, OUT(vec3) t, OUT(vec3) b) {
    float s = n.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (s + n.z);
    float c = n.x * n.y * a;
    t = vec3(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
    b = vec3(c, s + n.y * n.y * a, -n.y);
}

// Maps a direction given in the frame (t, b, n) with n as +z to world space.
inline vec3 frame_to_world(vec3 local, vec3 t, vec3 b, vec3 n) {
    return local.x * t + local.y * b + local.z * n;
}

TP_NAMESPACE_END

#endif // TP_SHARED_MATH_H
