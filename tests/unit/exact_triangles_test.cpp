// The grown triangles that Embree traces for the CPU engine (cpu_ref/exact_triangles.h): each
// must hold its exact triangle with every edge moved out by delta, so that Embree's test, whose
// rounding stays below delta / 6, offers every ray that meets the exact triangle to the filter.
#include "cpu_ref/exact_triangles.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <random>

namespace {

using tp::vec3;

// Signed distance of p from the line through a and b in the plane with normal n, positive
// outside a counter-clockwise triangle (right of a -> b seen from n). In double: the test's own
// rounding stays far below the 1e-3 delta tolerance used below.
double outside_distance(glm::dvec3 a, glm::dvec3 b, glm::dvec3 n, glm::dvec3 p) {
    const glm::dvec3 out = glm::normalize(glm::cross(b - a, n));
    return glm::dot(p - a, out);
}

tp::ExactMesh one_triangle(vec3 a, vec3 b, vec3 c) {
    tp::ExactMesh m;
    m.vertices = {a, b, c};
    m.triangles = {tp::uvec3(0, 1, 2)};
    return m;
}

} // namespace

TEST_CASE("grown triangles hold their exact triangle with every edge moved out by delta",
          "[unit][cpu]") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const double delta = tp::exact_delta(1.0);
    CHECK(delta == std::ldexp(1.0, -17));
    int tested = 0;
    for (int k = 0; k < 2000; ++k) {
        const tp::ExactMesh m =
            one_triangle(vec3(u(rng), u(rng), u(rng)), vec3(u(rng), u(rng), u(rng)),
                         vec3(u(rng), u(rng), u(rng)));
        const glm::dvec3 p[3] = {glm::dvec3(m.vertices[0]), glm::dvec3(m.vertices[1]),
                                 glm::dvec3(m.vertices[2])};
        const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        // Corners sharper than 1 degree need a mitre over 100 delta; the cap (1024 delta) is
        // tested below.
        bool sharp = false;
        for (int i = 0; i < 3; ++i) {
            const glm::dvec3 e1 = glm::normalize(p[(i + 1) % 3] - p[i]);
            const glm::dvec3 e2 = glm::normalize(p[(i + 2) % 3] - p[i]);
            sharp |= std::acos(glm::clamp(glm::dot(e1, e2), -1.0, 1.0)) < 0.0175;
        }
        if (sharp) continue;
        ++tested;
        vec3 q[3];
        const float margin = tp::grow_triangles(m, delta, q);
        double longest = 0.0;
        for (int e = 0; e < 3; ++e) {
            const glm::dvec3 a(q[e]), b(q[(e + 1) % 3]);
            longest = std::max(longest, glm::length(b - a));
            // The grown edge runs delta outside the exact one (parallel: both of its ends are
            // delta out, to the float rounding of the grown corners, ~1e-7 of their size).
            CHECK(std::abs(outside_distance(p[e], p[(e + 1) % 3], n, a) - delta) <
                  1e-3 * delta + 2e-7);
            CHECK(std::abs(outside_distance(p[e], p[(e + 1) % 3], n, b) - delta) <
                  1e-3 * delta + 2e-7);
            // Every exact corner lies inside every grown edge.
            for (int i = 0; i < 3; ++i) CHECK(outside_distance(a, b, n, p[i]) < 0.0);
        }
        CHECK(margin == Approx(2.0 * delta * longest).epsilon(1e-6));
    }
    CHECK(tested > 1500);
}

TEST_CASE("a sharp corner's growth is capped, a zero-area triangle is left alone", "[unit][cpu]") {
    const double delta = tp::exact_delta(1.0);
    SECTION("a corner of 0.01 degrees moves 1024 delta along its bisector") {
        const float h = float(std::tan(0.5 * 0.01 * glm::pi<double>() / 180.0));
        const tp::ExactMesh m = one_triangle(vec3(0, 0, 0), vec3(1, -h, 0), vec3(1, h, 0));
        vec3 q[3];
        tp::grow_triangles(m, delta, q);
        // The bisector of the corner at the origin is -x; its mitre would be delta / sin(0.005
        // deg) = 11459 delta.
        CHECK(double(q[0].x) == Approx(-1024.0 * delta).epsilon(1e-3));
        CHECK(double(std::abs(q[0].y)) < 1e-3 * delta);
    }
    SECTION("zero area") {
        const tp::ExactMesh m = one_triangle(vec3(0, 0, 0), vec3(1, 0, 0), vec3(2, 0, 0));
        vec3 q[3];
        CHECK(tp::grow_triangles(m, delta, q) == 0.0f);
        for (int i = 0; i < 3; ++i) CHECK(q[i] == m.vertices[i]);
    }
}
