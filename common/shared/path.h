// The integrator's per-vertex rules, shared so that both engines make the same decisions:
// multiple importance sampling weights, the geometric validity of scattered and light
// directions, and how new rays and shadow rays leave the surface. The path loop
// (integrator.h) follows this order per vertex:
//   1. add emission (MIS-weighted against light sampling unless the last bounce was specular)
//   2. stop at max_depth scattering events
//   3. next-event estimation: choose a light, sample it, trace a shadow ray
//   4. sample the BSDF, multiply the throughput, Russian roulette, spawn the next ray
#ifndef TP_SHARED_PATH_H
#define TP_SHARED_PATH_H

#include "alpha.h"
#include "brdf.h"
#include "camera.h"
#include "lights.h"
#include "offset.h"
#include "rng.h"

TP_NAMESPACE_BEGIN

// Power heuristic with beta = 2 for one sample from each of two strategies
// (Veach 1997, sec. 9.2.4, eq. 9.13).
inline float power_heuristic(float pdf_this, float pdf_other) {
    float a = pdf_this * pdf_this;
    float b = pdf_other * pdf_other;
    if (!(a > 0.0f)) return 0.0f;
    if (isinf(a)) return 1.0f;
    return a / (a + b);
}

// Weight of emission found by a BSDF-sampled ray. light_pdf is the solid-angle density with
// which next-event estimation would have produced the same direction (selection included).
inline float emission_mis_weight(bool prev_specular, float prev_bsdf_pdf, float light_pdf) {
    if (prev_specular) return 1.0f;
    return power_heuristic(prev_bsdf_pdf, light_pdf);
}

// A reflected direction must leave on the viewer's side of the true surface and a transmitted
// one on the other side; otherwise shading normals would leak light through the surface.
// ng is the geometric normal (either orientation), wo the direction towards the viewer.
inline bool scatter_is_consistent(vec3 ng, vec3 wo, vec3 wi, uint lobe) {
    float side_o = dot(ng, wo);
    float side_i = dot(ng, wi);
    bool transmitted = (lobe & LOBE_TRANSMISSION) != 0u;
    return transmitted ? side_o * side_i < 0.0f : side_o * side_i > 0.0f;
}

struct Ray {
    vec3 origin;
    float tmax; // the hit must lie in (0, tmax)
    vec3 dir;   // unit
    uint tag;   // the ray's identity for alpha BLEND's coin (alpha.h, ray_tag); 0: none
};

// New ray leaving p (coordinate error bound p_error, offset.h) in direction d (unit) from a
// surface with geometric normal ng; slack: the intersector's factor on the bound
// (offset_ray_origin).
inline Ray spawn_ray(vec3 p, vec3 p_error, vec3 ng, vec3 d, float slack) {
    Ray r;
    r.origin = offset_ray_origin(p, p_error, dot(d, ng) > 0.0f ? ng : -ng, slack);
    r.dir = d;
    r.tmax = FLOAT_MAX;
    r.tag = 0u;
    return r;
}

// The camera ray of one path: through pixel (x, y) jittered by the path's first two random
// numbers (rng.h), from the pinhole (camera.h). The path loops and the debug views of both
// engines start here, so a (seed, pixel, sample) names the same ray everywhere.
inline Ray camera_ray(Camera cam, RngKey key, uint x, uint y) {
    Ray r;
    r.origin = cam.eye;
    vec2 jitter = rng_get2(key, RNG_PIXEL_X);
    r.dir = camera_direction(cam, float(x) + jitter.x, float(y) + jitter.y);
    r.tmax = FLOAT_MAX;
    r.tag = ray_tag(key, 0u, RAY_TAG_PATH);
    return r;
}

// Shadow ray from p towards a light sample. A sample with a finite distance ends at the light
// point, itself moved off the light's surface by the same error-bound rule when the light is a
// triangle (its point is a barycentric mix of the world vertices p0..p2, whose magnitudes
// bound the error as a triangle's do in offset.h), so neither end can hit its own surface.
// slack: as for spawn_ray; normal_from_vertices: how the light's normal is had (light_normal).
inline Ray shadow_ray(vec3 p, vec3 p_error, vec3 ng, LightSample ls, Light l, float slack,
                      bool normal_from_vertices) {
    Ray r = spawn_ray(p, p_error, ng, ls.wi, slack);
    if (ls.dist >= FLOAT_MAX) return r;
    vec3 target = ls.point;
    if (l.type == LIGHT_TRIANGLE)
        target = offset_ray_origin(
            target, point_error_bound(triangle_vertex_magnitude(l.p0, l.p1, l.p2), target),
            light_normal(l, normal_from_vertices), slack);
    vec3 d = target - r.origin;
    float len = length(d);
    r.dir = len > 0.0f ? d / len : ls.wi;
    r.tmax = len;
    return r;
}

TP_NAMESPACE_END

#endif // TP_SHARED_PATH_H
