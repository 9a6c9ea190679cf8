// Ray origins leave a surface along its geometric normal by a bound on the float error of the
// hit point, the rule of pbrt-v4 (sec. 6.8.6, "Robust Spawned Ray Origins"): far enough that
// neither the hit point's rounding nor the intersector's rounding when it meets the same plane
// again puts the origin on the wrong side, and no farther. The bound is a fixed multiple of the
// magnitudes that enter the computation, so it has no scene-dependent epsilon and scales with
// the scene: scaled by 1e-4, every offset shrinks by 1e-4; moved to 1e5, an offset is a few
// ulps of 1e5.
//
// Waechter & Binder's fixed rule (Ray Tracing Gems, ch. 6: 256 ulps per coordinate, and 1/65536
// absolute within 1/32 of the origin) does not scale so: its absolute part is 40 % of a sphere's
// radius in a scene scaled by 1e-4, and its 256 ulps are 2 units at 1e5 (docs/stress.md).
#ifndef TP_SHARED_OFFSET_H
#define TP_SHARED_OFFSET_H

#include "lang.h"

TP_NAMESPACE_BEGIN

// u = 2^-24, the unit roundoff of float; gamma(n) = n u / (1 - n u) bounds the relative error
// of n roundings (Higham 2002, sec. 3.1; pbrt-v4 sec. 6.8.1).
const float FLOAT_UNIT_ROUNDOFF = 5.9604645e-8f;

// The error bound, per world coordinate c, of a hit point p on a triangle with object-space
// vertices v_i under the instance (M, T), x -> M x + T, with inverse rows (M', T'). Two kinds of
// rounding enter it, of two magnitudes:
//
// Object magnitude, m_c = sum_k |M_ck| max_i |v_ik| (the size of the triangle's coordinates
// carried into world space, without T):
//   - the barycentric mix sum b_i v_i (1 - u - v: two roundings; three products, two sums):
//     gamma(7) max_i |v_ik| per object coordinate, as pbrt-v4's gamma(7) sum |b_i v_i|;
//   - the products and partial sums of M (p_obj) in the transform, and its action on that
//     error: gamma(3) m_c + (1 + gamma(3)) gamma(7) m_c <= gamma(10) m_c;
//   - re-testing the same triangle: the intersectors find t from vertices relative to the
//     origin in object space, whose rounding is a few more u of m_c (pbrt-v4's deltaT for
//     Woop's test is ~gamma(7) of those magnitudes), and the object-space result of the
//     origin's transform rounds at that size too.
//   Together gamma(20) m_c; OFFSET_GAMMA_M takes twice that, room for operations an
//   intersector orders differently than this count assumes.
//
// World magnitude, |p| = max_c |p_c|. T never enters the barycentric mix: it is added once in
// each of the two transforms, so it costs roundings of world-sized sums, not gamma(20) of |T|
// (|T_c| <= |p_c| + m_c, the excess is in the m term). These roundings are:
//   - the sum that adds T in M p_obj + T, the last sum of surface_snap_to_ray and the offset
//     p + d n: one rounding of |p_c| each, 3 u |p| (OFFSET_GAMMA_P);
//   - the intersector's transform of the new origin o into object space, M' o + T': a row k
//     with n_k non-zero entries rounds its products and partial sums by up to n_k u
//     sum_j |M'_kj| |o_j| (products with a zero entry and sums with an exact 0 are exact); back
//     in world space that is u |p| mix_c, mix_c = sum_k |M_ck| n_k sum_j |M'_kj|
//     (instance_rounding_mix, surface.h): 1 for an axis-aligned instance, up to 9 rotated.
//
// A triangle held in world space (the one-level structures: a mesh that one instance uses in
// the CPU's Embree scene, every triangle of compute mode's one-level BVH) has the same bound,
// computed the same way from its object-space vertices and instance, from which both engines
// rebuild every hit. Its intersector re-tests W_i = fl(M v_i + T) (scene/world_vertex.h) with
// the world-space origin. Those vertices, and so every point of the triangle, are off the
// exact placed triangle by at most u |W_ic| <= u (m_c + |T_c|) <= u (2 m_c + |p|): 2 u m_c fits
// in the doubling of OFFSET_GAMMA_M, and u |p| in u |p| mix_c, which was for the origin's
// transform that no longer happens (mix_c >= sum_k |M_ck| |M'_kc| >= 1, as M M' = I). The
// re-test subtracts the origin from vertices within the triangle's extent, 2 m_c, of the
// point, and rounds at that size, as in object space.
const float OFFSET_GAMMA_M = 40.0f * FLOAT_UNIT_ROUNDOFF;
const float OFFSET_GAMMA_P = 3.0f * FLOAT_UNIT_ROUNDOFF;

// The magnitude of each coordinate over a triangle's vertices, max_i |v_ik|: the size at which
// a barycentric mix of them rounds.
inline vec3 triangle_vertex_magnitude(vec3 v0, vec3 v1, vec3 v2) {
    return max(max(abs(v0), abs(v1)), abs(v2));
}

// The bound above for a point p whose object magnitudes are m, without the intersector's
// transform of the origin (surface_point adds it for its instance).
inline vec3 point_error_bound(vec3 m, vec3 p) {
    vec3 a = abs(p);
    return OFFSET_GAMMA_M * m + vec3(OFFSET_GAMMA_P * max(max(a.x, a.y), a.z));
}

// p: the computed point; p_error: a bound on |p_c - exact_c| for each coordinate c; n: the
// unit geometric normal on the side the new ray leaves towards. The origin moves along n by
// slack * dot(|n|, p_error): dot(|n|, p_error) is the largest distance along n that errors
// within p_error can make, and `slack` is the bound's factor for an intersector whose re-test
// of a triangle the terms above do not derive: 1 for Embree and the compute mode's watertight
// test, whose rounding they count; the pipeline mode's traversal is the driver's, undocumented,
// and needs 4 (docs/stress.md).
inline vec3 offset_ray_origin(vec3 p, vec3 p_error, vec3 n, float slack) {
    float d = slack * dot(abs(n), p_error);
    return p + d * n;
}

TP_NAMESPACE_END

#endif // TP_SHARED_OFFSET_H
