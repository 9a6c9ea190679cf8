// What the glTF loader (scene/gltf_loader.h) makes of good input, from files the tests write
// (support/gltf_builder.h): the node hierarchy and instancing, the ways a buffer can hold the
// data (external, embedded, GLB, interleaved, normalized, sparse, strips and fans), texture
// slots (images, uv sets, KHR_texture_transform, samplers), normals and tangents for normal maps,
// cameras, lights and their units, the feature mask, what is listed as ignored or not rendered,
// and the Cornell box flattening to the same geometry and lights as its OBJ twin; and the input
// errors that name the glTF field (the command line's exit code: tests/cli/bad_input_test.cpp).
#include "image/png_io.h"
#include "scene/features.h"
#include "scene/flatten.h"
#include "scene/gltf_loader.h"
#include "scene/load.h"
#include "shared/surface.h"
#include "support/cornell_files.h"
#include "support/gltf_builder.h"
#include "support/test_paths.h"
#include "util/error.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
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
          (tp::FEATURE_INSTANCING | tp::FEATURE_EMISSIVE_TRIANGLES | tp::FEATURE_PBR));
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

TEST_CASE("glTF: accessors: interleaved, normalized, quantized, sparse, and strips and fans",
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
    // uvs as given: glTF's (0, 0) is the image's top-left, as twinpath's image coordinates.
    CHECK(fan_mesh.uvs == std::vector<tp::vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    CHECK(fan_mesh.uvs1.empty());
    // Strip 1 2 0 3: (1, 2, 0), then the odd one as {v1, v3, v2} (section 3.7.2.1): (2, 3, 0).
    CHECK(s.meshes[1].triangles == std::vector<tp::uvec3>{{1, 2, 0}, {2, 3, 0}});
    CHECK(s.meshes[2].positions == std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    CHECK(s.meshes[3].positions == std::vector<glm::dvec3>{{0, 0, 0}, {3, 0, 0}, {0, 3, 0}});
    CHECK(mentions(s.dropped, "mode 1"));
    // The texture: its 8-bit values as stored; the slot reads them as sRGB colour.
    REQUIRE(s.textures.size() == 1);
    CHECK(s.textures[0].format == tp::TEXEL_RGBA8);
    CHECK(s.textures[0].raw(0) == tp::vec4(1.0f));
    CHECK(s.textures[0].raw(1) == tp::vec4(0, 0, 0, 1));
    REQUIRE(s.texture_slots.size() == 1);
    CHECK(s.materials[0].kd_texture == 0);
    CHECK(s.texture_slots[0].sampling == tp::SLOT_SRGB);
}

TEST_CASE("glTF: every textureInfo is a slot with its image, uv set, sampler and colour space",
          "[unit][gltf]") {
    const std::string dir = tp::test::temp_dir("gltf-slots");
    tp::write_png(dir + "/t.png", 2, 1, {128, 64, 255, 0, 10, 20});
    const std::string png = read_file(dir + "/t.png");
    GltfBuilder g;
    const uint32_t pos = g.vec3s({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const uint32_t nrm = g.vec3s({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    const uint32_t uv0 = g.vec2s({{0, 0}, {1, 0}, {0, 1}});
    const uint32_t uv1 = g.vec2s({{0.5f, 0.5f}, {1, 0.5f}, {0.5f, 1}});
    const float tangent[] = {0, 1, 0, -1, 0, 1, 0, -1, 0, 1, 0, -1};
    const uint32_t tan = g.accessor(g.view(tangent, sizeof tangent), 5126, 3, "VEC4");
    // Image 0 in a buffer view, image 1 the same bytes as a data: URI: two images.
    g.add("images", {{"bufferView", g.view(png.data(), png.size())}, {"mimeType", "image/png"}});
    g.add("images", {{"uri", "data:image/png;base64," + tp::test::base64(png)}});
    g.add("samplers",
          {{"wrapS", 33071}, {"wrapT", 33648}, {"magFilter", 9728}, {"minFilter", 9987}});
    g.add("samplers", {{"wrapS", 10497}, {"wrapT", 33071}});
    g.add("textures", {{"source", 0}});
    g.add("textures", {{"source", 1}, {"sampler", 0}});
    g.add("textures", {{"source", 0}, {"sampler", 1}});
    g.add("textures", {{"extensions", {{"KHR_texture_basisu", {{"source", 0}}}}}});
    g.add(
        "materials",
        {{"pbrMetallicRoughness",
          {{"baseColorTexture", {{"index", 0}, {"texCoord", 1}}},
           {"metallicRoughnessTexture", {{"index", 1}}}}},
         {"normalTexture", {{"index", 2}, {"scale", 0.5}}},
         {"emissiveTexture", {{"index", 0}}},
         {"occlusionTexture", {{"index", 0}, {"strength", 0.5}}},
         {"extensions",
          {{"KHR_materials_transmission",
            {{"transmissionFactor", 1}, {"transmissionTexture", {{"index", 1}, {"texCoord", 1}}}}},
           {"KHR_materials_specular",
            {{"specularTexture", {{"index", 2}}},
             {"specularColorTexture",
              {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"texCoord", 1}}}}}}}}},
           {"KHR_materials_volume",
            {{"thicknessFactor", 1}, {"thicknessTexture", {{"index", 0}}}}}}}});
    g.add("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 3}}}}}});
    g.add("materials",
          {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 2}}}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_specular",
                               "KHR_materials_volume", "KHR_texture_transform"};
    const json attrs = {{"POSITION", pos},
                        {"NORMAL", nrm},
                        {"TEXCOORD_0", uv0},
                        {"TEXCOORD_1", uv1},
                        {"TANGENT", tan}};
    json prims = json::array();
    for (int m = 0; m < 3; ++m) prims.push_back({{"attributes", attrs}, {"material", m}});
    g.add("meshes", {{"primitives", prims}});
    g.add("nodes", {{"mesh", 0}});
    g.scene({0});
    const Loaded l = load(g.write_glb(dir, "slots"));
    const tp::Scene& s = l.scene;

    // Each image decoded once, its 8-bit values as stored.
    REQUIRE(s.textures.size() == 2);
    for (const tp::Texture& t : s.textures) {
        CHECK(t.width == 2);
        CHECK(t.format == tp::TEXEL_RGBA8);
        CHECK(t.words[0] == (128u | 64u << 8 | 255u << 16 | 255u << 24)); // R in the low byte
    }
    const tp::Material& m = s.materials[0];
    auto slot = [&](int index) -> const tp::TextureSlot& {
        REQUIRE(index != tp::NO_TEXTURE);
        return s.texture_slots.at(size_t(index));
    };
    const uint32_t image0 = slot(m.kd_texture).image,
                   image1 = slot(m.metallic_roughness_texture).image;
    CHECK(image0 != image1);
    const tp::vec3 id_s(1, 0, 0), id_t(0, 1, 0); // no KHR_texture_transform: the identity
    struct Expected {
        const char* name;
        int index;
        uint32_t image, sampling;
    };
    const uint32_t sampler0 =
        tp::SLOT_WRAP_CLAMP | tp::SLOT_WRAP_MIRROR << tp::SLOT_WRAP_T_SHIFT | tp::SLOT_NEAREST;
    const uint32_t sampler1 = tp::SLOT_WRAP_REPEAT | tp::SLOT_WRAP_CLAMP << tp::SLOT_WRAP_T_SHIFT;
    const Expected expected[] = {
        {"baseColorTexture", m.kd_texture, image0, tp::SLOT_SRGB | tp::SLOT_UV1},
        {"metallicRoughnessTexture", m.metallic_roughness_texture, image1, sampler0},
        {"normalTexture", m.normal_texture, image0, sampler1},
        {"emissiveTexture", m.emissive_texture, image0, tp::SLOT_SRGB},
        {"transmissionTexture", m.transmission_texture, image1, sampler0 | tp::SLOT_UV1},
        {"specularTexture", m.specular_texture, image0, sampler1},
        {"specularColorTexture", m.specular_color_texture, image0,
         tp::SLOT_SRGB | tp::SLOT_UV1}}; // KHR_texture_transform's texCoord overrides 0
    for (const Expected& e : expected) {
        CAPTURE(e.name);
        const tp::TextureSlot& ts = slot(e.index);
        CHECK(ts.image == e.image);
        CHECK(ts.sampling == e.sampling);
        CHECK(ts.transform_s == id_s);
        CHECK(ts.transform_t == id_t);
    }
    // Equal slots are one: specular reads what normal reads, specular colour what base colour.
    CHECK(m.specular_texture == m.normal_texture);
    CHECK(m.specular_color_texture == m.kd_texture);
    CHECK(s.texture_slots.size() == 5);
    CHECK(m.normal_scale == 0.5f);
    CHECK(m.flags == tp::MATERIAL_FLAG_VOLUME);
    CHECK(m.transmission == 1.0f);
    // Ignored, with the reason, and nothing dropped.
    const std::vector<std::string>& ignored = s.material_ignored.at(0);
    CHECK(mentions(ignored, "occlusionTexture: ignored by a path tracer (it computes occlusion)"));
    CHECK(mentions(ignored, "thicknessTexture: ignored (a ray tracer measures thickness)"));
    CHECK(mentions(ignored, "samplers[0].minFilter 9987: ignored"));
    CHECK(s.material_dropped.at(0).empty());
    // A texture without a decodable image and a third uv set: dropped, said so.
    CHECK(s.materials[1].kd_texture == tp::NO_TEXTURE);
    CHECK(mentions(s.material_dropped.at(1), "KHR_texture_basisu"));
    CHECK(s.materials[2].kd_texture == tp::NO_TEXTURE);
    CHECK(mentions(s.material_dropped.at(2), "texCoord 2"));
    // The mesh of material 0 holds both uv sets as given, and the tangents as given.
    const tp::Mesh& mesh = s.meshes.at(s.objects.at(0).mesh);
    CHECK(mesh.uvs == std::vector<tp::vec2>{{0, 0}, {1, 0}, {0, 1}});
    CHECK(mesh.uvs1 == std::vector<tp::vec2>{{0.5f, 0.5f}, {1, 0.5f}, {0.5f, 1}});
    CHECK(mesh.tangents == std::vector<tp::vec4>(3, tp::vec4(0, 1, 0, -1)));
    // Materials 1 and 2 read no uv set: their primitive is another mesh, without uvs.
    const tp::Mesh& plain = s.meshes.at(s.objects.at(1).mesh);
    CHECK(s.objects.at(1).mesh != s.objects.at(0).mesh);
    CHECK(plain.uvs.empty());
    CHECK(plain.uvs1.empty());
    CHECK(plain.tangents.empty());
}

TEST_CASE("glTF: KHR_texture_transform maps uv where the extension's example says",
          "[unit][gltf]") {
    const std::string dir = tp::test::temp_dir("gltf-transform");
    tp::write_png(dir + "/t.png", 1, 1, {200, 100, 50});
    GltfBuilder g;
    const uint32_t pos = g.vec3s({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const uint32_t uv = g.vec2s({{0, 0}, {1, 0}, {0, 1}});
    g.add("images", {{"uri", "t.png"}});
    g.add("textures", {{"source", 0}});
    const double rotation = 0.3;
    const auto transformed = [](json transform) {
        return json{{"pbrMetallicRoughness",
                     {{"baseColorTexture",
                       {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}}}}};
    };
    // The extension's example: "only the lower left quadrant of the source image, rotated
    // clockwise 90 degrees"; and offset, rotation and anisotropic scale together.
    g.add("materials",
          transformed({{"offset", {0, 1}}, {"rotation", M_PI / 2}, {"scale", {0.5, 0.5}}}));
    g.add("materials",
          transformed({{"offset", {0.25, -0.5}}, {"rotation", rotation}, {"scale", {2, 3}}}));
    g.add("meshes",
          {{"primitives",
            json::array(
                {{{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", uv}}}, {"material", 0}},
                 {{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", uv}}}, {"material", 1}}})}});
    g.add("nodes", {{"mesh", 0}});
    g.scene({0});
    const Loaded l = load(g.write_gltf(dir, "transform"));
    const tp::Scene& s = l.scene;
    auto st = [&](uint32_t material, tp::vec2 p) {
        const tp::TextureSlot& ts = s.texture_slots.at(size_t(s.materials[material].kd_texture));
        const tp::vec3 h(p, 1.0f);
        return tp::vec2(glm::dot(ts.transform_s, h), glm::dot(ts.transform_t, h));
    };
    auto near = [](tp::vec2 a, tp::vec2 b) { return glm::length(a - b) < 1e-6f; };
    // uv's corners land on the lower-left quadrant (t = 1 is the bottom row): the uv square's
    // top edge (v = 0) along the quadrant's left edge, turned clockwise.
    CHECK(near(st(0, {0, 0}), {0, 1}));
    CHECK(near(st(0, {1, 0}), {0, 0.5f}));
    CHECK(near(st(0, {0, 1}), {0.5f, 1}));
    CHECK(near(st(0, {1, 1}), {0.5f, 0.5f}));
    // T R S: scale (2, 3), then (x, y) -> (c x + s y, -s x + c y), then the offset.
    const double x = 2 * 0.4, y = 3 * 0.7, c = std::cos(rotation), sn = std::sin(rotation);
    const tp::vec2 expected(float(c * x + sn * y + 0.25), float(-sn * x + c * y - 0.5));
    CHECK(near(st(1, {0.4f, 0.7f}), expected));
    // The uvs stay as given: the map is the slot's.
    CHECK(s.meshes.at(0).uvs == std::vector<tp::vec2>{{0, 0}, {1, 0}, {0, 1}});
}

TEST_CASE("glTF: normal maps get normals and tangents: given, generated, or flat", "[unit][gltf]") {
    const std::string dir = tp::test::temp_dir("gltf-normal-maps");
    tp::write_png(dir + "/n.png", 1, 1, {128, 128, 255});
    GltfBuilder g;
    // The unit quad facing +Z, glTF's upright uv layout: the tangent is +X, handedness +1.
    const uint32_t pos = g.vec3s({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    const uint32_t nrm = g.vec3s(std::vector<glm::vec3>(4, {0, 0, 1}));
    const uint32_t uv = g.vec2s({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
    const float given[] = {0, 1, 0, -1, 0, 1, 0, -1, 0, 1, 0, -1, 0, 1, 0, -1};
    const uint32_t tan = g.accessor(g.view(given, sizeof given), 5126, 4, "VEC4");
    const uint32_t idx = g.indices({0, 1, 2, 0, 2, 3});
    g.add("images", {{"uri", "n.png"}});
    g.add("textures", {{"source", 0}});
    g.add("materials", {{"normalTexture", {{"index", 0}}}});
    g.add("materials", {{"name", "plain"}});
    const auto prim = [&](json attributes, int material) {
        return json{{"attributes", attributes}, {"indices", idx}, {"material", material}};
    };
    const json prims = json::array(
        {prim({{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}, {"TANGENT", tan}}, 0),
         prim({{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}, 0),
         // Without NORMAL: flat normals, and the tangents given are ignored (section 3.7.2.1).
         prim({{"POSITION", pos}, {"TEXCOORD_0", uv}, {"TANGENT", tan}}, 0),
         // The same accessors as the second under a material without a normal map.
         prim({{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}, 1)});
    g.add("meshes", {{"primitives", prims}});
    g.add("nodes", {{"mesh", 0}});
    g.scene({0});
    const Loaded l = load(g.write_gltf(dir, "normal_maps"));
    const tp::Scene& s = l.scene;
    REQUIRE(s.objects.size() == 4);
    REQUIRE(s.meshes.size() == 4);
    const tp::Mesh& given_mesh = s.meshes[s.objects[0].mesh];
    CHECK(given_mesh.tangents == std::vector<tp::vec4>(4, tp::vec4(0, 1, 0, -1)));
    const tp::Mesh& generated = s.meshes[s.objects[1].mesh];
    REQUIRE(generated.tangents.size() == 4);
    for (const tp::vec4& t : generated.tangents) CHECK(t == tp::vec4(1, 0, 0, 1));
    const tp::Mesh& flat = s.meshes[s.objects[2].mesh];
    CHECK(flat.positions.size() == 6); // unwelded: three vertices per triangle
    CHECK(flat.normals == std::vector<tp::vec3>(6, tp::vec3(0, 0, 1)));
    REQUIRE(flat.tangents.size() == 6);
    for (const tp::vec4& t : flat.tangents) CHECK(t == tp::vec4(1, 0, 0, 1));
    const tp::Mesh& plain = s.meshes[s.objects[3].mesh];
    CHECK(plain.tangents.empty());
    CHECK(plain.uvs.empty());
    CHECK(plain.positions.size() == 4);
    CHECK(tp::analyze_features(tp::flatten(s)).has(tp::FEATURE_NORMAL_MAPS));
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
    // The lights: colour times intensity at 683 lm/W, the point light where its node is, the
    // directional light's direction towards the light (up).
    REQUIRE(l.scene.lights.size() == 2);
    CHECK(l.scene.lights[0].type == tp::LIGHT_POINT);
    CHECK(l.scene.lights[0].position == glm::dvec3(4, 5, 6));
    CHECK(l.scene.lights[0].value ==
          tp::vec3(float(8 / 683.0), float(4 / 683.0), float(2 / 683.0)));
    CHECK(l.scene.lights[1].type == tp::LIGHT_DIRECTIONAL);
    CHECK(l.scene.lights[1].direction.y == Approx(1.0f));
    CHECK(l.scene.lights[1].value == tp::vec3(float(3 / 683.0)));
    // The range: the inverse square holds at every distance; ignored, not dropped.
    CHECK(mentions(l.scene.ignored, "lights[0].range: ignored"));
    CHECK(l.scene.dropped.empty());
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
                        {"occlusionTexture", {{"index", 0}}},
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
    // textures[0] has no image: the normal map is dropped; alpha MASK is rendered.
    CHECK(mentions(m, "normalTexture: textures[0] has no image"));
    CHECK(mentions(m, "KHR_materials_clearcoat"));
    CHECK_FALSE(mentions(m, "alphaMode"));
    CHECK(l.scene.materials[0].alpha_mode == tp::ALPHA_MASK);
    CHECK(mentions(l.scene.material_ignored.at(0), "occlusionTexture"));
    CHECK_FALSE(mentions(m, "occlusionTexture"));
    CHECK(mentions(l.warnings, "twinpath info"));
}

TEST_CASE("glTF: spot, point and directional lights in radiometric units", "[unit][gltf]") {
    GltfBuilder g = cube_builder();
    const double h = std::sqrt(0.5);
    g.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    g.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"type", "spot"}, {"color", {1, 0.5, 0.25}}, {"intensity", 683}},
        {{"type", "spot"},
         {"intensity", 100},
         {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}},
        {{"type", "point"}}, // intensity 1 cd by default
        {{"type", "directional"}, {"color", {0.5, 1, 1}}, {"intensity", 1000}}};
    const auto light = [](int i) { return json{{"KHR_lights_punctual", {{"light", i}}}}; };
    g.add("nodes", {{"mesh", 0}});
    // Spot 0 at (1, 2, 3) untransformed: it shines along -Z. Spot 1 turned -90 degrees about
    // +X and scaled: its -Z becomes -Y, normalized.
    g.add("nodes", {{"translation", {1, 2, 3}}, {"extensions", light(0)}});
    g.add("nodes", {{"rotation", {-h, 0, 0, h}}, {"scale", {2, 3, 4}}, {"extensions", light(1)}});
    g.add("nodes", {{"translation", {0, 5, 0}}, {"extensions", light(2)}});
    g.add("nodes", {{"extensions", light(3)}});
    g.scene({0, 1, 2, 3, 4});
    const std::string dir = tp::test::temp_dir("gltf-lights");
    const Loaded l = load(g.write_gltf(dir, "lights"));
    const std::vector<tp::LightDesc>& lights = l.scene.lights;
    REQUIRE(lights.size() == 4);
    // 683 cd is 1 W/sr: Blender's 683 cd -> 4 pi W point light, of intensity 4 pi / (4 pi).
    CHECK(lights[0].type == tp::LIGHT_SPOT);
    CHECK(lights[0].position == glm::dvec3(1, 2, 3));
    CHECK(lights[0].direction == tp::vec3(0, 0, -1));
    CHECK(lights[0].value == tp::vec3(1.0f, 0.5f, 0.25f));
    CHECK(lights[0].inner_cone == 0.0f); // the extension's defaults
    CHECK(lights[0].outer_cone == Approx(M_PI / 4));
    CHECK(lights[1].type == tp::LIGHT_SPOT);
    CHECK(glm::length(lights[1].direction - tp::vec3(0, -1, 0)) < 1e-6f);
    CHECK(lights[1].value == tp::vec3(float(100 / 683.0)));
    CHECK(lights[1].inner_cone == 0.2f);
    CHECK(lights[1].outer_cone == 0.5f);
    CHECK(lights[2].type == tp::LIGHT_POINT);
    CHECK(lights[2].value == tp::vec3(float(1 / 683.0)));
    // 1000 lx of colour (0.5, 1, 1): 1000 / 683 W/m^2 per unit of colour.
    CHECK(lights[3].type == tp::LIGHT_DIRECTIONAL);
    CHECK(lights[3].value ==
          tp::vec3(float(500 / 683.0), float(1000 / 683.0), float(1000 / 683.0)));
    CHECK(lights[3].direction == tp::vec3(0, 0, 1)); // towards the light: the node's +Z
    CHECK(tp::gltf_light_value(tp::vec3(1.0f), 683.0) == tp::vec3(1.0f));
    CHECK(l.scene.dropped.empty());
    const tp::FlatScene f = tp::flatten(l.scene);
    CHECK(tp::analyze_features(f).has(tp::FEATURE_POINT_LIGHTS)); // spot lights are point-like
}

TEST_CASE("glTF: input errors name the file and the glTF field", "[unit][gltf]") {
    const std::string dir = tp::test::temp_dir("gltf-errors");
    tp::write_png(dir + "/t.png", 1, 1, {1, 2, 3});
    int n = 0;
    const auto rejected = [&](const std::function<void(GltfBuilder&)>& edit) {
        GltfBuilder g = cube_builder();
        for (int i = 0; i < 3; ++i) g.add("materials", json::object());
        g.doc["meshes"][0]["primitives"][0]["material"] = 2;
        g.add("nodes", {{"mesh", 0}});
        g.scene({0});
        edit(g);
        const std::string path = g.write_gltf(dir, "bad" + std::to_string(n++));
        try {
            load(path);
        } catch (const tp::InputError& e) {
            const std::string what = e.what();
            CHECK(what.find(path) != std::string::npos);
            return what;
        }
        FAIL("no error");
        return std::string();
    };
    CHECK_THAT(rejected([](GltfBuilder& g) {
                   g.doc["materials"][2]["pbrMetallicRoughness"]["roughnessFactor"] = 1.5;
               }),
               Catch::Contains("materials[2].pbrMetallicRoughness.roughnessFactor"));
    CHECK_THAT(rejected([](GltfBuilder& g) {
                   g.doc["materials"][1]["pbrMetallicRoughness"]["metallicFactor"] = -0.1;
               }),
               Catch::Contains("materials[1].pbrMetallicRoughness.metallicFactor"));
    CHECK_THAT(rejected([](GltfBuilder& g) {
                   g.doc["materials"][2]["extensions"]["KHR_materials_transmission"] = {
                       {"transmissionFactor", 2}};
               }),
               Catch::Contains("KHR_materials_transmission.transmissionFactor"));
    CHECK_THAT(rejected([](GltfBuilder& g) {
                   g.doc["materials"][0]["extensions"]["KHR_materials_volume"] = {
                       {"attenuationDistance", 0}};
               }),
               Catch::Contains("materials[0].extensions.KHR_materials_volume.attenuationDistance"));
    CHECK_THAT(rejected([](GltfBuilder& g) {
                   g.doc["materials"][0]["extensions"]["KHR_materials_ior"] = {{"ior", 0.5}};
               }),
               Catch::Contains("KHR_materials_ior.ior"));
    CHECK_THAT(
        rejected([](GltfBuilder& g) {
            g.doc["materials"][2]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 5}};
        }),
        Catch::Contains("materials[2].pbrMetallicRoughness.baseColorTexture.index"));
    CHECK_THAT(rejected([](GltfBuilder& g) {
                   g.add("samplers", {{"wrapS", 1234}});
               }),
               Catch::Contains("samplers[0].wrapS"));
    CHECK_THAT(rejected([](GltfBuilder& g) {
                   g.add("images", {{"uri", "t.png"}});
                   g.add("textures", {{"source", 0}});
                   g.doc["materials"][2]["emissiveTexture"] = {{"index", 0}, {"texCoord", 1}};
               }),
               Catch::Contains("has no TEXCOORD_1, which materials[2].emissiveTexture reads"));
    const auto spot = [&](json cone) {
        return rejected([cone](GltfBuilder& g) {
            g.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
                {{"type", "spot"}, {"spot", cone}}};
            g.doc["nodes"][0]["extensions"]["KHR_lights_punctual"]["light"] = 0;
        });
    };
    CHECK_THAT(spot({{"innerConeAngle", 0.5}, {"outerConeAngle", 0.5}}),
               Catch::Contains("lights[0].spot.innerConeAngle"));
    CHECK_THAT(spot({{"innerConeAngle", 0.9}}), // above the default outer cone, pi / 4
               Catch::Contains("lights[0].spot.innerConeAngle"));
    CHECK_THAT(spot({{"outerConeAngle", 2.0}}), Catch::Contains("lights[0].spot.outerConeAngle"));
    CHECK_THAT(spot({{"outerConeAngle", 0}}), Catch::Contains("lights[0].spot.outerConeAngle"));
}

TEST_CASE("glTF: the Cornell box flattens to its OBJ twin's geometry and lights", "[unit][gltf]") {
    // The same triangles, instances, emitters and camera; the materials are glTF's BSDF with
    // the MTL's diffuse colour as base colour, metallic 0, roughness 1 and specular 0: Lambert
    // with the same albedo.
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
            const tp::Material &mo = a.material_of(uint32_t(i)), &mg = b.material_of(uint32_t(i));
            CHECK(mg.type == tp::MATERIAL_PBR);
            CHECK(mg.kd == mo.kd);
            CHECK(mg.ke == mo.ke);
            CHECK(mg.metallic == 0.0f);
            CHECK(mg.roughness == 1.0f);
            CHECK(mg.specular == 0.0f);
        }
        REQUIRE(a.lights.size() == b.lights.size());
        CHECK(std::memcmp(a.lights.data(), b.lights.data(), a.lights.size() * sizeof(tp::Light)) ==
              0);
        CHECK(std::memcmp(&a.params, &b.params, sizeof a.params) == 0);
        CHECK(tp::analyze_features(b).mask == (tp::analyze_features(a).mask | tp::FEATURE_PBR));
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
