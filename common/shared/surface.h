// Hit reconstruction: from an instance, a triangle's object-space vertices and the hit's
// barycentrics to the world-space point and frame that shading uses. Both engines call these
// with the same inputs (Embree and the GPU traversal both report (u, v) as the weights of
// vertices 1 and 2), so they shade the same point.
#ifndef TP_SHARED_SURFACE_H
#define TP_SHARED_SURFACE_H

#include "math.h"
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

struct SurfacePoint {
    vec3 p;  // world position
    vec3 ng; // unit geometric normal, (v1 - v0) x (v2 - v0): the front (emitting) side
    vec3 ns; // unit shading normal, on ng's side
    vec2 uv;
};

inline SurfacePoint surface_point(Instance t, vec3 v0, vec3 v1, vec3 v2, vec2 bary) {
    SurfacePoint s;
    s.p = instance_point_to_world(t, barycentric_mix3(v0, v1, v2, bary));
    s.ng = normalize(instance_normal_to_world(t, cross(v1 - v0, v2 - v0)));
    s.ns = s.ng;
    s.uv = vec2(0.0f);
    return s;
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
