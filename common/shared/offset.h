// Ray origins leave a surface by the offset of Waechter & Binder, "A Fast and Robust Method for
// Avoiding Self-Intersection", Ray Tracing Gems (2019), ch. 6, listing 6-1: the hit point is
// moved along the geometric normal by a fixed number of float ULPs (integer arithmetic on the
// bit pattern), which scales with the magnitude of each coordinate, and near the origin, where
// ULPs become tiny, by a small absolute distance instead. No scene-dependent epsilon.
#ifndef TP_SHARED_OFFSET_H
#define TP_SHARED_OFFSET_H

#include "lang.h"

TP_NAMESPACE_BEGIN

const float OFFSET_ORIGIN = 1.0f / 32.0f;
const float OFFSET_FLOAT_SCALE = 1.0f / 65536.0f;
const float OFFSET_INT_SCALE = 256.0f;

inline float offset_coordinate(float p, float n) {
    int of_i = int(OFFSET_INT_SCALE * n);
    float p_i = intBitsToFloat(floatBitsToInt(p) + (p < 0.0f ? -of_i : of_i));
    return abs(p) < OFFSET_ORIGIN ? p + OFFSET_FLOAT_SCALE * n : p_i;
}

// p: the hit point; n: the geometric normal on the side the new ray leaves towards.
inline vec3 offset_ray_origin(vec3 p, vec3 n) {
    return vec3(offset_coordinate(p.x, n.x), offset_coordinate(p.y, n.y),
                offset_coordinate(p.z, n.z));
}

TP_NAMESPACE_END

#endif // TP_SHARED_OFFSET_H
