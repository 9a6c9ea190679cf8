// Where a scene sits does not change what the engines trace (docs/stress.md, "Scale and position"):
// the description keeps positions in double (scene/scene.h) and flatten() rounds to float only
// after moving the world next to the camera (FlatScene::origin), each mesh relative to its own
// lowest corner.
#include "scene/flatten.h"
#include "scene/generators.h"
#include "scene/load.h"
#include "shared/surface.h"
#include "support/test_paths.h"
#include "util/error.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

using tp::vec3;

const glm::dmat4 I(1.0);

// A floor, a sphere, an emissive quad facing down (the floor's mesh again: instancing), a point
// light and a camera, moved by `offset`. Every number is a float of magnitude above 2^-7, so
// for the offsets below (at most 1e6 < 2^20) each sum has at most 20 + 7 + 24 = 51 significant
// bits and is exact in double: the moved description is the same scene exactly.
tp::Scene scene_at(const glm::dvec3& offset) {
    tp::Scene s;
    s.path = "offset scene";
    tp::Material grey = tp::default_material();
    grey.kd = vec3(0.5f);
    tp::Material lamp = tp::default_material();
    lamp.ke = vec3(4.0f);
    s.materials = {grey, lamp};
    s.material_names = {"grey", "lamp"};
    s.meshes = {tp::make_quad(), tp::make_icosphere(2, false)};
    const glm::dmat4 at = glm::translate(I, offset);
    const auto add = [&](uint32_t mesh, uint32_t material, const glm::dmat4& m) {
        tp::Object o;
        o.mesh = mesh;
        o.material = material;
        o.transform = at * m;
        s.objects.push_back(o);
    };
    add(0, 0, glm::scale(I, glm::dvec3(2.0)));
    add(1, 0, glm::scale(glm::translate(I, glm::dvec3(vec3(0.2f, 0.5f, -0.3f))), glm::dvec3(0.5)));
    add(0, 1,
        glm::scale(glm::rotate(glm::translate(I, glm::dvec3(0.0, 2.0, 0.0)), glm::pi<double>(),
                               glm::dvec3(1, 0, 0)),
                   glm::dvec3(0.4)));
    tp::LightDesc p;
    p.type = tp::LIGHT_POINT;
    p.position = glm::dvec3(vec3(1.1f, 1.5f, 0.9f)) + offset;
    p.value = vec3(2.0f);
    s.lights = {p};
    s.camera.given = true;
    s.camera.eye = glm::dvec3(vec3(0.1f, 1.3f, 3.6f)) + offset;
    s.camera.target = glm::dvec3(vec3(0.0f, 0.4f, 0.0f)) + offset;
    s.settings.width = s.settings.height = 64;
    return s;
}

template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

template <typename T>
bool same_bits(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// The arrays both engines read, bit for bit.
void require_same_floats(const tp::FlatScene& a, const tp::FlatScene& b) {
    CHECK(same_bits(a.positions, b.positions));
    CHECK(same_bits(a.normals, b.normals));
    CHECK(same_bits(a.triangles, b.triangles));
    CHECK(same_bits(a.instances, b.instances));
    CHECK(same_bits(a.lights, b.lights));
    CHECK(same_bits(a.light_table, b.light_table));
    CHECK(same_bits(a.params.camera, b.params.camera));
    CHECK(same_bits(a.bounds_min, b.bounds_min));
    CHECK(same_bits(a.bounds_max, b.bounds_max));
}

fs::path write_file(const fs::path& p, const std::string& text) {
    std::ofstream(p) << text;
    return p;
}

} // namespace

// Before the description kept double, the floats of the scene at 1e5 were multiples of 2^-7
// (0.0078) and its world vertices differed from the origin's by up to 2^-8.
TEST_CASE("a scene moved with its camera flattens to the same floats", "[scene]") {
    const tp::FlatScene origin = tp::flatten(scene_at(glm::dvec3(0.0)));
    CHECK(origin.params.camera.eye == vec3(0.0f));
    for (const glm::dvec3 d : {glm::dvec3(1e2, -1e2, 1e2), glm::dvec3(-1e5, 1e5, 1e5),
                               glm::dvec3(1e6, -1e6, 1e6), glm::dvec3(1e6, 0.0, 0.0)}) {
        INFO("moved by " << d.x << ", " << d.y << ", " << d.z);
        const tp::FlatScene moved = tp::flatten(scene_at(d));
        CHECK(moved.origin == origin.origin + d);
        require_same_floats(origin, moved);
    }
}

// The same for a scene whose meshes are in world space (an OBJ file): the mesh's lowest corner
// moves with its vertices exactly, so its float offsets from it do not change.
TEST_CASE("world-space vertices moved with the camera flatten to the same floats", "[scene]") {
    const auto obj = [](const fs::path& dir, double d) {
        const auto v = [d](double x, double y, double z) {
            return fmt::format("v {:.17g} {:.17g} {:.17g}\n", x + d, y + d, z + d);
        };
        // A floor and a tilted triangle above it, coordinates on the grid of 2^-12.
        return write_file(dir / fmt::format("at{}.obj", d),
                          v(-1, 0, -1) + v(1, 0, -1) + v(1, 0, 1) + v(-1, 0, 1) +
                              v(0.25, 0.5, 0.125) + v(0.75, 0.625, 0.25) +
                              v(0.5, 1.0009765625, 0.375) + "f 1 4 3 2\nf 5 6 7\n");
    };
    const fs::path dir = tp::test::temp_dir("world-origin-obj");
    const auto flat = [&](double d) {
        std::vector<std::string> warnings;
        tp::Scene s = tp::load_scene(obj(dir, d).string(), warnings);
        tp::SceneOverrides o;
        o.eye = glm::dvec3(0.125 + d, 1.5 + d, 3.0 + d);
        o.target = glm::dvec3(d, 0.25 + d, d);
        tp::apply_overrides(s, o);
        return tp::flatten(s);
    };
    const tp::FlatScene origin = flat(0.0);
    for (const double d : {1e2, 1e4, 1e6}) {
        INFO("moved by " << d);
        require_same_floats(origin, flat(d));
    }
    fs::remove_all(dir);
}

// Positions are read in double: 1e-4 apart at 1e4 (float there rounds to multiples of 2^-10 =
// 9.8e-4) they stay 1e-4 apart, to float's precision near the camera.
TEST_CASE("JSON and OBJ positions and --eye are read in double", "[scene]") {
    const fs::path dir = tp::test::temp_dir("world-origin-double");
    std::vector<std::string> warnings;
    const tp::Scene o = tp::load_scene(
        write_file(dir / "s.obj",
                   "v 10000.0001 10000 10000\nv 10000.0002 10000 10000\nv 10000 10000.0001 "
                   "10000\nf 1 2 3\n")
            .string(),
        warnings);
    CHECK(o.meshes.at(0).positions.at(0).x == 10000.0001);
    CHECK(o.meshes.at(0).positions.at(1).x == 10000.0002);
    const tp::Scene j = tp::load_scene(write_file(dir / "s.json", R"({
  "camera": {"eye": [10000.0001, 10000, 10001], "target": [10000.0001, 10000.0002, 10000]},
  "materials": {"m": {"Kd": [0.5, 0.5, 0.5]}},
  "meshes": {"t": {"type": "triangles",
                   "vertices": [[10000.0001, 0, 0], [10000, 1, 0], [10000, 0, 1]],
                   "triangles": [[0, 1, 2]]}},
  "objects": [{"mesh": "t", "material": "m", "transform": {"translate": [0.0002, 10000, 10000]}}],
  "lights": [{"type": "point", "position": [10000.0003, 10000, 10000], "intensity": [1, 1, 1]}]
})")
                                           .string(),
                                       warnings);
    CHECK(j.camera.eye.x == 10000.0001);
    CHECK(j.camera.target.y == 10000.0002);
    CHECK(j.meshes.at(0).positions.at(0).x == 10000.0001);
    CHECK(j.objects.at(0).transform[3].x == 0.0002);
    CHECK(j.lights.at(0).position.x == 10000.0003);
    // Camera-relative: the point light 2e-4 from the eye along x, the vertex (10000.0003,
    // 10000, 10000) at 2e-4 too (the mesh is 1 m across: rounded by ~1e-7 of that).
    const tp::FlatScene f = tp::flatten(j);
    CHECK(f.lights.at(0).p0.x == Approx(2e-4).epsilon(1e-6));
    const tp::vec3 w = tp::instance_point_to_world(f.instances.at(0), f.positions.at(0));
    CHECK(w.x == Approx(2e-4).epsilon(1e-4));
    fs::remove_all(dir);
}

// The range rule (docs/scene-format.md, "Range") is about sizes and distances from the camera:
// where an object sits in its own space does not matter, its size there does.
TEST_CASE("the range rule: an object's size and its distance from the camera", "[scene]") {
    const double far = 0x1p40; // beyond the rule's 2^36
    const auto scene = [](tp::Mesh box, const glm::dmat4& transform) {
        tp::Scene s;
        s.path = "range";
        s.materials = {tp::default_material()};
        s.material_names = {"m"};
        s.meshes = {std::move(box)};
        tp::Object o;
        o.name = "box";
        o.transform = transform;
        s.objects = {o};
        s.camera.given = true;
        s.camera.eye = glm::dvec3(0.0, 0.0, 3.0);
        s.camera.target = glm::dvec3(0.0);
        return s;
    };
    // A unit box modelled 2^40 from its origin and moved back next to the camera: the same
    // floats as the box modelled in place (2^40 + 1 is exact in double).
    tp::Mesh distant = tp::make_box();
    for (glm::dvec3& p : distant.positions) p.x += far;
    const tp::FlatScene moved_back =
        tp::flatten(scene(distant, glm::translate(I, glm::dvec3(0.5 - far, 0.0, 0.0))));
    const tp::FlatScene in_place =
        tp::flatten(scene(tp::make_box(), glm::translate(I, glm::dvec3(0.5, 0.0, 0.0))));
    require_same_floats(in_place, moved_back);
    // A box 2^40 wide in its own space, scaled down to 2 m: an input error naming it.
    tp::Mesh wide = tp::make_box();
    for (glm::dvec3& p : wide.positions) p *= far;
    CHECK_THROWS_WITH(tp::flatten(scene(wide, glm::scale(I, glm::dvec3(1.0 / far)))),
                      Catch::Contains("object 0 ('box') spans") &&
                          Catch::Contains("in its own space"));
    // The box 2^40 from the camera: an input error naming the distance.
    CHECK_THROWS_WITH(tp::flatten(scene(tp::make_box(), glm::translate(I, glm::dvec3(far)))),
                      Catch::Contains("object 0 ('box') has a vertex") &&
                          Catch::Contains("from the camera"));
}
