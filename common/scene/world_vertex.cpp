#include "scene/world_vertex.h"

namespace tp {

vec3 world_vertex(const Instance& inst, vec3 p) {
    const glm::dvec3 q(p);
    const auto row = [&](vec4 r) { return glm::dot(glm::dvec3(r), q) + double(r.w); };
    return vec3(glm::dvec3(row(inst.to_world0), row(inst.to_world1), row(inst.to_world2)));
}

} // namespace tp
