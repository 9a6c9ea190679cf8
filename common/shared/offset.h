// Ray origins leave a surface along its geometric normal by a bound on the float error of the
// hit point, the rule of pbrt-v4 (sec. 6.8.6, "Robust Spawned Ray Origins"): far enough that
// neither the hit point's rounding nor the intersector's rounding when it meets the same plane
// again puts the origin on the wrong side, and no farther. The bound is a fixed multiple of the
// magnitudes that enter the computation, so it has no scene-dependent epsilon and scales with
// the scene: scaled by 1e-4, every offset shrinks by 1e-4; moved to 1e5, an offset is a few
// ulps of 1e5.
//
// It replaces Waechter & Binder's rule (Ray Tracing Gems, ch. 6: 256 ulps per coordinate, and
// 1/65536 absolute within 1/32 of the origin), whose absolute part is 40 % of a sphere's radius
// in a scene scaled by 1e-4, and whose 256 ulps are 2 units at 1e5 (docs/stress.md).
#ifndef TP_SHARED_OFFSET_H
#define TP_SHARED_OFFSET_H

#include "lang.h"

TP_NAMESPACE_BEGIN

// u = 2^-24, the unit roundoff of float; gamma(n) = n u / (1 - n u) bounds the relative error
// of n roundings (Higham 2002, sec. 3.1; pbrt-v4 sec. 6.8.1).
const float FLOAT_UNIT_ROUNDOFF = 5.9604645e-8f;

// The error bound, per world coordinate c, of a hit point on a triangle with object-space
// vertices v_i under the instance (M, T), in units of m_c = sum_k |M_ck| max_i |v_ik| + |T_c|
// and of |p| = max_c |p_c| (surface.h, surface_point and surface_snap_to_ray):
//   - the barycentric mix sum b_i v_i (1 - u - v: two roundings; three products, two sums):
//     gamma(7) max_i |v_ik| per object coordinate, as pbrt-v4's gamma(7) sum |b_i v_i|;
//   - the instance transform (three products, three sums) and its action on that error:
//     gamma(3) m_c + (1 + gamma(3)) gamma(7) m_c <= gamma(10) m_c;
//   - re-testing the same triangle from the offset origin: the intersectors (Embree, Woop's
//     watertight test) move the origin into object space (gamma(3) of |p| and m_c) and find t
//     from vertices relative to it, whose rounding is a few more u of m_c (pbrt-v4's
//     deltaT for Woop's test is ~gamma(7) of the vertex magnitudes relative to the origin);
//   - the last sum of surface_snap_to_ray and the offset p + d n each round a coordinate by
//     u |p_c|.
// Adding the terms: gamma(20) m_c + gamma(5) |p|. OFFSET_GAMMA_M and OFFSET_GAMMA_P take twice
// that (to first order in u), room for operations an intersector orders differently than this
// count assumes.
const float OFFSET_GAMMA_M = 40.0f * FLOAT_UNIT_ROUNDOFF;
const float OFFSET_GAMMA_P = 10.0f * FLOAT_UNIT_ROUNDOFF;

// The bound above for a point p on a triangle whose coordinate magnitudes are m.
inline vec3 point_error_bound(vec3 m, vec3 p) {
    vec3 a = abs(p);
    return OFFSET_GAMMA_M * m + vec3(OFFSET_GAMMA_P * max(max(a.x, a.y), a.z));
}

// p: the computed point; p_error: a bound on |p_c - exact_c| for each coordinate c; n: the
// unit geometric normal on the side the new ray leaves towards. The origin moves along n by
// dot(|n|, p_error), the largest distance along n that errors within p_error can make.
inline vec3 offset_ray_origin(vec3 p, vec3 p_error, vec3 n) {
    float d = dot(abs(n), p_error);
    return p + d * n;
}

TP_NAMESPACE_END

#endif // TP_SHARED_OFFSET_H
