// The outgoing directions of the BSDF goodness-of-fit cases, shared by the CPU and GPU suites
// so that both test the samplers in the same frames.
#pragma once

#include "shared/lang.h"

#include <glm/glm.hpp>

#include <cmath>

namespace tp::test::chi2 {

// A unit vector at angle theta from n, at a fixed azimuth about it.
inline tp::vec3 direction_at(const glm::dvec3& n, double theta_degrees) {
    const glm::dvec3 a = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 t = glm::normalize(glm::cross(n, a));
    const glm::dvec3 b = glm::cross(n, t);
    const double th = glm::radians(theta_degrees), phi = 0.7;
    return tp::vec3(std::cos(th) * n + std::sin(th) * (std::cos(phi) * t + std::sin(phi) * b));
}

} // namespace tp::test::chi2
