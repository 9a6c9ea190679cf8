#include "view/view_camera.h"

#include "shared/camera.h"

#include <fmt/core.h>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace tp {
namespace {

glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& axis, double angle) {
    // Rodrigues' rotation formula about a unit axis.
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0 - c);
}

} // namespace

ViewCamera::ViewCamera(const FlatScene& scene) {
    const Camera& c = scene.params.camera;
    eye_ = scene.origin + glm::dvec3(c.eye);
    const glm::dvec3 forward(c.forward);
    const glm::dvec3 centre = 0.5 * (glm::dvec3(scene.bounds_min) + glm::dvec3(scene.bounds_max));
    double distance = glm::dot(centre - glm::dvec3(c.eye), forward);
    if (!(distance > 0)) distance = glm::length(centre - glm::dvec3(c.eye));
    if (!(distance > 0)) distance = 1.0;
    target_ = eye_ + forward * distance;
    up_ = glm::dvec3(c.up);
    fov_ = float(2.0 * std::atan(double(c.tan_half_fov_y)) * 180.0 / glm::pi<double>());
}

void ViewCamera::orbit(double yaw, double pitch) {
    glm::dvec3 offset = eye_ - target_;
    offset = rotate(offset, glm::normalize(up_), yaw);
    const glm::dvec3 dir = glm::normalize(-offset);
    const glm::dvec3 right = glm::normalize(glm::cross(dir, up_));
    // Keep 1 degree away from the poles, where right = dir x up is undefined.
    const double elevation = std::asin(std::clamp(glm::dot(dir, glm::normalize(up_)), -1.0, 1.0));
    const double limit = 89.0 * glm::pi<double>() / 180.0;
    const double p = std::clamp(elevation - pitch, -limit, limit) - elevation;
    offset = rotate(offset, right, -p);
    eye_ = target_ + offset;
}

void ViewCamera::pan(double right, double up) {
    const glm::dvec3 dir = glm::normalize(target_ - eye_);
    const glm::dvec3 r = glm::normalize(glm::cross(dir, up_));
    const glm::dvec3 u = glm::cross(r, dir);
    const double d = glm::length(target_ - eye_);
    const glm::dvec3 move = (r * right + u * up) * d;
    eye_ += move;
    target_ += move;
}

void ViewCamera::dolly(double factor) {
    eye_ = target_ + (eye_ - target_) * std::clamp(factor, 1e-3, 1e3);
}

void ViewCamera::fly(double right, double up, double forward) {
    const glm::dvec3 dir = glm::normalize(target_ - eye_);
    const glm::dvec3 r = glm::normalize(glm::cross(dir, up_));
    const glm::dvec3 u = glm::cross(r, dir);
    const double d = glm::length(target_ - eye_);
    const glm::dvec3 move = (r * right + u * up + dir * forward) * d;
    eye_ += move;
    target_ += move;
}

void ViewCamera::zoom_fov(double degrees) {
    fov_ = float(std::clamp(double(fov_) + degrees, 1.0, 170.0));
}

Camera ViewCamera::camera(const glm::dvec3& origin, uint32_t width, uint32_t height) const {
    return camera_make(vec3(eye_ - origin), vec3(target_ - origin), vec3(up_), fov_, width, height);
}

std::string ViewCamera::render_flags() const {
    // Positions are doubles in the scene (scene/scene.h): 17 digits give them back exactly; the
    // up vector is a float. + 0.0 turns -0 into 0.
    const auto position = [](const glm::dvec3& p) {
        return fmt::format("{:.17g},{:.17g},{:.17g}", p.x + 0.0, p.y + 0.0, p.z + 0.0);
    };
    const vec3 u(up_);
    return fmt::format("--eye {} --target {} --up {:.9g},{:.9g},{:.9g} --fov {:.9g}",
                       position(eye_), position(target_), u.x + 0.0f, u.y + 0.0f, u.z + 0.0f, fov_);
}

} // namespace tp
