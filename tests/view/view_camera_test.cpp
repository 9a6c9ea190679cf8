// The viewer's camera (view/view_camera.h) and input script (view/view_input.h).
#include "scene/flatten.h"
#include "scene/load.h"
#include "support/test_paths.h"
#include "util/error.h"
#include "view/view_camera.h"
#include "view/view_input.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <fstream>

namespace {

tp::Scene cornell(tp::SceneOverrides o = {}) {
    std::vector<std::string> warnings;
    tp::Scene s = tp::load_scene(tp::test::scenes_dir() + "/cornell.json", warnings);
    o.width = 40;
    o.height = 30;
    tp::apply_overrides(s, o);
    return s;
}

// Parses "--eye X,Y,Z --target ... --up ... --fov F" back into overrides.
tp::SceneOverrides parse_flags(const std::string& flags) {
    std::istringstream in(flags);
    tp::SceneOverrides o;
    std::string flag, value;
    while (in >> flag >> value) {
        if (flag == "--fov") {
            o.fov = std::stof(value);
            continue;
        }
        glm::dvec3 v;
        REQUIRE(std::sscanf(value.c_str(), "%lf,%lf,%lf", &v.x, &v.y, &v.z) == 3);
        if (flag == "--up")
            o.up = tp::vec3(v);
        else
            (flag == "--eye" ? o.eye : o.target) = v;
    }
    return o;
}

void check_same_camera(const tp::Camera& a, const tp::Camera& b) {
    // A camera made from the same floats by the same camera_make gives the same basis up to the
    // rounding of normalize and cross: a few float ulps of a unit vector (1.2e-7 each).
    const float tol = 1e-6f;
    CHECK(glm::length(a.forward - b.forward) < tol);
    CHECK(glm::length(a.right - b.right) < tol);
    CHECK(glm::length(a.up - b.up) < tol);
    CHECK(a.tan_half_fov_y == Approx(b.tan_half_fov_y).epsilon(1e-6));
}

} // namespace

TEST_CASE("the view camera starts as the scene's camera", "[view]") {
    const tp::FlatScene flat = tp::flatten(cornell());
    const tp::ViewCamera cam(flat);
    const tp::Camera c = cam.camera(flat.origin, 40, 30);
    check_same_camera(c, flat.params.camera);
    CHECK(glm::length(c.eye - flat.params.camera.eye) < 1e-6f);
}

TEST_CASE("P's flags make render reproduce the view after camera moves", "[view]") {
    const tp::FlatScene flat = tp::flatten(cornell());
    tp::ViewCamera cam(flat);
    cam.orbit(0.4, -0.2);
    cam.pan(0.05, 0.02);
    cam.dolly(0.8);
    cam.fly(0.01, 0.0, 0.03);
    cam.zoom_fov(-5.0);
    const tp::Camera view = cam.camera(flat.origin, 40, 30);
    // render flattens with the new eye as its origin; directions do not depend on the origin.
    const tp::FlatScene replay = tp::flatten(cornell(parse_flags(cam.render_flags())));
    check_same_camera(view, replay.params.camera);
    const glm::dvec3 eye_view = flat.origin + glm::dvec3(view.eye);
    const glm::dvec3 eye_replay = replay.origin + glm::dvec3(replay.params.camera.eye);
    CHECK(glm::length(eye_view - eye_replay) < 1e-6);
}

TEST_CASE("orbit keeps the target and its distance, pan and fly move both", "[view]") {
    const tp::FlatScene flat = tp::flatten(cornell());
    tp::ViewCamera cam(flat);
    const glm::dvec3 target = cam.target();
    const double d = glm::length(cam.eye() - target);
    cam.orbit(1.0, 0.5);
    CHECK(glm::length(cam.target() - target) == 0.0);
    CHECK(glm::length(cam.eye() - target) == Approx(d).epsilon(1e-12));
    // Pitching past the pole stops 1 degree short of it: the view direction never meets up.
    cam.orbit(0.0, -10.0);
    const tp::Camera c = cam.camera(flat.origin, 40, 30);
    CHECK(std::abs(double(glm::dot(c.forward, tp::vec3(0, 1, 0)))) <
          std::cos(0.99 * 3.14159 / 180.0));
    const glm::dvec3 offset = cam.eye() - cam.target();
    cam.pan(0.1, -0.2);
    CHECK(glm::length((cam.eye() - cam.target()) - offset) < 1e-12);
}

TEST_CASE("the input script names the file and line of a bad action", "[view]") {
    const std::string dir = tp::test::temp_dir("view-script");
    const std::string path = dir + "/s.txt";
    std::ofstream(path) << "# a comment\n0 key H\n3 orbit 10 -5\n\n4 wheel 2 # dolly\n";
    const std::vector<tp::ScriptedAction> a = tp::read_view_script(path);
    REQUIRE(a.size() == 3);
    CHECK(a[0].action.kind == tp::ViewAction::Key);
    CHECK(a[0].action.key == 'H');
    CHECK(a[1].frame == 3);
    CHECK(a[1].action.kind == tp::ViewAction::Orbit);
    CHECK(a[1].action.y == -5.0);
    CHECK(a[2].action.kind == tp::ViewAction::Wheel);
    for (const char* bad : {"1 jump 3\n", "x key P\n", "2 orbit 4\n", "2 key Z\n", "2 key P P\n"}) {
        std::ofstream(path) << "0 key H\n" << bad;
        INFO(bad);
        try {
            tp::read_view_script(path);
            FAIL("accepted");
        } catch (const tp::InputError& e) {
            CHECK(std::string(e.what()).find(path + ":2") != std::string::npos);
        }
    }
}
