// The viewer's camera in the scene's own coordinates (double: FlatScene::origin is added back),
// and the moves of the mouse and keyboard: orbit about the target, pan, dolly, fly, field of
// view. Every move yields a new pinhole Camera (shared/camera.h) for the engine, in the
// camera-relative world the scene was flattened into.
#pragma once

#include "scene/flatten.h"

#include <glm/vec3.hpp>

#include <string>

namespace tp {

class ViewCamera {
  public:
    // The scene's camera as flatten() made it; the target lies at the distance of the scene's
    // bounding-box centre along the view direction.
    explicit ViewCamera(const FlatScene& scene);

    // Rotates the eye about the target: `yaw` about the up vector, `pitch` about the right
    // vector (radians); the pitch stops short of the up vector.
    void orbit(double yaw, double pitch);
    // Moves eye and target along right and up by fractions of the target distance.
    void pan(double right, double up);
    // Multiplies the target distance by `factor` (the eye moves, the target stays).
    void dolly(double factor);
    // Moves eye and target by (right, up, forward) fractions of the target distance.
    void fly(double right, double up, double forward);
    // Adds `degrees` to the vertical field of view, kept in [1, 170].
    void zoom_fov(double degrees);

    // The engine's camera for a film of width x height, relative to `origin`.
    Camera camera(const glm::dvec3& origin, uint32_t width, uint32_t height) const;
    // --eye X,Y,Z --target X,Y,Z --up X,Y,Z --fov F, with enough digits to give back the same
    // floats.
    std::string render_flags() const;

    const glm::dvec3& eye() const { return eye_; }
    const glm::dvec3& target() const { return target_; }
    float fov() const { return fov_; }

  private:
    glm::dvec3 eye_, target_, up_;
    float fov_;
};

} // namespace tp
