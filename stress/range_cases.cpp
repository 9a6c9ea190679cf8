// The range group: objects far from the camera, inside and beyond the float32 range rule
// (docs/scene-format.md, "Range"). An object out of view changes no pixel's expectation; past
// the rule's 2^36 m the scene is an input error that names the object.
#include "stress/common.h"

#include "scene/generators.h"
#include "util/error.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

namespace tp::stress {
namespace {

const glm::mat4 I4(1.0f);

// The reference scene with one more black object `name`, placed by `transform`.
Scene with_far_object(const Size& s, const char* name, Mesh mesh, const glm::mat4& transform) {
    Scene scene = reference_scene(s.image, s.spp);
    const uint32_t black = add_material(scene, "black", phong(vec3(0.0f)));
    add_object(scene, name, add_mesh(scene, std::move(mesh)), black, transform);
    return scene;
}

} // namespace

std::vector<CaseResult> range_cases(const Engine& e, const Size& s) {
    std::vector<CaseResult> out;
    Rendered ref;
    try {
        ref = render(e, flatten(reference_scene(s.image, s.spp)), 1);
    } catch (const std::exception& ex) {
        CaseResult c = make_case("range", "reference", e, "renders");
        c.measured = std::string("threw: ") + ex.what();
        return {c};
    }
    // Out of view (the camera looks along -z from z = 3.6): a unit box beside the scene, and a
    // sphere of radius 1e9 at 4e10, which hides 1.6e-4 of the dim environment's sphere of
    // directions from any point: far below the noise of these renders.
    struct Inside {
        const char* name;
        Mesh mesh;
        glm::mat4 transform;
    };
    const Inside inside[] = {
        {"far object at 1e10", make_box(), glm::translate(I4, vec3(1e10f, 0.0f, 0.0f))},
        {"huge object far away", make_icosphere(3, false),
         glm::scale(glm::translate(I4, vec3(-4e10f, 0.0f, 0.0f)), vec3(1e9f))}};
    uint32_t seed = 2;
    for (const Inside& v : inside)
        out.push_back(timed(make_case("range", v.name, e,
                                      "statistically consistent with the scene without it, no "
                                      "NaN/Inf, no new black pixel"),
                            [&](CaseResult& c) {
                                const Rendered r = render(
                                    e, flatten(with_far_object(s, v.name, v.mesh, v.transform)),
                                    seed++);
                                expect_consistent(c, ref, r, s.alpha);
                            }));
    // Beyond the rule: CPU renders of the Cornell box with its short block at x = 1e24 or more
    // were black (every triangle grown by 2^-17 of the scene's extent, cpu_ref/exact_triangles.h).
    for (const float x : {1e20f, 1e30f}) {
        const std::string name = fmt::format("far object at {:.0e}", x);
        out.push_back(timed(
            make_case("range", name, e, "an input error naming the object"), [&](CaseResult& c) {
                const Scene scene = with_far_object(s, name.c_str(), make_box(),
                                                    glm::translate(I4, vec3(x, 0.0f, 0.0f)));
                try {
                    render(e, flatten(scene), 1);
                    c.measured = "rendered";
                } catch (const InputError& ex) {
                    c.measured = ex.what();
                    c.pass = c.measured.find("'" + name + "'") != std::string::npos;
                }
            }));
    }
    return out;
}

} // namespace tp::stress
