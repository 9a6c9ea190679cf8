// Alpha as coverage (glTF 2.0, "Alpha Coverage"): whether a surface is there at a point, decided
// by every traversal of both engines before it accepts a hit, so that a cut-out casts the shadow
// of its shape. MASK keeps the surface where alpha >= the cutoff. BLEND keeps it with probability
// alpha (stochastic transparency, as pbrt-v4's alpha test does): the threshold is a hash of the
// ray and the triangle, a pure function, so a query gives the same answer in any traversal order
// and on both engines, and two surfaces along one ray are kept independently.
#ifndef TP_SHARED_ALPHA_H
#define TP_SHARED_ALPHA_H

#include "rng.h"
#include "types.h"

TP_NAMESPACE_BEGIN

// A number in [0, 1) from the ray (origin o, direction d) and the triangle.
inline float alpha_blend_threshold(vec3 o, vec3 d, uint instance, uint primitive) {
    uvec4 h = pcg4d(uvec4(floatBitsToUint(o.x) ^ floatBitsToUint(d.y),
                          floatBitsToUint(o.y) ^ floatBitsToUint(d.z),
                          floatBitsToUint(o.z) ^ floatBitsToUint(d.x),
                          (instance * 0x9E3779B9u) ^ primitive));
    return uint_to_unit_float(h.x);
}

inline bool alpha_covers(uint mode, float alpha, float cutoff, vec3 o, vec3 d, uint instance,
                         uint primitive) {
    if (mode == ALPHA_MASK) return alpha >= cutoff;
    if (mode == ALPHA_BLEND) return alpha > alpha_blend_threshold(o, d, instance, primitive);
    return true;
}

TP_NAMESPACE_END

#endif // TP_SHARED_ALPHA_H
