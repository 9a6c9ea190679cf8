// Light fixtures for the light-sampling tests: a triangle light seen from a point, a ray-triangle
// intersection in double precision for its pdf, and a small environment map with its pixel
// alias table, sampled and evaluated the way shared/scene_access.h does.
#pragma once

#include "scene/alias_table.h"
#include "shared/lights.h"
#include "support/chi2.h"

#include <glm/glm.hpp>

#include <cmath>
#include <optional>
#include <vector>

namespace tp::test::lights {

inline tp::vec3 test_shading_point() {
    return tp::vec3(0.1f, -0.2f, 0.3f);
}

// A scalene triangle about 2 m from the shading point, its front (CCW) face turned towards it.
inline tp::Light test_triangle_light() {
    tp::Light l{};
    l.type = tp::LIGHT_TRIANGLE;
    l.p0 = tp::vec3(-1.0f, 2.0f, -1.0f);
    l.p1 = tp::vec3(0.0f, 2.2f, 1.5f);
    l.p2 = tp::vec3(1.2f, 2.5f, -0.5f);
    const tp::vec3 c = (l.p0 + l.p1 + l.p2) / 3.0f;
    if (glm::dot(glm::cross(l.p1 - l.p0, l.p2 - l.p0), test_shading_point() - c) < 0.0f)
        std::swap(l.p1, l.p2);
    l.area = 0.5f * glm::length(glm::cross(l.p1 - l.p0, l.p2 - l.p0));
    l.normal = tp::triangle_light_normal(l.p0, l.p1, l.p2);
    l.value = tp::vec3(1.0f);
    return l;
}

inline glm::dvec3 to_centroid(const tp::Light& l, const tp::vec3& p) {
    return glm::normalize(glm::dvec3((l.p0 + l.p1 + l.p2) / 3.0f - p));
}

struct TriangleHit {
    double t;         // distance along the unit direction
    double cos_light; // cosine at the light, positive on its front face
};

// Moeller-Trumbore in double precision.
inline std::optional<TriangleHit> hit_triangle(const tp::Light& l, const tp::vec3& p,
                                               const glm::dvec3& w) {
    const glm::dvec3 a(l.p0), e1 = glm::dvec3(l.p1) - a, e2 = glm::dvec3(l.p2) - a;
    const glm::dvec3 q = glm::cross(w, e2);
    const double det = glm::dot(e1, q);
    if (det == 0.0) return std::nullopt;
    const glm::dvec3 s = glm::dvec3(p) - a;
    const double u = glm::dot(s, q) / det;
    const glm::dvec3 r = glm::cross(s, e1);
    const double v = glm::dot(w, r) / det;
    const double t = glm::dot(e2, r) / det;
    if (u < 0.0 || v < 0.0 || u + v > 1.0 || t <= 0.0) return std::nullopt;
    return TriangleHit{t, -glm::dot(glm::normalize(glm::cross(e1, e2)), w)};
}

struct EnvMap {
    uint32_t width = 16, height = 8;
    float rotation = 0.6f; // radians about +Y
    std::vector<tp::AliasEntry> table;
};

// Pixel luminances in [0.1, 2] with every 13th pixel black, weighted by sin(theta) of the pixel
// centre as flatten.cpp does; the sampling must be exact for any weights.
inline EnvMap test_environment_map() {
    EnvMap env;
    std::vector<double> weights(size_t(env.width) * env.height);
    for (uint32_t y = 0; y < env.height; ++y)
        for (uint32_t x = 0; x < env.width; ++x) {
            const uint32_t i = y * env.width + x;
            const double lum = i % 13 == 5 ? 0.0 : 0.1 + 1.9 * double((i * 7919u) % 101u) / 100.0;
            weights[i] = lum * std::sin(3.14159265358979 * (y + 0.5) / env.height);
        }
    env.table = tp::build_alias_table(weights);
    return env;
}

// Pixel by the alias table (u.x slot, u.y coin), then a point in it (u.z, u.w). The slot takes
// u.x's 24 random bits as the top of a 32-bit word: with the map's 128 = 2^7 pixels that
// choice is exact.
inline tp::LightSample sample_environment(const EnvMap& env, const glm::vec4& u) {
    const uint32_t bits = uint32_t(double(u.x) * 0x1p32);
    const uint32_t slot = tp::alias_slot_from_bits(bits, uint32_t(env.table.size()));
    const tp::AliasEntry& e = env.table[slot];
    const uint32_t pixel = tp::alias_resolve(slot, e.prob, e.alias, u.y);
    return tp::sample_environment_map(pixel, env.table[pixel].pdf, env.width, env.height,
                                      env.rotation, tp::vec2(u.z, u.w));
}

// A chart whose cells tile the map's pixels, 4 x 4 cells to a pixel: the axis is the map's
// pole (+Y), rows at equal steps of theta, and phi measured so that phi = 0 is the left edge of
// the (rotated) map: direction(theta, phi) = rotate_y(latlong_to_direction(phi / 2 pi, theta /
// pi)). The pdf is then smooth in every cell, and the cubature exact to rounding.
inline tp::test::chi2::SphereChart environment_chart(const EnvMap& env) {
    const double pi = 3.14159265358979323846;
    std::vector<double> theta, phi;
    for (uint32_t i = 0; i <= 4 * env.height; ++i)
        theta.push_back(pi * double(i) / (4.0 * env.height));
    for (uint32_t j = 0; j <= 4 * env.width; ++j)
        phi.push_back(2.0 * pi * double(j) / (4.0 * env.width));
    // latlong_to_direction at s = 0 (phi_map = -pi) points to +Z; phi grows towards -X.
    const glm::dvec3 t(tp::rotate_y(tp::vec3(0.0f, 0.0f, 1.0f), env.rotation));
    const glm::dvec3 b(tp::rotate_y(tp::vec3(-1.0f, 0.0f, 0.0f), env.rotation));
    return tp::test::chi2::SphereChart(glm::dvec3(0.0, 1.0, 0.0), t, b, theta, phi);
}

inline float environment_pdf(const EnvMap& env, const tp::vec3& w) {
    const tp::vec2 st = tp::environment_map_coords(w, env.rotation);
    const uint32_t pixel = tp::environment_map_pixel(st, env.width, env.height);
    return tp::environment_map_pdf(env.table[pixel].pdf, env.width, env.height,
                                   std::sin(st.y * tp::PI));
}

} // namespace tp::test::lights
