// flatten() hands both engines a camera-relative world (FlatScene::origin, "large world
// coordinates"), so a scene far from its own origin keeps the float precision it has near it.
#include "scene/flatten.h"
#include "scene/generators.h"
#include "shared/surface.h"

#include <catch2/catch.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace {

using tp::vec3;
using tp::vec4;

// A floor, a sphere, an emissive quad facing down, a point light and a camera, every
// translation a multiple of 2^-7 and |t| < 8: moved by an offset of +-1e5 per axis, t + offset
// is then exact in float (floats in [2^16, 2^17) are the multiples of 2^-7), so the two
// descriptions are the same scene exactly and any difference comes from flatten().
tp::Scene scene_at(vec3 offset) {
    tp::Scene s;
    s.path = "offset scene";
    tp::Material grey = tp::default_material();
    grey.kd = vec3(0.5f);
    tp::Material lamp = tp::default_material();
    lamp.ke = vec3(4.0f);
    s.materials = {grey, lamp};
    s.material_names = {"grey", "lamp"};
    s.meshes = {tp::make_quad(), tp::make_icosphere(2, false)};
    const glm::mat4 at = glm::translate(glm::mat4(1.0f), offset);
    const auto add = [&](uint32_t mesh, uint32_t material, const glm::mat4& m) {
        tp::Object o;
        o.mesh = mesh;
        o.material = material;
        o.transform = at * m;
        s.objects.push_back(o);
    };
    const glm::mat4 I(1.0f);
    add(0, 0, glm::scale(I, vec3(2.0f)));
    add(1, 0, glm::scale(glm::translate(I, vec3(0.203125f, 0.5f, -0.0078125f)), vec3(0.5f)));
    add(0, 1,
        glm::scale(
            glm::rotate(glm::translate(I, vec3(0.0f, 2.0f, 0.0f)), glm::pi<float>(), vec3(1, 0, 0)),
            vec3(0.4f)));
    tp::Light p{};
    p.type = tp::LIGHT_POINT;
    p.p0 = vec3(1.0f, 1.5f, 1.0f) + offset;
    p.value = vec3(2.0f);
    s.lights = {p};
    s.camera.given = true;
    s.camera.eye = vec3(0.0f, 1.296875f, 3.6015625f) + offset;
    s.camera.target = vec3(0.0f, 0.3984375f, 0.0f) + offset;
    s.settings.width = s.settings.height = 64;
    return s;
}

// A camera-relative float position in the scene's coordinates, less the offset, in double (its
// rounding, below 2^-36 at 1e5, is far below the tolerance).
glm::dvec3 placed(vec3 p, const tp::FlatScene& f, vec3 offset) {
    return glm::dvec3(p) + f.origin - glm::dvec3(offset);
}

} // namespace

// The float world positions the engines compute (hit points and light vertices through
// instance_point_to_world, the camera, point lights, bounds) must agree between the scene and
// the same scene 1e5 away along every axis to the spacing of the untranslated scene's floats:
// its camera-relative coordinates are below 8, where floats are 2^-21 apart; 2^-20 allows one
// rounding on each side. Without the rebase the translated world's floats are multiples of 2^-7
// (0.0078) and differ by up to 2^-8 = 0.0039.
TEST_CASE("a scene 1e5 away flattens to the precision it has at the origin", "[scene]") {
    const double spacing = std::ldexp(1.0, -20);
    const vec3 far(-1e5f, 1e5f, 1e5f);
    const tp::FlatScene a = tp::flatten(scene_at(vec3(0.0f)));
    const tp::FlatScene b = tp::flatten(scene_at(far));
    const auto near_enough = [&](vec3 pa, vec3 pb) {
        const glm::dvec3 d = glm::abs(placed(pa, a, vec3(0.0f)) - placed(pb, b, far));
        return std::max(d.x, std::max(d.y, d.z)) <= spacing;
    };
    REQUIRE(a.instances.size() == b.instances.size());
    double worst = 0.0;
    for (size_t i = 0; i < a.instances.size(); ++i) {
        const tp::MeshInfo& m = a.meshes[a.instances[i].mesh];
        for (uint32_t v = 0; v < m.vertex_count; ++v) {
            const vec3 p = a.positions[m.first_vertex + v];
            const vec3 wa = tp::instance_point_to_world(a.instances[i], p);
            const vec3 wb = tp::instance_point_to_world(b.instances[i], p);
            const glm::dvec3 d = glm::abs(placed(wa, a, vec3(0.0f)) - placed(wb, b, far));
            worst = std::max(worst, std::max(d.x, std::max(d.y, d.z)));
        }
    }
    INFO("worst world-vertex difference " << worst);
    CHECK(worst <= spacing);
    // The eye is the origin of the camera-relative world; the view is the same.
    CHECK(b.params.camera.eye == vec3(0.0f));
    CHECK(near_enough(a.params.camera.eye, b.params.camera.eye));
    CHECK(glm::length(a.params.camera.forward - b.params.camera.forward) <= 1e-7f);
    // The point light, the emitter's triangles (lights 1 and 2) and the bounds.
    REQUIRE(a.lights.size() == b.lights.size());
    for (size_t k = 0; k < a.lights.size(); ++k) {
        CHECK(near_enough(a.lights[k].p0, b.lights[k].p0));
        if (a.lights[k].type != tp::LIGHT_TRIANGLE) continue;
        CHECK(near_enough(a.lights[k].p1, b.lights[k].p1));
        CHECK(near_enough(a.lights[k].p2, b.lights[k].p2));
    }
    CHECK(near_enough(a.bounds_min, b.bounds_min));
    CHECK(near_enough(a.bounds_max, b.bounds_max));
}
