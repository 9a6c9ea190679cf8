// offset.h and the hit point of surface.h: a spawned ray's origin lies on its side of the
// triangle's true plane and the watertight test (intersect.h) does not find that triangle again,
// at every scale and distance from the origin, under instance transforms; the offset scales
// with the scene; the point snapped to the ray is where the ray meets the triangle, even on a
// triangle 2e8 long.
#include "shared/intersect.h"
#include "shared/path.h"
#include "shared/surface.h"

#include <catch2/catch.hpp>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <random>

namespace {

glm::vec3 random_unit(std::mt19937& g) {
    std::normal_distribution<float> n;
    return glm::normalize(glm::vec3(n(g), n(g), n(g)));
}

tp::Instance make_instance(const glm::mat4& m) {
    const glm::mat4 w = glm::transpose(m), o = glm::transpose(glm::inverse(m));
    tp::Instance t{};
    t.to_world0 = w[0];
    t.to_world1 = w[1];
    t.to_world2 = w[2];
    t.to_object0 = o[0];
    t.to_object1 = o[1];
    t.to_object2 = o[2];
    return t;
}

// The world point of object point v under t, in double from the float rows: the surface the
// engines intersect (Embree and the compute traversal transform the ray, not the vertices).
glm::dvec3 world(const tp::Instance& t, const tp::vec3& v) {
    const glm::dvec4 h(glm::dvec3(v), 1.0);
    return {glm::dot(glm::dvec4(t.to_world0), h), glm::dot(glm::dvec4(t.to_world1), h),
            glm::dot(glm::dvec4(t.to_world2), h)};
}

// Does the ray hit triangle (a, b, c) of instance t, as the compute traversal tests it?
bool hits_again(const tp::Instance& t, const tp::vec3& a, const tp::vec3& b, const tp::vec3& c,
                const tp::Ray& r) {
    const tp::vec3 o = tp::instance_point_to_object(t, r.origin);
    const tp::vec3 d = tp::instance_vector_to_object(t, r.dir);
    tp::vec3 tuv;
    return tp::intersect_triangle(o, tp::watertight_ray(d), a, b, c, tp::FLOAT_MAX, tuv);
}

} // namespace

TEST_CASE("the offset origin lies strictly on the normal's side", "[offset]") {
    std::mt19937 g(11);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (int e = -8; e <= 8; ++e) {
        const float scale = std::pow(10.0f, float(e));
        for (int i = 0; i < 2000; ++i) {
            const tp::vec3 p = scale * tp::vec3(unit(g), unit(g), unit(g));
            const tp::vec3 n = random_unit(g);
            const tp::vec3 q = tp::offset_ray_origin(p, tp::point_error_bound(abs(p), p), n, 1.0f);
            const glm::dvec3 d = glm::dvec3(q) - glm::dvec3(p);
            CAPTURE(p.x, p.y, p.z, n.x, n.y, n.z);
            REQUIRE(glm::dot(d, glm::dvec3(n)) > 0.0);
            for (int k = 0; k < 3; ++k) // no coordinate moves against the normal
                REQUIRE(d[k] * double(n[k]) >= 0.0);
        }
    }
}

TEST_CASE("spawned rays clear their triangle at every scale and distance", "[offset]") {
    // Triangles of size s at distance D from the origin, s from 1e-4 to 1e5 and D up to 1e5 s
    // (the stress suite's scales and translations), built through a random rotation, scale and
    // translation as instances are. The hit is the surface point of random barycentrics,
    // snapped to a ray from a random origin; new rays leave it into both half-spaces at random
    // directions, grazing ones included (|cos| down to 1e-3). Each origin must lie on its side
    // of the exact plane (double, from the float rows and vertices) and the watertight test
    // must not meet the triangle again.
    std::mt19937 g(13);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f), bary(0.0f, 1.0f);
    int rays = 0;
    for (float s : {1e-4f, 1e-2f, 1.0f, 1e2f, 1e5f}) {
        for (float distance : {0.0f, 1.0f, 1e2f, 1e5f}) {
            for (int i = 0; i < 500; ++i) {
                const glm::vec3 axis = random_unit(g);
                const glm::mat4 m = glm::scale(
                    glm::rotate(glm::translate(glm::mat4(1.0f), s * distance * random_unit(g)),
                                3.0f * unit(g), axis),
                    glm::vec3(s * (1.5f + unit(g))));
                const tp::Instance t = make_instance(m);
                const tp::vec3 a(unit(g), unit(g), unit(g)), b(unit(g), unit(g), unit(g)),
                    c(unit(g), unit(g), unit(g));
                float u = bary(g), v = bary(g);
                if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
                tp::SurfacePoint sp = tp::surface_point(t, a, b, c, tp::vec2(u, v));
                const glm::dvec3 wa = world(t, a);
                const glm::dvec3 nd =
                    glm::normalize(glm::cross(world(t, b) - wa, world(t, c) - wa));
                if (!(std::abs(glm::dot(glm::dvec3(sp.ng), nd)) > 0.999)) continue; // sliver
                const tp::vec3 eye = sp.p + 3.0f * s * random_unit(g);
                tp::surface_snap_to_ray(sp, eye, glm::normalize(sp.p - eye));
                for (int j = 0; j < 8; ++j) {
                    tp::vec3 d = random_unit(g);
                    if (j < 2) d = glm::normalize(d - glm::dot(d, sp.ng) * sp.ng + 1e-3f * sp.ng);
                    const tp::Ray r = tp::spawn_ray(sp.p, sp.p_error, sp.ng, d, 1.0f);
                    const double side = glm::dot(glm::dvec3(r.origin) - wa, nd);
                    CAPTURE(s, distance, i, j);
                    REQUIRE(side * glm::dot(glm::dvec3(d), nd) > 0.0);
                    REQUIRE_FALSE(hits_again(t, a, b, c, r));
                    ++rays;
                }
            }
        }
    }
    CHECK(rays > 70000);
}

TEST_CASE("the offset scales with the scene", "[offset]") {
    // The same triangle and hit at scale 1 and 1e-4 (a power-of-two-free factor, so the float
    // values differ in every digit): offsets in ratio 1e-4 to a few u, not an absolute floor.
    const tp::vec3 a(-0.3f, 0.1f, 0.2f), b(0.7f, -0.2f, 0.4f), c(0.1f, 0.6f, -0.5f);
    const tp::vec3 d = glm::normalize(tp::vec3(0.2f, 1.0f, 0.3f));
    double len[2];
    int k = 0;
    for (float s : {1.0f, 1e-4f}) {
        const tp::Instance t = make_instance(glm::scale(glm::mat4(1.0f), glm::vec3(s)));
        const tp::SurfacePoint sp = tp::surface_point(t, a, b, c, tp::vec2(0.3f, 0.4f));
        const tp::Ray r = tp::spawn_ray(sp.p, sp.p_error, sp.ng, d, 1.0f);
        len[k++] = glm::length(glm::dvec3(r.origin) - glm::dvec3(sp.p));
    }
    CHECK(len[0] > 0.0);
    CHECK(len[1] / len[0] == Approx(1e-4).epsilon(1e-3));
    // And it is about 40 u of the coordinates' magnitude, not Waechter & Binder's 256 ulps.
    CHECK(len[0] < 100.0 * double(tp::FLOAT_UNIT_ROUNDOFF));
}

TEST_CASE("the snapped hit point of a floor 2e8 wide is where the ray meets it", "[offset]") {
    // The floor of the stress case "floor vertices at +-1e8" (y = 0). Rays from a camera 1.3
    // above it hit it within ~10 units; the barycentrics of the watertight test are good to ~1e-7
    // of 2e8, so the barycentric point is off by up to ~10 units, while o + t d with t from the
    // plane is good to a few u of |o| + t, and its y stays exactly 0.
    const tp::Instance t = make_instance(glm::scale(glm::mat4(1.0f), glm::vec3(1e8f)));
    const tp::vec3 v0(-1.0f, 0.0f, -1.0f), v1(-1.0f, 0.0f, 1.0f), v2(1.0f, 0.0f, 1.0f);
    const tp::vec3 w0 = tp::instance_point_to_world(t, v0), w1 = tp::instance_point_to_world(t, v1),
                   w2 = tp::instance_point_to_world(t, v2);
    std::mt19937 g(17);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    const tp::vec3 eye(0.0f, 1.3f, 3.6f);
    double worst_bary = 0.0, worst_snap = 0.0;
    for (int i = 0; i < 2000; ++i) {
        const tp::vec3 target(5.0f * unit(g), 0.0f, 5.0f * unit(g) - 2.0f);
        const tp::vec3 d = glm::normalize(target - eye);
        tp::vec3 tuv;
        if (!tp::intersect_triangle(eye, tp::watertight_ray(d), w0, w1, w2, tp::FLOAT_MAX, tuv))
            continue;
        tp::SurfacePoint sp = tp::surface_point(t, v0, v1, v2, tp::vec2(tuv.y, tuv.z));
        const double te = -double(eye.y) / double(d.y);
        const glm::dvec3 exact = glm::dvec3(eye) + te * glm::dvec3(d);
        worst_bary = std::max(worst_bary, glm::length(glm::dvec3(sp.p) - exact));
        tp::surface_snap_to_ray(sp, eye, d);
        const double err = glm::length(glm::dvec3(sp.p) - exact);
        worst_snap = std::max(worst_snap, err);
        CAPTURE(i, err);
        REQUIRE(sp.p.y == 0.0f);
        REQUIRE(err <= 8.0 * double(tp::FLOAT_UNIT_ROUNDOFF) * (glm::length(glm::dvec3(eye)) + te));
    }
    CHECK(worst_bary > 1.0); // what the snap is for
    CHECK(worst_snap < 1e-5);
}

TEST_CASE("floor rays next to a resting sphere start outside it at 1e5 along every axis",
          "[offset]") {
    // The stress case "translate 1e5 (all axes)": the floor (make_quad scaled by 2) and the
    // sphere of radius 0.5 resting on it at (0.2, 0.5, 0), moved by (-1e5, 1e5, 1e5). A floor
    // point at distance rho from the contact has the sphere h = 0.5 - sqrt(0.25 - rho^2) above
    // it (0.0635 at rho = 0.25). With the translation counted in the object magnitudes at 40 u,
    // the offset was 50 u 1e5 = 0.30 and the new origins of every floor point with rho < 0.55
    // lay inside the sphere: their paths stayed there, 51 black pixels at 64 x 64 on all three
    // engines. The hit point's true error along y is a few roundings of 1e5 (u 1e5 = 0.006).
    const tp::vec3 shift(-1e5f, 1e5f, 1e5f);
    const tp::Instance floor =
        make_instance(glm::scale(glm::translate(glm::mat4(1.0f), shift), glm::vec3(2.0f)));
    const tp::vec3 v0(-1.0f, 0.0f, 1.0f), v1(1.0f, 0.0f, 1.0f), v2(1.0f, 0.0f, -1.0f),
        v3(-1.0f, 0.0f, -1.0f);
    const glm::dvec3 centre = glm::dvec3(0.2, 0.5, 0.0) + glm::dvec3(shift);
    const tp::vec3 eye = tp::vec3(0.0f, 1.3f, 3.6f) + shift;
    int rays = 0;
    for (int i = 0; i < 64; ++i) {
        const float angle = 6.2831853f * float(i) / 64.0f;
        for (float rho : {0.25f, 0.35f, 0.5f}) {
            const tp::vec3 target =
                tp::vec3(0.2f + rho * std::cos(angle), 0.0f, rho * std::sin(angle)) + shift;
            const tp::vec3 d = glm::normalize(target - eye);
            const tp::vec3 o = tp::instance_point_to_object(floor, eye);
            const tp::vec3 od = tp::instance_vector_to_object(floor, d);
            tp::vec3 tuv;
            tp::SurfacePoint sp;
            if (tp::intersect_triangle(o, tp::watertight_ray(od), v0, v1, v2, tp::FLOAT_MAX, tuv))
                sp = tp::surface_point(floor, v0, v1, v2, tp::vec2(tuv.y, tuv.z));
            else if (tp::intersect_triangle(o, tp::watertight_ray(od), v0, v2, v3, tp::FLOAT_MAX,
                                            tuv))
                sp = tp::surface_point(floor, v0, v2, v3, tp::vec2(tuv.y, tuv.z));
            else
                continue; // behind the sphere's silhouette does not matter here: no floor hit
            tp::surface_snap_to_ray(sp, eye, d);
            const tp::Ray r =
                tp::spawn_ray(sp.p, sp.p_error, sp.ng, tp::vec3(0.0f, 1.0f, 0.0f), 1.0f);
            const double height = double(r.origin.y) - 1e5;
            CAPTURE(i, rho, height);
            REQUIRE(height > 0.0); // above the floor
            REQUIRE_FALSE(hits_again(floor, v0, v1, v2, r));
            REQUIRE_FALSE(hits_again(floor, v0, v2, v3, r));
            REQUIRE(glm::length(glm::dvec3(r.origin) - centre) > 0.5); // outside the sphere
            ++rays;
        }
    }
    CHECK(rays == 192);
}
