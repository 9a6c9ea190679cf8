// Hit reconstruction: from an instance, a triangle's object-space vertices and the hit's
// barycentrics to the world-space point and frame that shading uses. Both engines call these
// with the same inputs (Embree and the GPU traversal both report (u, v) as the weights of
// vertices 1 and 2), so they shade the same point.
#ifndef TP_SHARED_SURFACE_H
#define TP_SHARED_SURFACE_H

#include "math.h"
#include "offset.h"
#include "types.h"

TP_NAMESPACE_BEGIN

inline vec3 instance_point_to_world(Instance t, vec3 p) {
    vec4 h = vec4(p.x, p.y, p.z, 1.0f);
    return vec3(dot(t.to_world0, h), dot(t.to_world1, h), dot(t.to_world2, h));
}

inline vec3 instance_vector_to_world(Instance t, vec3 v) {
    vec4 h = vec4(v.x, v.y, v.z, 0.0f);
    return vec3(dot(t.to_world0, h), dot(t.to_world1, h), dot(t.to_world2, h));
}

inline vec3 instance_point_to_object(Instance t, vec3 p) {
    vec4 h = vec4(p.x, p.y, p.z, 1.0f);
    return vec3(dot(t.to_object0, h), dot(t.to_object1, h), dot(t.to_object2, h));
}

inline vec3 instance_vector_to_object(Instance t, vec3 v) {
    vec4 h = vec4(v.x, v.y, v.z, 0.0f);
    return vec3(dot(t.to_object0, h), dot(t.to_object1, h), dot(t.to_object2, h));
}

// Normals transform by the inverse transpose: n_world = (M^-1)^T n, i.e. the columns of the
// inverse's upper 3x3 weighted by n.
inline vec3 instance_normal_to_world(Instance t, vec3 n) {
    return n.x * vec3(t.to_object0.x, t.to_object0.y, t.to_object0.z) +
           n.y * vec3(t.to_object1.x, t.to_object1.y, t.to_object1.z) +
           n.z * vec3(t.to_object2.x, t.to_object2.y, t.to_object2.z);
}

inline vec3 barycentric_mix3(vec3 a, vec3 b, vec3 c, vec2 uv) {
    return (1.0f - uv.x - uv.y) * a + uv.x * b + uv.y * c;
}

inline vec2 barycentric_mix2(vec2 a, vec2 b, vec2 c, vec2 uv) {
    return (1.0f - uv.x - uv.y) * a + uv.x * b + uv.y * c;
}

inline vec4 barycentric_mix4(vec4 a, vec4 b, vec4 c, vec2 uv) {
    return (1.0f - uv.x - uv.y) * a + uv.x * b + uv.y * c;
}

struct SurfacePoint {
    vec3 p;       // world position
    vec3 p_error; // bound on the float error of each coordinate of p (offset.h)
    vec3 ng;      // unit geometric normal, (v1 - v0) x (v2 - v0): the front (emitting) side
    vec3 ns;      // unit shading normal, on ng's side
    vec2 uv;      // the mesh's uv sets (zero where it has none)
    vec2 uv1;
    vec3 tangent;   // the normal map's tangent frame in world space (zero where there is none):
    vec3 bitangent; // the interpolated tangent and cross(normal, tangent) w, transformed
};

// What the error bound of a hit point needs from its instance (offset.h), a function of the
// instance alone: the CPU computes it once per instance (cpu_ref/cpu_engine.h), the shaders
// at each hit, where a buffer for it would cost a load as large as the arithmetic.
struct InstanceErrorTerms {
    vec4 abs_row0; // |M| row by row (0 in w: T is not in the object magnitude)
    vec4 abs_row1;
    vec4 abs_row2;
    vec3 rounding_mix; // instance_rounding_mix
};

// How the rounding of the intersector's transform of an origin into object space reaches world
// coordinate c, in units of u |p| (offset.h): mix_c = sum_k |M_ck| n_k sum_j |M'_kj|, n_k the
// number of non-zero entries of the inverse's row k. 1 for an axis-aligned instance (one exact
// product per row), up to 9 for a rotated one.
inline float instance_row_rounding(vec4 r) {
    vec3 a = abs(vec3(r.x, r.y, r.z));
    float n = (a.x > 0.0f ? 1.0f : 0.0f) + (a.y > 0.0f ? 1.0f : 0.0f) + (a.z > 0.0f ? 1.0f : 0.0f);
    return n * (a.x + a.y + a.z);
}

inline vec3 instance_rounding_mix(Instance t) {
    vec4 w = vec4(instance_row_rounding(t.to_object0), instance_row_rounding(t.to_object1),
                  instance_row_rounding(t.to_object2), 0.0f);
    return vec3(dot(abs(t.to_world0), w), dot(abs(t.to_world1), w), dot(abs(t.to_world2), w));
}

inline InstanceErrorTerms instance_error_terms(Instance t) {
    InstanceErrorTerms e;
    e.abs_row0 = vec4(abs(vec3(t.to_world0.x, t.to_world0.y, t.to_world0.z)), 0.0f);
    e.abs_row1 = vec4(abs(vec3(t.to_world1.x, t.to_world1.y, t.to_world1.z)), 0.0f);
    e.abs_row2 = vec4(abs(vec3(t.to_world2.x, t.to_world2.y, t.to_world2.z)), 0.0f);
    e.rounding_mix = instance_rounding_mix(t);
    return e;
}

// The object magnitude of each world coordinate of a point of the triangle:
// m_c = sum_k |M_ck| max_i |v_ik| for the instance's rows (M, T); T is not in it (offset.h).
inline vec3 triangle_coordinate_magnitude(InstanceErrorTerms e, vec3 v0, vec3 v1, vec3 v2) {
    vec4 b = vec4(triangle_vertex_magnitude(v0, v1, v2), 0.0f);
    return vec3(dot(e.abs_row0, b), dot(e.abs_row1, b), dot(e.abs_row2, b));
}

// e = instance_error_terms(t).
inline SurfacePoint surface_point_with(Instance t, InstanceErrorTerms e, vec3 v0, vec3 v1, vec3 v2,
                                       vec2 bary) {
    SurfacePoint s;
    s.p = instance_point_to_world(t, barycentric_mix3(v0, v1, v2, bary));
    vec3 a = abs(s.p);
    s.p_error = point_error_bound(triangle_coordinate_magnitude(e, v0, v1, v2), s.p) +
                FLOAT_UNIT_ROUNDOFF * max(max(a.x, a.y), a.z) * e.rounding_mix;
    s.ng = normalize(instance_normal_to_world(t, cross(v1 - v0, v2 - v0)));
    s.ns = s.ng;
    s.uv = vec2(0.0f);
    s.uv1 = vec2(0.0f);
    s.tangent = vec3(0.0f);
    s.bitangent = vec3(0.0f);
    return s;
}

inline SurfacePoint surface_point(Instance t, vec3 v0, vec3 v1, vec3 v2, vec2 bary) {
    return surface_point_with(t, instance_error_terms(t), v0, v1, v2, bary);
}

// Moves the hit point to where the ray (o, d) meets the triangle's plane. Rebuilt from float
// barycentrics, the point is off by their error times the triangle's size, along the plane:
// ~10 units on a triangle 2e8 long, whose barycentrics are good to ~6e-8 (docs/stress.md). The
// plane through that point with normal ng is still the triangle's to the rounding of p (the
// barycentric error moves p within it), so t = dot(p - o, ng) / dot(d, ng) and q = o + t d land
// where the ray meets the triangle, laterally to a few ulps of |p - o|, however large the
// triangle. The step q + dot(p - q, ng) ng then puts q back on p's plane, so that the distance
// from the plane stays the one p_error bounds, plus the rounding of that step: the difference
// and the dot (gamma(4) |p - q| along ng, below sqrt(3) gamma(4) < 8u times its largest
// coordinate: SNAP_GAMMA). A ray in the plane (dot(d, ng) = 0) or a degenerate
// triangle (ng NaN) keeps the barycentric point.
const float SNAP_GAMMA = 8.0f * FLOAT_UNIT_ROUNDOFF;

inline void surface_snap_to_ray(INOUT(SurfacePoint) s, vec3 o, vec3 d) {
    float t = dot(s.p - o, s.ng) / dot(d, s.ng);
    if (!(abs(t) < FLOAT_MAX)) return;
    vec3 q = o + t * d;
    vec3 e = abs(s.p - q);
    s.p = q + dot(s.p - q, s.ng) * s.ng;
    s.p_error += vec3(SNAP_GAMMA * max(max(e.x, e.y), e.z));
}

// Interpolated vertex normals; flipped onto the geometric side when the mesh's normals
// disagree with its winding, and ignored when they degenerate.
inline void surface_set_shading_normal(INOUT(SurfacePoint) s, Instance t, vec3 n0, vec3 n1, vec3 n2,
                                       vec2 bary) {
    vec3 n = instance_normal_to_world(t, barycentric_mix3(n0, n1, n2, bary));
    float len = length(n);
    if (!(len > 0.0f)) return;
    n = n / len;
    s.ns = dot(n, s.ng) < 0.0f ? -n : n;
}

// The tangent frame of a normal map from the object-space interpolated normal n and tangent tg
// (xyz, and the bitangent's sign in w): glTF 2.0, "Meshes": bitangent = cross(normal, tangent)
// tangent.w. Both are surface directions, so they transform as vectors; the bitangent is formed
// before the transform so that a mirroring instance keeps the frame's handedness.
inline void surface_set_tangent_frame(INOUT(SurfacePoint) s, Instance t, vec3 n, vec4 tg) {
    vec3 tangent = vec3(tg.x, tg.y, tg.z);
    s.tangent = instance_vector_to_world(t, tangent);
    s.bitangent = instance_vector_to_world(t, cross(n, tangent) * (tg.w < 0.0f ? -1.0f : 1.0f));
}

// Bends the shading normal by a tangent-space normal-map texel c (linear, in [0, 1]^3):
// n' = normalize(T x + B y + N z) with (x, y, z) = (2 c - 1) (scale, scale, 1) (glTF 2.0,
// "normalTexture"), T made orthogonal to the shading normal N and B = N x T on the side of the
// frame's bitangent. Without a tangent frame, or for a texel that decodes to a zero vector, the
// normal stays as it is.
inline void surface_apply_normal_map(INOUT(SurfacePoint) s, vec3 c, float scale) {
    vec3 n = s.ns;
    vec3 t = s.tangent - n * dot(n, s.tangent);
    float lt = length(t);
    if (!(lt > 0.0f)) return;
    t = t / lt;
    vec3 b = cross(n, t);
    if (dot(b, s.bitangent) < 0.0f) b = -b;
    vec3 v = 2.0f * c - 1.0f;
    vec3 m = (v.x * scale) * t + (v.y * scale) * b + v.z * n;
    float lm = length(m);
    if (!(lm > 0.0f)) return;
    s.ns = m / lm;
}

// Two-sided shading for the reflective models: turns both normals to wo's side. When the
// interpolated normal faces away from wo although the surface itself faces it (low-poly
// smooth meshes at grazing angles), the geometric normal is used instead so that the
// reflection models see a valid configuration.
inline void surface_face_viewer(INOUT(SurfacePoint) s, vec3 wo) {
    if (dot(s.ng, wo) < 0.0f) {
        s.ng = -s.ng;
        s.ns = -s.ns;
    }
    if (dot(s.ns, wo) <= 0.0f) s.ns = s.ng;
}

TP_NAMESPACE_END

#endif // TP_SHARED_SURFACE_H
