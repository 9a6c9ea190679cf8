// offset.h, Waechter & Binder (Ray Tracing Gems ch. 6): the offset origin lies strictly on the
// normal's side, by int(256 n_i) ulps per coordinate away from the origin region and by
// n_i / 65536 inside it, and that is enough to clear the rounding error of a hit point computed
// in float, at any distance from the origin.
#include "shared/offset.h"

#include <catch2/catch.hpp>
#include <glm/glm.hpp>

#include <cmath>
#include <random>

namespace {

glm::vec3 random_unit(std::mt19937& g) {
    std::normal_distribution<float> n;
    return glm::normalize(glm::vec3(n(g), n(g), n(g)));
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
            const tp::vec3 q = tp::offset_ray_origin(p, n);
            const glm::dvec3 d = glm::dvec3(q) - glm::dvec3(p);
            CAPTURE(p.x, p.y, p.z, n.x, n.y, n.z);
            REQUIRE(glm::dot(d, glm::dvec3(n)) > 0.0);
            for (int k = 0; k < 3; ++k) // no coordinate moves against the normal
                REQUIRE(d[k] * double(n[k]) >= 0.0);
        }
    }
}

TEST_CASE("away from the origin the offset is int(256 n) ulps per coordinate", "[offset]") {
    std::mt19937 g(12);
    std::uniform_real_distribution<float> mag(1.0f / 32.0f, 1e6f);
    for (int i = 0; i < 10000; ++i) {
        const tp::vec3 p(mag(g), -mag(g), mag(g));
        const tp::vec3 n = random_unit(g);
        const tp::vec3 q = tp::offset_ray_origin(p, n);
        for (int k = 0; k < 3; ++k) {
            const int ulps = std::abs(tp::floatBitsToInt(q[k]) - tp::floatBitsToInt(p[k]));
            CAPTURE(p[k], n[k]);
            REQUIRE(ulps == std::abs(int(256.0f * n[k])));
        }
    }
}

TEST_CASE("near the origin the offset is n / 65536", "[offset]") {
    const tp::vec3 n = glm::normalize(tp::vec3(1.0f, -2.0f, 0.5f));
    for (const tp::vec3& p : {tp::vec3(0.0f), tp::vec3(-0.0f), tp::vec3(0.01f, -0.03f, 1e-20f)}) {
        const tp::vec3 q = tp::offset_ray_origin(p, n);
        for (int k = 0; k < 3; ++k) CHECK(q[k] == p[k] + n[k] / 65536.0f);
    }
}

TEST_CASE("offset hit points clear the float error of triangles far from the origin", "[offset]") {
    // A hit point interpolated in float from its triangle's vertices (as surface.h does) is
    // off the true plane by a few ulps of its coordinates; the offset origin must be on the
    // normal's side of that plane, the one the next ray must not hit again, and on the other
    // side for the opposite normal. The plane is evaluated in double from the float vertices.
    // The offset never exceeds 256 ulps per coordinate, 256 * 2^-23 * |p| * sqrt(3) in length.
    std::mt19937 g(13);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f), bary(0.0f, 1.0f);
    for (float distance : {1.0f, 100.0f, 1e4f, 1e5f}) {
        for (int i = 0; i < 5000; ++i) {
            const tp::vec3 c = distance * random_unit(g);
            const tp::vec3 a = c + tp::vec3(unit(g), unit(g), unit(g));
            const tp::vec3 b = c + tp::vec3(unit(g), unit(g), unit(g));
            const tp::vec3 d = c + tp::vec3(unit(g), unit(g), unit(g));
            float u = bary(g), v = bary(g);
            if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
            const tp::vec3 p = (1.0f - u - v) * a + u * b + v * d;
            const tp::vec3 ng = glm::normalize(glm::cross(b - a, d - a));
            const glm::dvec3 nd = glm::normalize(
                glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(d) - glm::dvec3(a)));
            const auto side = [&](const tp::vec3& q) {
                return glm::dot(glm::dvec3(q) - glm::dvec3(a), nd);
            };
            const tp::vec3 front = tp::offset_ray_origin(p, ng),
                           back = tp::offset_ray_origin(p, -ng);
            CAPTURE(distance, i);
            REQUIRE(side(front) > 0.0);
            REQUIRE(side(back) < 0.0);
            REQUIRE(glm::length(glm::dvec3(front) - glm::dvec3(p)) <=
                    256.0 * std::ldexp(1.0, -23) * glm::length(glm::dvec3(p)) * std::sqrt(3.0) +
                        1.0 / 65536.0);
        }
    }
}
