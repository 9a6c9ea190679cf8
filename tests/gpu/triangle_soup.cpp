#include "triangle_soup.h"

#include "scene/scene.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include <random>

namespace tp::test {

FlatScene soup(uint32_t seed, uint32_t count, double centre, double extent, double size,
               uint32_t instances, uint32_t degenerate) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Scene s;
    s.path = fmt::format("soup {}", seed);
    s.materials = {default_material()};
    s.material_names = {"grey"};
    Mesh mesh;
    for (uint32_t i = 0; i < count; ++i) {
        const glm::dvec3 c = centre + extent * glm::dvec3(u(rng), u(rng), u(rng));
        for (int k = 0; k < 3; ++k)
            mesh.positions.push_back(vec3(c + size * glm::dvec3(u(rng), u(rng), u(rng))));
        mesh.triangles.push_back(uvec3(3 * i, 3 * i + 1, 3 * i + 2));
    }
    s.meshes = {mesh};
    for (uint32_t i = 0; i < instances; ++i) {
        Object o;
        o.name = fmt::format("object {}", i);
        if (i > 0)
            o.transform = glm::translate(glm::scale(glm::mat4(1.0f), vec3(float(1.0 + u(rng)))),
                                         vec3(float(extent * u(rng)), 0.0f, 0.0f));
        s.objects.push_back(o);
    }
    s.camera.given = true;
    s.camera.eye = vec3(float(centre));
    s.camera.target = vec3(float(centre), float(centre), float(centre) - 1.0f);
    s.settings.width = s.settings.height = 8;
    FlatScene flat = flatten(s);
    // Collapsed after flatten(), which would drop zero-area triangles: the builder must still
    // hold them in boxes that contain them.
    for (uint32_t i = 0; degenerate > 0 && i < flat.meshes[0].triangle_count; i += degenerate) {
        const uvec3 t = flat.triangles[flat.meshes[0].first_triangle + i];
        vec3* p = &flat.positions[flat.meshes[0].first_vertex];
        p[t.y] = (i / degenerate) % 2 ? p[t.x] : p[t.x] + (p[t.x] - p[t.z]);
        p[t.z] = p[t.x];
    }
    return flat;
}

} // namespace tp::test
