// What the glTF loader (scene/gltf_loader.h) makes of good input, from files the tests write
// (support/gltf_builder.h): the node hierarchy and instancing, the ways a buffer can hold the
// data (external, embedded, GLB, interleaved, normalized, sparse, strips and fans), textures and
// uvs, cameras, lights, the feature mask, what is listed as not rendered, and the Cornell box
// flattening to exactly what its OBJ twin flattens to. Bad input: tests/cli/bad_input_test.cpp.
#include "image/png_io.h"
#include "scene/features.h"
#include "scene/flatten.h"
#include "scene/load.h"
#include "shared/surface.h"
#include "support/cornell_files.h"
#include "support/gltf_builder.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

using tp::test::GltfBuilder;
using json = nlohmann::json;

namespace {

struct Loaded {
    tp::Scene scene;
    std::vector<std::string> warnings;
};

Loaded load(const std::string& path, tp::LoadOptions options = {}) {
    Loaded l;
    l.scene = tp::load_scene(path, l.warnings, options);
    return l;
}

bool mentions(const std::vector<std::string>& notes, const std::string& s) {
    for (const std::string& n : notes)
        if (n.find(s) != std::string::npos) return true;
    return false;
}

// A builder holding the unit cube as accessors 0 (positions) and 1 (indices), mesh 0.
GltfBuilder cube_builder() {
    GltfBuilder g;
    const tp::test::CubeData c = tp::test::unit_cube();
    g.mesh({{"POSITION", g.vec3s(c.positions)}}, int(g.indices(c.indices)));
    return g;
}

void check_matrix(const glm::dmat4& a, const glm::dmat4& b) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) CHECK(a[c][r] == Approx(b[c][r]).margin(1e-12));
}

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace

TEST_CASE("glTF: one mesh under 100 nodes is one mesh and 100 instances", "[unit][gltf]") {
    GltfBuilder g = cube_builder();
    std::vector<uint32_t> roots;
    for (int i = 0; i < 100; ++i)
        roots.push_back(
            g.add("nodes", {{"mesh", 0}, {"translation", {2.0 * (i % 10), 0, 2.0 * (i / 10)}}}));
    g.add("materials", {{"emissiveFactor", {1, 1, 1}}}); // lit, so no fallback environment
    g.doc["meshes"][0]["primitives"][0]["material"] = 0;
    g.scene(roots);
    const std::string dir = tp::test::temp_dir("gltf-instancing");
    const Loaded l = load(g.write_glb(dir, "many"));
    const tp::Scene& s = l.scene;
    REQUIRE(s.meshes.size() == 1);
    REQUIRE(s.objects.size() == 100);
    for (int i = 0; i < 100; ++i) {
        CHECK(s.objects[size_t(i)].mesh == 0);
        CHECK(s.objects[size_t(i)].transform[3] ==
              glm::dvec4(2.0 * (i % 10), 0.0, 2.0 * (i / 10), 1.0));
    }
    const tp::FlatScene f = tp::flatten(s);
    CHECK(f.meshes.size() == 1);
    CHECK(f.unique_triangles == 12);
    CHECK(f.instanced_triangles == 1200);
    CHECK(tp::instances_per_mesh(f) == std::vector<uint32_t>{100});
    CHECK(tp::analyze_features(f).mask ==
          (tp::FEATURE_INSTANCING | tp::FEATURE_EMISSIVE_TRIANGLES | tp::FEATURE_PHONG_SPECULAR));
}

TEST_CASE("glTF: node transforms compose down the hierarchy", "[unit][gltf]") {
    GltfBuilder g = cube_builder();
    // Root: translation, rotation (90 degrees about +Y as x, y, z, w) and scale; its child: a
    // column-major matrix translating by (0, 5, 0); the grandchild has the mesh.
    const double h = std::sqrt(0.5);
    g.add("nodes", {{"translation", {1, 2, 3}},
                    {"rotation", {0, h, 0, h}},
                    {"scale", {2, 2, 2}},
                    {"children", {1}}});
    g.add("nodes",
          {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 5, 0, 1}}, {"children", {2}}});
    g.add("nodes", {{"mesh", 0}, {"name", "leaf"}});
    g.scene({0});
    const std::string dir = tp::test::temp_dir("gltf-hierarchy");
    const Loaded l = load(g.write_gltf(dir, "tree"));
    REQUIRE(l.scene.objects.size() == 1);
    CHECK(l.scene.objects[0].name == "leaf");
    const glm::dmat4 expected =
        glm::translate(glm::dmat4(1.0), glm::dvec3(1, 2, 3)) *
        glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(0, 1, 0)) *
        glm::scale(glm::dmat4(1.0), glm::dvec3(2.0)) *
        glm::translate(glm::dmat4(1.0), glm::dvec3(0, 5, 0));
    check_matrix(l.scene.objects[0].transform, expected);
    // Nothing emits: the OBJ rule lights it with a white environment, and says so.
    CHECK(l.scene.environment.kind == tp::EnvironmentKind::Constant);
    CHECK(mentions(l.warnings, "no emissive material"));
}

TEST_CASE("glTF: external, embedded and GLB buffers load the same scene", "[unit][gltf]") {
    GltfBuilder g = cube_builder();
    g.add("nodes", {{"mesh", 0}});
    g.scene({0});
    const std::string dir = tp::test::temp_dir("gltf-containers");
    const tp::Scene a = load(g.write_gltf(dir, "external")).scene;
    const tp::Scene b = load(g.write_gltf(dir, "embedded", true)).scene;
    const tp::Scene c = load(g.write_glb(dir, "binary")).scene;
    // A percent-encoded file name ("my cube.bin" as "my%20cube.bin").
    std::ofstream(dir + "/my cube.bin", std::ios::binary) << g.bin;
    json d = g.doc;
    d["buffers"] = json::array({{{"byteLength", g.bin.size()}, {"uri", "my%20cube.bin"}}});
    std::ofstream(dir + "/encoded.gltf") << d.dump();
    const tp::Scene e = load(dir + "/encoded.gltf").scene;
    for (const tp::Scene* s : {&b, &c, &e}) {
        REQUIRE(s->meshes.size() == 1);
        CHECK(s->meshes[0].positions == a.meshes[0].positions);
        CHECK(s->meshes[0].triangles == a.meshes[0].triangles);
    }
    CHECK(a.meshes[0].triangles.size() == 12);
    CHECK(tp::test::unit_cube().positions.size() == a.meshes[0].positions.size());
}

TEST_CASE("glTF: accessors: interleaved, normalized, quantized, sparse; strips and fans",
          "[unit][gltf]") {
    GltfBuilder g;
    // Interleaved float position + normal, 24 bytes per vertex.
    const float interleaved[] = {0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1,
                                 1, 1, 0, 0, 0, 1, 0, 1, 0, 0, 0, 1};
    const uint32_t v = g.view(interleaved, sizeof interleaved, 24);
    const uint32_t pos = g.accessor(v, 5126, 4, "VEC3");
    const uint32_t nrm = g.accessor(v, 5126, 4, "VEC3", 12);
    // Normalized unsigned-byte uvs (0, 255 -> 0, 1), with a texture so that they are read.
    const uint8_t uv8[] = {0, 0, 255, 0, 255, 255, 0, 255};
    const uint32_t uv = g.accessor(g.view(uv8, sizeof uv8), 5121, 4, "VEC2");
    g.doc["accessors"][uv]["normalized"] = true;
    const uint8_t quad_fan[] = {0, 1, 2, 3};
    const uint32_t fan = g.accessor(g.view(quad_fan, 4), 5121, 4, "SCALAR");
    const uint8_t quad_strip[] = {1, 2, 0, 3};
    const uint32_t strip = g.accessor(g.view(quad_strip, 4), 5121, 4, "SCALAR");
    // KHR_mesh_quantization: normalized short positions (32767 -> 1).
    const int16_t q[] = {0, 0, 0, 32767, 0, 0, 0, 32767, 0};
    const uint32_t qpos = g.accessor(g.view(q, sizeof q), 5122, 3, "VEC3");
    g.doc["accessors"][qpos]["normalized"] = true;
    // Sparse: no buffer view (zeros), vertices 1 and 2 replaced.
    const uint16_t sparse_idx[] = {1, 2};
    const float sparse_val[] = {3, 0, 0, 0, 3, 0};
    const uint32_t si = g.view(sparse_idx, sizeof sparse_idx),
                   sv = g.view(sparse_val, sizeof sparse_val);
    const uint32_t spos =
        g.add("accessors", {{"componentType", 5126},
                            {"count", 3},
                            {"type", "VEC3"},
                            {"sparse",
                             {{"count", 2},
                              {"indices", {{"bufferView", si}, {"componentType", 5123}}},
                              {"values", {{"bufferView", sv}}}}}});

    // A 2x1 PNG for the textured material (white, black).
    const std::string dir = tp::test::temp_dir("gltf-accessors");
    tp::write_png(dir + "/tex.png", 2, 1, {255, 255, 255, 0, 0, 0});
    g.add("images", {{"uri", "tex.png"}});
    g.add("textures", {{"source", 0}});
    g.add("materials", {{"pbrMetallicRoughness",
                         {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0}}}});

    const json prims =
        json::array({{{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}},
                      {"indices", fan},
                      {"mode", 6},
                      {"material", 0}},
                     {{"attributes", {{"POSITION", pos}}}, {"indices", strip}, {"mode", 5}},
                     {{"attributes", {{"POSITION", qpos}}}},
                     {{"attributes", {{"POSITION", spos}}}},
                     {{"attributes", {{"POSITION", pos}}}, {"mode", 1}}}); // lines: not rendered
    g.add("meshes", {{"primitives", prims}});
    g.add("nodes", {{"mesh", 0}});
    g.scene({0});
    const Loaded l = load(g.write_glb(dir, "accessors"));
    const tp::Scene& s = l.scene;
    REQUIRE(s.meshes.size() == 4);
    REQUIRE(s.objects.size() == 4);
    // Fan 0 1 2 3: triangles (1, 2, 0), (2, 3, 0) (section 3.7.2.1), counter-clockwise seen
    // from +Z like the positions' quad.
    const tp::Mesh& fan_mesh = s.meshes[0];
    CHECK(fan_mesh.triangles == std::vector<tp::uvec3>{{1, 2, 0}, {2, 3, 0}});
    CHECK(fan_mesh.normals == std::vector<tp::vec3>(4, tp::vec3(0, 0, 1)));
    CHECK(fan_mesh.positions[2] == glm::dvec3(1, 1, 0));
    // uv (u, v) is stored as (u, 1 - v): glTF's v runs down the image.
    CHECK(fan_mesh.uvs == std::vector<tp::vec2>{{0, 1}, {1, 1}, {1, 0}, {0, 0}});
    // Strip 1 2 0 3: (1, 2, 0), then the odd one as {v1, v3, v2} (section 3.7.2.1): (2, 3, 0).
    CHECK(s.meshes[1].triangles == std::vector<tp::uvec3>{{1, 2, 0}, {2, 3, 0}});
    CHECK(s.meshes[2].positions == std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    CHECK(s.meshes[3].positions == std::vector<glm::dvec3>{{0, 0, 0}, {3, 0, 0}, {0, 3, 0}});
    CHECK(mentions(s.dropped, "mode 1"));
    // The texture: sRGB 255 and 0 decoded to linear 1 and 0.
    REQUIRE(s.textures.size() == 1);
    CHECK(s.textures[0].texels == std::vector<tp::vec3>{tp::vec3(1.0f), tp::vec3(0.0f)});
    CHECK(s.materials[0].kd_texture == 0);
}

TEST_CASE("glTF: textures: embedded images, uv sets and KHR_texture_transform", "[unit][gltf]") {
    const std::string dir = tp::test::temp_dir("gltf-textures");
    tp::write_png(dir + "/t.png", 1, 1, {128, 64, 255});
    const std::string png = read_file(dir + "/t.png");
    GltfBuilder g;
    const uint32_t pos = g.vec3s({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const uint32_t uv0 = g.vec2s({{0, 0}, {1, 0}, {0, 1}});
    const uint32_t uv1 = g.vec2s({{0.5f, 0.5f}, {1, 0.5f}, {0.5f, 1}});
    const uint32_t img_view = g.view(png.data(), png.size());
    g.add("images", {{"bufferView", img_view}, {"mimeType", "image/png"}});
    g.add("images", {{"uri", "data:image/png;base64," + tp::test::base64(png)}});
    g.add("textures", {{"source", 0}});
    g.add("textures", {{"source", 1}});
    // Material 0 reads TEXCOORD_1 through its own image; material 1 reads TEXCOORD_0 through
    // the data: URI image with a transform (scale 2, offset (0.25, 0)).
    g.add("materials",
          {{"pbrMetallicRoughness",
            {{"baseColorTexture", {{"index", 0}, {"texCoord", 1}}}, {"metallicFactor", 0}}}});
    g.add("materials",
          {{"pbrMetallicRoughness",
            {{"baseColorTexture",
              {{"index", 1},
               {"extensions",
                {{"KHR_texture_transform", {{"scale", {2, 2}}, {"offset", {0.25, 0}}}}}}}},
             {"metallicFactor", 0}}}});
    const json attrs = {{"POSITION", pos}, {"TEXCOORD_0", uv0}, {"TEXCOORD_1", uv1}};
    g.add("meshes", {{"primitives", json::array({{{"attributes", attrs}, {"material", 0}},
                                                 {{"attributes", attrs}, {"material", 1}}})}});
    g.add("nodes", {{"mesh", 0}});
    g.scene({0});
    const Loaded l = load(g.write_gltf(dir, "textures"));
    const tp::Scene& s = l.scene;
    REQUIRE(s.textures.size() == 2);
    for (const tp::Texture& t : s.textures) {
        REQUIRE(t.texels.size() == 1);
        CHECK(t.texels[0].x == Approx(tp::srgb_to_linear(128.0f / 255.0f)).epsilon(1e-6));
        CHECK(t.texels[0].z == 1.0f);
    }
    REQUIRE(s.meshes.size() == 2);
    CHECK(s.meshes[0].uvs[1] == tp::vec2(1.0f, 0.5f)); // TEXCOORD_1 (1, 0.5) flipped
    // (1, 0) scaled by 2 and offset: (2.25, 0), flipped: (2.25, 1).
    CHECK(s.meshes[1].uvs[1] == tp::vec2(2.25f, 1.0f));
    CHECK(s.meshes[1].uvs[2] == tp::vec2(0.25f, -1.0f));
}

TEST_CASE("glTF: cameras and lights", "[unit][gltf]") {
    GltfBuilder g = cube_builder();
    const double h = std::sqrt(0.5);
    g.add("cameras", {{"type", "orthographic"},
                      {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}});
    g.add("cameras", {{"type", "perspective"},
                      {"perspective", {{"yfov", 0.5}, {"aspectRatio", 2.0}, {"znear", 0.1}}}});
    g.add("cameras", {{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}});
    g.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    g.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"type", "point"}, {"color", {1, 0.5, 0.25}}, {"intensity", 8}, {"range", 10}},
        {{"type", "directional"}, {"intensity", 3}}};
    // The orthographic camera comes first in the hierarchy; the perspective camera 1 sits at
    // (0, 0, 5) turned 90 degrees about +Y, so it looks along -X.
    g.add("nodes", {{"camera", 0}});
    g.add("nodes", {{"camera", 1}, {"translation", {0, 0, 5}}, {"rotation", {0, h, 0, h}}});
    g.add("nodes", {{"camera", 2}, {"translation", {0, 1, 5}}});
    g.add("nodes", {{"mesh", 0}});
    g.add("nodes",
          {{"translation", {4, 5, 6}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    // The directional light turned -90 degrees about +X: its -Z becomes -Y (it shines down).
    g.add("nodes",
          {{"rotation", {-h, 0, 0, h}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
    g.scene({0, 1, 2, 3, 4, 5});
    const std::string dir = tp::test::temp_dir("gltf-cameras");
    const std::string path = g.write_gltf(dir, "cameras");
    const Loaded l = load(path);
    const tp::CameraDesc& c = l.scene.camera;
    REQUIRE(c.given);
    CHECK(c.eye == glm::dvec3(0, 0, 5));
    CHECK(c.target.x == Approx(-1.0));
    CHECK(c.target.z == Approx(5.0));
    CHECK(c.up.y == Approx(1.0f));
    CHECK(c.fov_y_degrees == Approx(0.5 * 180.0 / M_PI));
    CHECK(l.scene.settings.width == 1024); // aspect ratio 2 at the default height 512
    CHECK(l.scene.settings.height == 512);
    // --camera 2.
    const Loaded two = load(path, tp::LoadOptions{2u});
    CHECK(two.scene.camera.eye == glm::dvec3(0, 1, 5));
    CHECK(two.scene.camera.fov_y_degrees == Approx(180.0 / M_PI));
    CHECK(two.scene.settings.width == 512);
    // The lights: values are colour times intensity, the point light where its node is, the
    // directional light's direction towards the light (up).
    REQUIRE(l.scene.lights.size() == 2);
    CHECK(l.scene.lights[0].type == tp::LIGHT_POINT);
    CHECK(l.scene.lights[0].position == glm::dvec3(4, 5, 6));
    CHECK(l.scene.lights[0].value == tp::vec3(8, 4, 2));
    CHECK(l.scene.lights[1].type == tp::LIGHT_DIRECTIONAL);
    CHECK(l.scene.lights[1].direction.y == Approx(1.0f));
    CHECK(l.scene.lights[1].value == tp::vec3(3.0f));
    CHECK(mentions(l.scene.dropped, "range"));
    CHECK(l.scene.environment.kind == tp::EnvironmentKind::None); // lit by its lights
    const tp::FlatScene f = tp::flatten(l.scene);
    CHECK(tp::analyze_features(f).has(tp::FEATURE_POINT_LIGHTS));
    CHECK(tp::analyze_features(f).has(tp::FEATURE_DIRECTIONAL_LIGHTS));
}

TEST_CASE("glTF: what is not rendered is listed, and a zero scale hides a node", "[unit][gltf]") {
    GltfBuilder g = cube_builder();
    g.doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = 0;
    g.doc["meshes"][0]["primitives"][0]["material"] = 0;
    g.add("textures", json::object());
    g.add("materials", {{"name", "painted"},
                        {"normalTexture", {{"index", 0}}},
                        {"alphaMode", "MASK"},
                        {"extensions", {{"KHR_materials_clearcoat", json::object()}}}});
    g.add("nodes", {{"mesh", 0}, {"skin", 0}});
    g.add("nodes", {{"mesh", 0}, {"scale", {0, 0, 0}}});
    g.doc["animations"] = json::array({json::object()});
    g.doc["skins"] = json::array({{{"joints", {0}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_clearcoat"};
    g.scene({0, 1});
    const std::string dir = tp::test::temp_dir("gltf-dropped");
    const Loaded l = load(g.write_gltf(dir, "dropped"));
    CHECK(l.scene.objects.size() == 1); // the zero-scaled node is not rendered
    CHECK(mentions(l.scene.dropped, "nodes[1]: scaled to zero"));
    CHECK(mentions(l.scene.dropped, "animations: 1"));
    CHECK(mentions(l.scene.dropped, "nodes[0]: its skin"));
    CHECK(mentions(l.scene.dropped, "COLOR_0"));
    CHECK(mentions(l.scene.dropped, "extension KHR_materials_clearcoat"));
    REQUIRE(l.scene.material_dropped.size() == 1);
    const std::vector<std::string>& m = l.scene.material_dropped[0];
    CHECK(mentions(m, "normalTexture"));
    CHECK(mentions(m, "alphaMode MASK"));
    CHECK(mentions(m, "KHR_materials_clearcoat"));
    CHECK(mentions(l.warnings, "twinpath info"));
}

TEST_CASE("glTF: the Cornell box flattens exactly as its OBJ twin", "[unit][gltf]") {
    // The condition for identical paths on both engines (tests/gpu/gltf_render_test.cpp): the
    // flat scenes hold the same floats. Same camera on both (the bundled one).
    const std::string dir = tp::test::temp_dir("gltf-cornell");
    const tp::test::CornellFiles files = tp::test::write_cornell_files(dir);
    std::vector<std::string> w;
    const tp::CameraDesc camera = tp::load_scene("cornell", w).camera;
    for (const std::string& path : {files.glb, files.gltf}) {
        CAPTURE(path);
        Loaded obj = load(files.obj), gltf = load(path);
        CHECK(gltf.warnings.empty());
        obj.scene.camera = gltf.scene.camera = camera;
        const tp::FlatScene a = tp::flatten(obj.scene), b = tp::flatten(gltf.scene);
        CHECK(a.positions == b.positions);
        CHECK(a.triangles == b.triangles);
        CHECK(a.normals == b.normals);
        CHECK(a.uvs == b.uvs);
        REQUIRE(a.instances.size() == b.instances.size());
        for (size_t i = 0; i < a.instances.size(); ++i) {
            CHECK(std::memcmp(&a.instances[i], &b.instances[i], offsetof(tp::Instance, material)) ==
                  0);
            CHECK(std::memcmp(&a.material_of(uint32_t(i)), &b.material_of(uint32_t(i)),
                              sizeof(tp::Material)) == 0);
        }
        REQUIRE(a.lights.size() == b.lights.size());
        CHECK(std::memcmp(a.lights.data(), b.lights.data(), a.lights.size() * sizeof(tp::Light)) ==
              0);
        CHECK(std::memcmp(&a.params, &b.params, sizeof a.params) == 0);
        CHECK(tp::analyze_features(a).mask == tp::analyze_features(b).mask);
    }
}

TEST_CASE("a mirrored emitter's light faces where its surface emits", "[unit][gltf]") {
    // glTF (section 3.7.2.1) and twinpath both keep a triangle's front on its counter-clockwise
    // side in the mesh's own space; a node with a negative determinant mirrors it. Emission
    // leaves the surface's front, whose world normal is M^-T times the object normal
    // (surface.h); next-event estimation uses the light's normal, formed from its world
    // vertices: the two must agree, or a mirrored lamp lights the wrong side by one estimator.
    GltfBuilder g = cube_builder();
    g.add("materials", {{"emissiveFactor", {1, 1, 1}}});
    g.doc["meshes"][0]["primitives"][0]["material"] = 0;
    g.add("nodes", {{"mesh", 0}, {"scale", {-1, 1, 1}}, {"translation", {-3, 0, 0}}});
    g.add("nodes", {{"mesh", 0}, {"scale", {1, -2, 1}}, {"rotation", {0, 0.6, 0, 0.8}}});
    g.add("nodes", {{"mesh", 0}, {"translation", {3, 0, 0}}});
    g.scene({0, 1, 2});
    const std::string dir = tp::test::temp_dir("gltf-mirrored");
    const tp::FlatScene f = tp::flatten(load(g.write_glb(dir, "mirrored")).scene);
    size_t checked = 0;
    for (const tp::Light& l : f.lights) {
        if (l.type != tp::LIGHT_TRIANGLE) continue;
        const tp::Instance& inst = f.instances[l.instance];
        const tp::MeshInfo& mesh = f.meshes[inst.mesh];
        const tp::uvec3 t = f.triangles[mesh.first_triangle + l.primitive];
        const tp::vec3 v0 = f.positions[mesh.first_vertex + t.x],
                       v1 = f.positions[mesh.first_vertex + t.y],
                       v2 = f.positions[mesh.first_vertex + t.z];
        const tp::vec3 front =
            glm::normalize(tp::instance_normal_to_world(inst, glm::cross(v1 - v0, v2 - v0)));
        CAPTURE(l.instance, l.primitive);
        CHECK(glm::dot(l.normal, front) == Approx(1.0f).margin(1e-5));
        ++checked;
    }
    CHECK(checked == 3 * 12);
}
