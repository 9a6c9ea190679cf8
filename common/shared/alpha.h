// Alpha as coverage (glTF 2.0, "Alpha Coverage"): whether a surface is there at a point, decided
// by every traversal of both engines before it accepts a hit, so that a cut-out casts the shadow
// of its shape. MASK keeps the surface where alpha >= the cutoff. BLEND keeps it with probability
// alpha (stochastic transparency, as pbrt-v4's alpha test does): the threshold is a hash of the
// ray's tag and the triangle, a pure function, so a query gives the same answer in any traversal
// order, and two surfaces along one ray are kept independently. The tag names the ray by its
// path (ray_tag: the path's random-number key, its bounce and whether it is the path's next ray
// or a shadow ray), not by its floats, which the two engines compute only to rounding: so both
// engines make the same decision on the same path, and a path log replays it.
#ifndef TP_SHARED_ALPHA_H
#define TP_SHARED_ALPHA_H

#include "rng.h"
#include "types.h"

TP_NAMESPACE_BEGIN

const uint RAY_TAG_PATH = 0u;   // the ray that continues a path (the camera ray at bounce 0)
const uint RAY_TAG_SHADOW = 1u; // a shadow ray of next-event estimation

// The tag of the ray that bounce `bounce` of the path with key `key` traces, of kind RAY_TAG_*.
inline uint ray_tag(RngKey key, uint bounce, uint kind) {
    return pcg4d(uvec4(key.pixel, key.sample_index, 2u * bounce + kind, key.seed)).x;
}

// A number in [0, 1) from the ray's tag and the triangle.
inline float alpha_blend_threshold(uint tag, uint instance, uint primitive) {
    return uint_to_unit_float(pcg4d(uvec4(tag, instance, primitive, 0x414C5048u)).x);
}

inline bool alpha_covers(uint mode, float alpha, float cutoff, uint tag, uint instance,
                         uint primitive) {
    if (mode == ALPHA_MASK) return alpha >= cutoff;
    if (mode == ALPHA_BLEND) return alpha > alpha_blend_threshold(tag, instance, primitive);
    return true;
}

TP_NAMESPACE_END

#endif // TP_SHARED_ALPHA_H
