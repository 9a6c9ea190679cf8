// Generated tangent frames (scene/tangents.h) against the analytic tangent of meshes with a known
// uv layout: glTF's (v down) and OBJ's (v up) conventions, mirrored and rotated maps, uv1, a
// curved surface, degenerate mappings, and flat normals by unwelding.
#include "scene/scene.h"
#include "scene/tangents.h"

#include <catch2/catch.hpp>
#include <glm/glm.hpp>

#include <cmath>

using tp::vec2;
using tp::vec3;
using tp::vec4;

namespace {

// The unit quad in the XY plane facing +Z (counter-clockwise seen from +Z), corners
// (0,0), (1,0), (1,1), (0,1), with the given uvs.
tp::Mesh quad(std::vector<vec2> uvs) {
    tp::Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.normals.assign(4, vec3(0, 0, 1));
    m.uvs = std::move(uvs);
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

// glTF's slot: (s, t) = (u, v), the identity.
tp::TextureSlot gltf_slot(uint32_t sampling = 0u) {
    return tp::make_texture_slot(0, vec3(1, 0, 0), vec3(0, 1, 0), sampling);
}

void check_all(const std::vector<vec4>& t, vec4 expected) {
    for (const vec4& v : t) {
        CAPTURE(v.x, v.y, v.z, v.w);
        CHECK(glm::length(vec3(v) - vec3(expected)) < 1e-6f);
        CHECK(v.w == expected.w);
    }
}

} // namespace

TEST_CASE("tangents of a quad mapped as glTF maps an upright image", "[unit][tangents]") {
    // glTF's uv (0, 0) is the image's top-left: u runs along +X, v down the quad (-Y). The
    // tangent is dP/du = +X; the image's up is +Y = cross(+Z, +X): handedness +1.
    const tp::Mesh m = quad({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
    const std::vector<vec4> t = tp::generate_tangents(m, gltf_slot());
    REQUIRE(t.size() == 4);
    check_all(t, vec4(1, 0, 0, 1));
}

TEST_CASE("a mirrored uv layout gives handedness -1", "[unit][tangents]") {
    // u runs along -X: the tangent is -X, and cross(+Z, -X) = -Y points down the image.
    const tp::Mesh m = quad({{1, 1}, {0, 1}, {0, 0}, {1, 0}});
    check_all(tp::generate_tangents(m, gltf_slot()), vec4(-1, 0, 0, -1));
    // Mirrored in v instead: the tangent stays +X, the image's up is now -Y.
    const tp::Mesh v = quad({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    check_all(tp::generate_tangents(v, gltf_slot()), vec4(1, 0, 0, -1));
}

TEST_CASE("tangents follow the slot's map: OBJ's v-up convention and a rotation",
          "[unit][tangents]") {
    // OBJ's uv (v = 0 at the bottom) through obj_texture_slot (t = 1 - v): upright, +1.
    const tp::Mesh m = quad({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    check_all(tp::generate_tangents(m, tp::obj_texture_slot(0, false)), vec4(1, 0, 0, 1));
    // A slot that swaps the axes, s = v, t = u, on glTF's upright layout: s grows down the
    // quad (-Y), and t = u grows along +X, so the image's up is -X: cross(+Z, -Y) = +X is down
    // the image, handedness -1.
    const tp::Mesh g = quad({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
    const tp::TextureSlot swap = tp::make_texture_slot(0, vec3(0, 1, 0), vec3(1, 0, 0), 0u);
    check_all(tp::generate_tangents(g, swap), vec4(0, -1, 0, -1));
}

TEST_CASE("tangents read the slot's uv set", "[unit][tangents]") {
    tp::Mesh m = quad({{0, 0}, {0, 0}, {0, 0}, {0, 0}}); // set 0 degenerate
    m.uvs1 = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    check_all(tp::generate_tangents(m, gltf_slot(tp::SLOT_UV1)), vec4(1, 0, 0, 1));
}

TEST_CASE("tangents are orthogonal to the vertex normal and follow a curved surface",
          "[unit][tangents]") {
    // A strip bent around the Y axis: x = sin(a), z = cos(a) for a in [-0.6, 0.6], y in
    // [0, 1], u = a (along the bend), v = 1 - y. Normals point outwards: the tangent at a
    // vertex is the circle's tangent (cos a, 0, -sin a), handedness +1.
    tp::Mesh m;
    const int n = 6;
    for (int i = 0; i <= n; ++i) {
        const double a = -0.6 + 1.2 * i / n;
        for (int j = 0; j < 2; ++j) {
            m.positions.push_back({std::sin(a), double(j), std::cos(a)});
            m.normals.push_back(vec3(float(std::sin(a)), 0.0f, float(std::cos(a))));
            m.uvs.push_back(vec2(float(a), float(1 - j)));
        }
    }
    for (uint32_t i = 0; i < uint32_t(n); ++i) {
        const uint32_t a = 2 * i, b = 2 * i + 2;
        m.triangles.push_back({a, b, b + 1});
        m.triangles.push_back({a, b + 1, a + 1});
    }
    const std::vector<vec4> t = tp::generate_tangents(m, gltf_slot());
    for (size_t v = 0; v < t.size(); ++v) {
        CAPTURE(v);
        CHECK(std::abs(glm::dot(vec3(t[v]), m.normals[v])) < 1e-6f);
        CHECK(glm::length(vec3(t[v])) == Approx(1.0f).epsilon(1e-6));
        CHECK(t[v].w == 1.0f);
        // A face's tangent is its chord in the XZ plane; projected onto the plane of the
        // vertex normal, whose other axis is Y, it is the circle's tangent there exactly.
        const double a = -0.6 + 1.2 * double(v / 2) / n;
        const vec3 exact(float(std::cos(a)), 0.0f, float(-std::sin(a)));
        CHECK(glm::dot(vec3(t[v]), exact) > 1.0f - 1e-6f);
    }
}

TEST_CASE("a degenerate mapping gets some orthonormal tangent", "[unit][tangents]") {
    // All corners at one uv (and a mesh without uvs): no direction; any unit tangent
    // orthogonal to the normal, handedness +1.
    for (tp::Mesh m : {quad({{0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}}), quad({})}) {
        m.normals.assign(4, glm::normalize(vec3(1, 2, 3)));
        for (const vec4& t : tp::generate_tangents(m, gltf_slot())) {
            CHECK(std::isfinite(t.x));
            CHECK(glm::length(vec3(t)) == Approx(1.0f).epsilon(1e-6));
            CHECK(std::abs(glm::dot(vec3(t), m.normals[0])) < 1e-6f);
            CHECK(t.w == 1.0f);
        }
    }
}

TEST_CASE("unwelding gives every triangle its vertices and flat normal", "[unit][tangents]") {
    tp::Mesh m = quad({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
    m.positions[2].z = 1.0; // a fold along the diagonal 0-2
    m.normals.clear();
    m.uvs1 = m.uvs;
    tp::add_tangent_frame(m, gltf_slot());
    REQUIRE(m.positions.size() == 6);
    CHECK(m.triangles == std::vector<tp::uvec3>{{0, 1, 2}, {3, 4, 5}});
    CHECK(m.uvs.size() == 6);
    CHECK(m.uvs1.size() == 6);
    CHECK(m.tangents.size() == 6);
    CHECK(m.uvs[5] == vec2(0, 0)); // corner 3 of the quad
    // Triangle (0, 1, 2) with p2 = (1, 1, 1): normal cross((1,0,0), (1,1,1)) = (0, -1, 1)/sqrt2.
    const vec3 n0 = glm::normalize(vec3(0, -1, 1));
    for (int k = 0; k < 3; ++k) CHECK(glm::length(m.normals[size_t(k)] - n0) < 1e-6f);
    // Triangle (0, 2, 3): cross((1,1,1), (0,1,0)) = (-1, 0, 1)/sqrt2.
    const vec3 n1 = glm::normalize(vec3(-1, 0, 1));
    for (int k = 3; k < 6; ++k) CHECK(glm::length(m.normals[size_t(k)] - n1) < 1e-6f);
    for (size_t v = 0; v < 6; ++v)
        CHECK(std::abs(glm::dot(vec3(m.tangents[v]), m.normals[v])) < 1e-6f);
}
