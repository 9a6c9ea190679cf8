// camera.h, the pinhole of thesis eq. 2.48 generalised to any aspect ratio: the centre of the
// film looks along the view direction, and its edges at +-tan(fov/2) * aspect horizontally and
// +-tan(fov/2) vertically, with pixel y growing downwards (docs/design.md, "Camera").
#include "shared/camera.h"

#include <catch2/catch.hpp>
#include <glm/glm.hpp>

#include <cmath>

namespace {

// Coordinates of d on the image plane at distance 1: (right, up) / forward.
glm::dvec2 plane(const tp::Camera& c, const tp::vec3& d) {
    const double f = glm::dot(glm::dvec3(d), glm::dvec3(c.forward));
    return glm::dvec2(glm::dot(glm::dvec3(d), glm::dvec3(c.right)) / f,
                      glm::dot(glm::dvec3(d), glm::dvec3(c.up)) / f);
}

} // namespace

TEST_CASE("camera frame is orthonormal and right-handed with Y up", "[camera]") {
    // Looking down -Z with +Y up, right is +X.
    const tp::Camera c =
        tp::camera_make(tp::vec3(0, 0, 5), tp::vec3(0), tp::vec3(0, 1, 0), 45.0f, 64, 32);
    CHECK(glm::length(c.forward - tp::vec3(0, 0, -1)) < 1e-7f);
    CHECK(glm::length(c.right - tp::vec3(1, 0, 0)) < 1e-7f);
    CHECK(glm::length(c.up - tp::vec3(0, 1, 0)) < 1e-7f);
    CHECK(c.aspect == 2.0f);
    // An up vector that is not orthogonal to the view is made so.
    const tp::Camera t = tp::camera_make(tp::vec3(1, 2, 3), tp::vec3(-2, 0.5f, 1),
                                         tp::vec3(0.2f, 1, 0.3f), 60.0f, 10, 10);
    CHECK(std::abs(glm::dot(t.forward, t.right)) < 1e-6f);
    CHECK(std::abs(glm::dot(t.forward, t.up)) < 1e-6f);
    CHECK(std::abs(glm::dot(t.right, t.up)) < 1e-6f);
    CHECK(glm::length(t.up) == Approx(1.0f).epsilon(1e-6));
    CHECK(glm::length(glm::cross(t.right, t.up) + t.forward) < 1e-6f); // right x up = -forward
    CHECK(glm::dot(t.up, tp::vec3(0.2f, 1, 0.3f)) > 0.0f);
}

TEST_CASE("film centre looks forward and the edges lie at tan(fov/2) times aspect and tan(fov/2)",
          "[camera]") {
    for (const auto& [w, h, fov] :
         {std::tuple{640u, 480u, 60.0f}, {100u, 300u, 20.0f}, {7u, 7u, 120.0f}}) {
        CAPTURE(w, h, fov);
        const tp::Camera c =
            tp::camera_make(tp::vec3(1, -2, 3), tp::vec3(4, 0, -1), tp::vec3(0, 1, 0), fov, w, h);
        const double tx = std::tan(glm::radians(double(fov)) / 2.0) * double(w) / double(h);
        const double ty = std::tan(glm::radians(double(fov)) / 2.0);
        const float W = float(w), H = float(h);
        CHECK(glm::length(tp::camera_direction(c, W / 2, H / 2) - c.forward) < 1e-6f);
        const struct {
            float px, py;
            double x, y;
        } points[] = {{0, 0, -tx, ty},
                      {W, 0, tx, ty},
                      {0, H, -tx, -ty},
                      {W, H, tx, -ty},
                      {0, H / 2, -tx, 0},
                      {W / 2, 0, 0, ty},
                      {W / 4, 3 * H / 4, -tx / 2, -ty / 2}};
        for (const auto& p : points) {
            const tp::vec3 d = tp::camera_direction(c, p.px, p.py);
            CHECK(glm::length(d) == Approx(1.0f).epsilon(1e-6));
            const glm::dvec2 q = plane(c, d);
            CHECK(q.x == Approx(p.x).margin(2e-6 * (1.0 + tx)));
            CHECK(q.y == Approx(p.y).margin(2e-6 * (1.0 + ty)));
        }
    }
}
