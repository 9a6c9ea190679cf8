// Light sampling for next-event estimation and the light-side pdfs that multiple importance
// sampling needs. Radiometry follows docs/design.md: a point light's intensity I (W/sr) arrives as
// I / d^2; a directional light's irradiance E (W/m^2) arrives as E on a surface facing it;
// triangles and the environment carry radiance. Light *selection* (alias table) is the
// caller's, so every pdf here is conditional on the light having been chosen.
#ifndef TP_SHARED_LIGHTS_H
#define TP_SHARED_LIGHTS_H

#include "sampling.h"
#include "texture.h"
#include "types.h"

TP_NAMESPACE_BEGIN

struct LightSample {
    vec3 wi;       // unit direction from the shading point towards the light
    float dist;    // distance to the sampled point; FLOAT_MAX for directional and environment
    vec3 radiance; // arriving radiance, or I / d^2 and E for the delta lights
    float pdf;     // solid-angle pdf; 1 for delta lights; 0 marks an unusable sample
    vec3 point;    // the sampled point on the light (point and triangle lights)
    bool delta;    // point or directional: no MIS, the BSDF can never hit it
};

inline LightSample light_sample_none() {
    LightSample s;
    s.wi = vec3(0.0f, 0.0f, 1.0f);
    s.dist = 0.0f;
    s.radiance = vec3(0.0f);
    s.pdf = 0.0f;
    s.point = vec3(0.0f);
    s.delta = false;
    return s;
}

inline LightSample sample_point_light(Light l, vec3 p) {
    vec3 d = l.p0 - p;
    float dist2 = dot(d, d);
    if (dist2 <= 0.0f) return light_sample_none(); // the light sits exactly on the point
    LightSample s;
    s.dist = sqrt(dist2);
    s.wi = d / s.dist;
    s.radiance = l.value / dist2;
    s.point = l.p0;
    s.pdf = 1.0f;
    s.delta = true;
    return s;
}

// A spot light (KHR_lights_punctual): a point light whose intensity falls from I on the axis
// to 0 at the outer cone, smoothly over the angles between the cones: with c the cosine to the
// axis, f = clamp(c s + o, 0, 1)^2, where s = 1 / max(1e-3, cos(inner) - cos(outer)) and
// o = -cos(outer) s are stored in p2.xy (the extension's recommended falloff).
inline float spot_light_falloff(Light l, vec3 wi) {
    float f = clamp(-dot(wi, l.p1) * l.p2.x + l.p2.y, 0.0f, 1.0f);
    return f * f;
}

inline LightSample sample_spot_light(Light l, vec3 p) {
    LightSample s = sample_point_light(l, p);
    if (s.pdf > 0.0f) s.radiance *= spot_light_falloff(l, s.wi);
    return s;
}

inline LightSample sample_directional_light(Light l) {
    LightSample s;
    s.wi = l.p0;
    s.dist = FLOAT_MAX;
    s.radiance = l.value;
    s.point = vec3(0.0f);
    s.pdf = 1.0f;
    s.delta = true;
    return s;
}

// The unit normal of a triangle light's front (counter-clockwise) face; the scene loader stores
// it in Light::normal.
inline vec3 triangle_light_normal(vec3 p0, vec3 p1, vec3 p2) {
    return normalize(cross(p1 - p0, p2 - p0));
}

// The normal that sampling and shadow rays use: Light::normal as stored, or, with
// `from_vertices`, formed again from the vertices (the same value): an engine picks whichever
// is cheaper for it, a read of 12 more bytes per light or a cross product and a normalization
// (docs/gpu.md, "Stored light normal").
inline vec3 light_normal(Light l, bool from_vertices) {
    return from_vertices ? triangle_light_normal(l.p0, l.p1, l.p2) : l.normal;
}

// Area measure to solid angle: p_omega = p_A d^2 / cos(theta_l), with p_A = 1 / area.
inline float triangle_light_pdf(float area, float dist, float cos_light) {
    if (cos_light <= 0.0f || area <= 0.0f) return 0.0f;
    return dist * dist / (cos_light * area);
}

// from_vertices: how the light's normal is had (light_normal).
inline LightSample sample_triangle_light(Light l, vec3 p, vec2 u, bool from_vertices) {
    vec2 b = sample_uniform_triangle(u);
    vec3 q = l.p0 + b.x * (l.p1 - l.p0) + b.y * (l.p2 - l.p0);
    vec3 d = q - p;
    float dist2 = dot(d, d);
    if (dist2 <= 0.0f) return light_sample_none();
    LightSample s;
    s.dist = sqrt(dist2);
    s.wi = d / s.dist;
    // Emission leaves the front (counter-clockwise) face only.
    float cos_light = -dot(light_normal(l, from_vertices), s.wi);
    s.pdf = triangle_light_pdf(l.area, s.dist, cos_light);
    s.radiance = s.pdf > 0.0f ? l.value : vec3(0.0f);
    s.point = q;
    s.delta = false;
    return s;
}

// Constant environment: uniform sphere, pdf 1 / (4 pi).
inline LightSample sample_constant_environment(Light l, vec2 u) {
    LightSample s;
    s.wi = sample_uniform_sphere(u);
    s.dist = FLOAT_MAX;
    s.radiance = l.value;
    s.pdf = INV_FOUR_PI;
    s.point = vec3(0.0f);
    s.delta = false;
    return s;
}

// Environment map: a pixel is chosen with probability p_pixel (alias table over luminance x
// sin(theta)), then a point uniformly inside it in (s, t). The Jacobian of
// (s, t) -> direction is 2 pi^2 sin(theta), so p_omega = p_pixel w h / (2 pi^2 sin(theta)).
inline float environment_map_pdf(float p_pixel, uint w, uint h, float sin_theta) {
    if (sin_theta <= 0.0f) return 0.0f;
    return p_pixel * float(w) * float(h) / (2.0f * PI * PI * sin_theta);
}

// Point inside pixel `pixel` of a w x h map, in image coordinates (s, t).
inline vec2 environment_map_pixel_point(uint pixel, uint w, uint h, vec2 u) {
    uint py = pixel / w;
    uint px = pixel - py * w;
    return vec2((float(px) + u.x) / float(w), (float(py) + u.y) / float(h));
}

// Map coordinates (s, t) of world direction d for a map rotated by `rotation` about +Y.
inline vec2 environment_map_coords(vec3 d, float rotation) {
    return direction_to_latlong(rotate_y(d, -rotation));
}

// The pixel of a w x h map that contains image point st.
inline uint environment_map_pixel(vec2 st, uint w, uint h) {
    uint x = min(uint(st.x * float(w)), w - 1u);
    uint y = min(uint(st.y * float(h)), h - 1u);
    return y * w + x;
}

// Completes an environment-map sample once the engine has drawn `pixel` (probability p_pixel)
// from the map's alias table; the engine looks the radiance up itself.
inline LightSample sample_environment_map(uint pixel, float p_pixel, uint w, uint h, float rotation,
                                          vec2 u) {
    vec2 st = environment_map_pixel_point(pixel, w, h, u);
    LightSample s;
    s.wi = rotate_y(latlong_to_direction(st), rotation);
    s.dist = FLOAT_MAX;
    s.radiance = vec3(0.0f);
    s.pdf = environment_map_pdf(p_pixel, w, h, sin(st.y * PI));
    s.point = vec3(0.0f);
    s.delta = false;
    return s;
}

// Every light but the environment *map*, whose pixel table the engine reads itself.
inline LightSample sample_light(Light l, vec3 p, vec2 u, bool normal_from_vertices) {
    if (l.type == LIGHT_POINT) return sample_point_light(l, p);
    if (l.type == LIGHT_SPOT) return sample_spot_light(l, p);
    if (l.type == LIGHT_DIRECTIONAL) return sample_directional_light(l);
    if (l.type == LIGHT_TRIANGLE) return sample_triangle_light(l, p, u, normal_from_vertices);
    return sample_constant_environment(l, u);
}

TP_NAMESPACE_END

#endif // TP_SHARED_LIGHTS_H
