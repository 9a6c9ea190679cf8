// What the scene loaders make of good input (bad input is tests/cli/bad_input_test.cpp): the
// OBJ/MTL statements docs/design.md maps, JSON transforms and instancing, lights, the JSON pbr
// material and texture slots, and what flatten() derives from them.
#include "image/png_io.h"
#include "scene/flatten.h"
#include "scene/load.h"
#include "scene/obj_loader.h"
#include "shared/math.h"
#include "shared/surface.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <glm/glm.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <numeric>

namespace fs = std::filesystem;

namespace {

struct Loaded {
    tp::Scene scene;
    std::vector<std::string> warnings;
};

Loaded load(const fs::path& file) {
    Loaded l;
    l.scene = tp::load_scene(file.string(), l.warnings);
    return l;
}

bool mentions(const std::vector<std::string>& warnings, const std::string& s) {
    for (const std::string& w : warnings)
        if (w.find(s) != std::string::npos) return true;
    return false;
}

} // namespace

TEST_CASE("OBJ and MTL: statements and indices and the material mapping", "[scene][obj]") {
    const fs::path dir = tp::test::temp_dir("loader-obj");
    tp::write_png((dir / "wood.png").string(), 1, 1, {200, 150, 100});
    std::ofstream(dir / "m.mtl")
        << "# materials\r\n"
           "newmtl glossy\r\nKd 0.2 0.3 0.4\r\nKs 0.5\r\nNs 80\r\nKa 1 1 1\r\n"
           "map_Kd -s 1 1 1 wood.png\r\n"
           "newmtl chrome\nillum 3\nKs 0.9 0.8 0.7\n"
           "newmtl glass\nillum 7\nNi 1.33\nTf 0.9 1 0.9\n"
           "newmtl lamp\nKe 5 4 3\nillum 5\n";
    std::ofstream(dir / "s.obj") << "mtllib m.mtl\no thing\ng part\ns 1\n"
                                    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
                                    "usemtl glossy\nf 1/1/1 2/2/1 3/3/1 4/4/1  # a quad\n"
                                    "usemtl chrome\nf -4 -3 -2\n"
                                    "usemtl glass\nf 1 3 4\n"
                                    "usemtl lamp\nf 1 2 3\n";
    const Loaded l = load(dir / "s.obj");
    const tp::Scene& s = l.scene;
    // Materials: the default grey first, then the MTL's in order.
    REQUIRE(s.materials.size() == 5);
    CHECK(s.material_names[1] == "glossy");
    const tp::Material& glossy = s.materials[1];
    CHECK(glossy.type == tp::MATERIAL_PHONG);
    CHECK(glossy.kd == tp::vec3(0.2f, 0.3f, 0.4f));
    CHECK(glossy.ks == tp::vec3(0.5f)); // the grey shorthand
    CHECK(glossy.ns == 80.0f);
    // map_Kd: a slot with OBJ's uv convention (s = u, t = 1 - v) reading sRGB colour.
    REQUIRE(s.textures.size() == 1);
    REQUIRE(glossy.kd_texture == 0);
    const tp::TextureSlot& slot = s.texture_slots.at(0);
    CHECK(slot.image == 0);
    CHECK(slot.transform_s == tp::vec3(1, 0, 0));
    CHECK(slot.transform_t == tp::vec3(0, -1, 1));
    CHECK(slot.sampling == tp::SLOT_SRGB);
    CHECK(s.materials[2].type == tp::MATERIAL_MIRROR);
    CHECK(s.materials[2].ks == tp::vec3(0.9f, 0.8f, 0.7f));
    CHECK(s.materials[3].type == tp::MATERIAL_DIELECTRIC);
    CHECK(s.materials[3].ior == 1.33f);
    CHECK(s.materials[3].tf == tp::vec3(0.9f, 1.0f, 0.9f));
    CHECK(s.materials[4].ke == tp::vec3(5.0f, 4.0f, 3.0f));
    CHECK(s.materials[4].type == tp::MATERIAL_PHONG);
    CHECK(mentions(l.warnings, "illum 5")); // rendered as Phong, said so
    CHECK(mentions(l.warnings, "Ka"));      // ignored, said so
    // One mesh per material; the quad fan-triangulated; uvs and normals kept where every
    // corner has them, indices unified per corner.
    REQUIRE(s.meshes.size() == 4);
    REQUIRE(s.objects.size() == 4);
    const tp::Mesh& quad = s.meshes[s.objects[0].mesh];
    CHECK(s.objects[0].material == 1);
    CHECK(quad.triangles.size() == 2);
    CHECK(quad.positions.size() == 4);
    CHECK(quad.uvs.size() == 4);
    CHECK(quad.normals.size() == 4);
    CHECK(quad.triangles[1] == tp::uvec3(0, 2, 3));
    const tp::Mesh& negative = s.meshes[s.objects[1].mesh];
    CHECK(negative.positions[0] == glm::dvec3(0, 0, 0)); // -4 of 4 vertices is the first
    CHECK(negative.positions[2] == glm::dvec3(1, 1, 0));
    CHECK(negative.uvs.empty());
    CHECK(s.meshes[s.objects[3].mesh].normals.empty());
    // An emitter exists, so no environment is added.
    CHECK(s.environment.kind == tp::EnvironmentKind::None);
    CHECK(s.skipped_triangles == 0);
    fs::remove_all(dir);
}

TEST_CASE("OBJ: zero-area triangles are dropped and counted", "[scene][obj]") {
    const fs::path dir = tp::test::temp_dir("loader-degenerate");
    std::ofstream(dir / "d.obj")
        << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\nf 3 3 1\n";
    const Loaded l = load(dir / "d.obj");
    CHECK(l.scene.skipped_triangles == 2);
    CHECK(l.scene.meshes.at(0).triangles.size() == 1);
    CHECK(mentions(l.warnings, "skipped 2 degenerate"));
    fs::remove_all(dir);
}

TEST_CASE("JSON: transforms and instancing and lights and what flatten derives", "[scene][json]") {
    const fs::path dir = tp::test::temp_dir("loader-json");
    std::ofstream(dir / "s.json") << R"({
  "camera": {"eye": [0, 1, 5], "target": [0, 1, 0]},
  "film": {"width": 20, "height": 10},
  "render": {"spp": 3, "max_depth": 7, "min_depth": 2},
  "materials": {
    "white": {"Kd": [0.5, 0.5, 0.5]},
    "lamp": {"Kd": [0.1, 0.1, 0.1], "Ke": [2, 2, 2]}
  },
  "meshes": {
    "tri": {"type": "triangles", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2]]},
    "panel": {"type": "quad"}
  },
  "objects": [
    {"name": "a", "mesh": "tri", "material": "white",
     "transform": {"translate": [1, 2, 3], "rotate": {"axis": [0, 0, 1], "degrees": 90}, "scale": 2}},
    {"name": "b", "mesh": "tri", "material": "white"},
    {"name": "light", "mesh": "panel", "material": "lamp", "transform": {"translate": [0, 3, 0]}}
  ],
  "lights": [
    {"type": "point", "position": [0, 2, 0], "intensity": [3, 3, 3]},
    {"type": "directional", "direction": [0, -2, 0], "irradiance": [1, 1, 1]}
  ],
  "environment": {"type": "constant", "radiance": [0.1, 0.1, 0.1]}
})";
    const Loaded l = load(dir / "s.json");
    const tp::Scene& s = l.scene;
    CHECK(l.warnings.empty());
    CHECK(s.settings.width == 20);
    CHECK(s.settings.spp == 3);
    CHECK(s.settings.max_depth == 7);
    CHECK(s.settings.min_depth == 2);
    CHECK(s.camera.given);
    CHECK(s.camera.fov_y_degrees == 45.0f); // default

    const tp::FlatScene f = tp::flatten(s);
    // The triangle is stored once and instanced twice.
    CHECK(f.meshes.size() == 2);
    CHECK(f.unique_triangles == 1 + 2);
    CHECK(f.instanced_triangles == 1 + 1 + 2);
    // translate * rotate * scale: vertex (1, 0, 0) -> scale (2, 0, 0) -> rotate 90 degrees
    // about Z (0, 2, 0) -> translate (1, 4, 3); in the camera-relative world, minus the eye.
    CHECK(f.origin == glm::dvec3(0, 1, 5));
    const tp::vec3 p = tp::instance_point_to_world(f.instances[0], tp::vec3(1, 0, 0));
    CHECK(glm::length(p - tp::vec3(1, 3, -2)) < 1e-5f);
    const tp::vec3 back = tp::instance_point_to_object(f.instances[0], p);
    CHECK(glm::length(back - tp::vec3(1, 0, 0)) < 1e-5f);
    // Lights: the point and directional lights, the lamp's 2 triangles, the environment.
    REQUIRE(f.lights.size() == 5);
    CHECK(f.lights[0].type == tp::LIGHT_POINT);
    CHECK(f.lights[0].p0 == tp::vec3(0, 1, -5)); // (0, 2, 0) - eye
    CHECK(f.lights[1].type == tp::LIGHT_DIRECTIONAL);
    CHECK(glm::length(f.lights[1].p0 - tp::vec3(0, 1, 0)) < 1e-6f); // towards the light
    CHECK(f.lights[2].type == tp::LIGHT_TRIANGLE);
    CHECK(f.lights[2].area == Approx(2.0f)); // half of the 2 x 2 quad
    // Light::normal: the quad's counter-clockwise front faces +Y, as its vertex normals say; the
    // cross product (0, 4, 0) normalizes exactly.
    CHECK(f.lights[2].normal == tp::vec3(0, 1, 0));
    CHECK(f.lights[3].normal == tp::vec3(0, 1, 0));
    CHECK(f.instances[2].light_offset == 2);
    CHECK(f.params.env_light == 4);
    CHECK(f.params.light_count == 5);
    double pdf_sum = 0.0;
    for (const tp::AliasEntry& e : f.light_table) pdf_sum += double(e.pdf);
    CHECK(pdf_sum == Approx(1.0).epsilon(1e-6));
    // Camera: looking down -Z from (0, 1, 5), 2:1 film.
    CHECK(glm::length(f.params.camera.forward - tp::vec3(0, 0, -1)) < 1e-6f);
    CHECK(f.params.camera.aspect == 2.0f);
    fs::remove_all(dir);
}

TEST_CASE("JSON: a pbr material with every field, its texture slots and tangents",
          "[scene][json]") {
    const fs::path dir = tp::test::temp_dir("loader-json-pbr");
    tp::write_png((dir / "albedo.png").string(), 2, 2, {255, 0, 0, 0, 255, 0, 0, 0, 255, 9, 9, 9});
    tp::write_png((dir / "data.png").string(), 1, 1, {128, 128, 255});
    std::ofstream(dir / "s.json") << R"({
  "textures": {"albedo": {"file": "albedo.png"}, "data": {"file": "data.png"}},
  "materials": {
    "glass": {"type": "pbr", "base_color": [0.9, 0.8, 0.7], "metallic": 0.1, "roughness": 0.2,
              "ior": 1.45, "transmission": 0.95, "specular": 0.5, "specular_color": [1, 0.9, 2],
              "Ke": [0.5, 0.25, 0.125], "alpha": 0.75, "alpha_mode": "mask", "alpha_cutoff": 0.3,
              "thickness": 0.01, "attenuation_color": [0.5, 0.6, 0.7],
              "attenuation_distance": 2.5, "normal_scale": 0.8,
              "base_color_texture": "albedo", "metallic_roughness_texture": "data",
              "normal_texture": "data", "emissive_texture": "albedo",
              "transmission_texture": "data", "specular_texture": "data",
              "specular_color_texture": "albedo"},
    "defaults": {"type": "pbr"},
    "blend": {"type": "pbr", "alpha_mode": "blend", "thickness": 0},
    "phong": {"Kd": [0.5, 0.5, 0.5], "map_Kd": "albedo"}
  },
  "meshes": {"panel": {"type": "quad"}, "tri": {"type": "triangles",
             "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2]]}},
  "objects": [{"mesh": "panel", "material": "glass"}, {"mesh": "tri", "material": "defaults"},
              {"mesh": "tri", "material": "blend"}, {"mesh": "tri", "material": "phong"}]
})";
    const Loaded l = load(dir / "s.json");
    const tp::Scene& s = l.scene;
    const auto material = [&](const std::string& name) -> const tp::Material& {
        for (size_t i = 0; i < s.materials.size(); ++i)
            if (s.material_names[i] == name) return s.materials[i];
        FAIL("no material " << name);
        return s.materials.at(0);
    };
    const tp::Material& m = material("glass");
    CHECK(m.type == tp::MATERIAL_PBR);
    CHECK(m.kd == tp::vec3(0.9f, 0.8f, 0.7f));
    CHECK(m.metallic == 0.1f);
    CHECK(m.roughness == 0.2f);
    CHECK(m.ior == 1.45f);
    CHECK(m.transmission == 0.95f);
    CHECK(m.specular == 0.5f);
    CHECK(m.ks == tp::vec3(1.0f, 0.9f, 2.0f));
    CHECK(m.ke == tp::vec3(0.5f, 0.25f, 0.125f));
    CHECK(m.alpha == 0.75f);
    CHECK(m.alpha_mode == tp::ALPHA_MASK);
    CHECK(m.alpha_cutoff == 0.3f);
    CHECK(m.flags == tp::MATERIAL_FLAG_VOLUME);
    CHECK(m.tf == tp::vec3(0.5f, 0.6f, 0.7f));
    CHECK(m.attenuation_distance == 2.5f);
    CHECK(m.normal_scale == 0.8f);
    // Slots with OBJ's uv convention; colour slots sRGB, data slots linear; equal slots shared.
    REQUIRE(s.textures.size() == 2);
    const auto check_slot = [&](int index, uint32_t image, bool srgb) {
        REQUIRE(index != tp::NO_TEXTURE);
        const tp::TextureSlot& t = s.texture_slots.at(size_t(index));
        CHECK(t.image == image);
        CHECK(t.sampling == (srgb ? tp::SLOT_SRGB : 0u));
        CHECK(t.transform_s == tp::vec3(1, 0, 0));
        CHECK(t.transform_t == tp::vec3(0, -1, 1));
    };
    check_slot(m.kd_texture, 0, true);
    check_slot(m.metallic_roughness_texture, 1, false);
    check_slot(m.normal_texture, 1, false);
    check_slot(m.emissive_texture, 0, true);
    check_slot(m.transmission_texture, 1, false);
    check_slot(m.specular_texture, 1, false);
    check_slot(m.specular_color_texture, 0, true);
    CHECK(m.emissive_texture == m.kd_texture);
    CHECK(m.normal_texture == m.specular_texture);
    CHECK(s.texture_slots.size() == 2); // the phong map_Kd shares the sRGB slot of "albedo"
    CHECK(material("phong").kd_texture == m.kd_texture);
    // glTF's defaults.
    const tp::Material& d = material("defaults");
    CHECK(d.type == tp::MATERIAL_PBR);
    CHECK(d.kd == tp::vec3(1.0f));
    CHECK(d.metallic == 1.0f);
    CHECK(d.roughness == 1.0f);
    CHECK(d.ior == 1.5f);
    CHECK(d.specular == 1.0f);
    CHECK(d.ks == tp::vec3(1.0f));
    CHECK(d.alpha_mode == tp::ALPHA_OPAQUE);
    CHECK(d.alpha_cutoff == 0.5f);
    CHECK(d.flags == 0u);
    CHECK(d.attenuation_distance == tp::FLOAT_MAX);
    CHECK(d.normal_texture == tp::NO_TEXTURE);
    CHECK(material("blend").alpha_mode == tp::ALPHA_BLEND);
    CHECK(material("blend").flags == 0u);
    // The normal-mapped quad (XZ plane, facing +Y, OBJ uvs: u along +X, v along -Z) gets
    // tangents +X with handedness +1: cross(+Y, +X) = -Z is up its image. The other mesh none.
    const tp::Mesh& panel = s.meshes.at(s.objects.at(0).mesh);
    REQUIRE(panel.tangents.size() == panel.positions.size());
    for (const tp::vec4& t : panel.tangents) CHECK(t == tp::vec4(1, 0, 0, 1));
    CHECK(s.meshes.at(s.objects.at(1).mesh).tangents.empty());
    fs::remove_all(dir);
}

TEST_CASE("bundled scenes resolve by name", "[scene]") {
    std::vector<std::string> warnings;
    const tp::Scene s = tp::load_scene("cornell", warnings);
    CHECK(fs::path(s.path).filename() == "cornell.json");
    CHECK(tp::flatten(s).params.light_count == 2); // the ceiling light's two triangles
}

TEST_CASE("JSON: OBJ files read once each and at once give the scene of a serial load",
          "[scene][obj]") {
    // Two meshes name one file (with an MTL and a texture) and a third another file: each file
    // is parsed once, on its own task, and appended per mesh in the meshes' order. The scene
    // must be what load_obj gives called for each mesh in turn.
    const fs::path dir = tp::test::temp_dir("loader-obj-files");
    tp::write_png((dir / "wood.png").string(), 1, 1, {200, 150, 100});
    std::ofstream(dir / "a.mtl") << "newmtl glossy\nKd 0.2 0.3 0.4\nKs 0.5\nmap_Kd wood.png\n"
                                    "newmtl lamp\nKe 5 4 3\n";
    std::ofstream(dir / "a.obj") << "mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 2 2\n"
                                    "usemtl glossy\nf 1 2 3 4\nf 5 5 5\nusemtl lamp\nf 1 2 4\n";
    std::ofstream(dir / "b.mtl") << "newmtl wood\nKd 0.5 0.4 0.3\nmap_Kd wood.png\nKa 1 1 1\n";
    std::ofstream(dir / "b.obj") << "mtllib b.mtl\nusemtl wood\nv 0 0 1\nv 1 0 1\nv 0 1 1\n"
                                    "f 1 2 3\n";
    std::ofstream(dir / "s.json") << R"({
      "camera": { "eye": [0, 0, 5], "target": [0, 0, 0], "fov": 40 },
      "meshes": { "a1": { "type": "obj", "file": "a.obj" }, "b": { "type": "obj", "file": "b.obj" },
                  "a2": { "type": "obj", "file": "a.obj" } },
      "objects": [ { "mesh": "a1" }, { "mesh": "a2" }, { "mesh": "b" } ] })";
    const Loaded l = load(dir / "s.json");
    tp::Scene serial;
    std::vector<std::string> serial_warnings;
    std::vector<tp::ObjPart> parts;
    for (const char* file : {"a.obj", "a.obj", "b.obj"}) // the meshes' order: a1, a2, b
        for (const tp::ObjPart& p :
             tp::load_obj((dir / file).string(), serial, tp::NO_INDEX, serial_warnings))
            parts.push_back(p);
    const tp::Scene& s = l.scene;
    REQUIRE(s.materials.size() == serial.materials.size());
    CHECK(std::memcmp(s.materials.data(), serial.materials.data(),
                      serial.materials.size() * sizeof(tp::Material)) == 0);
    CHECK(s.material_names == serial.material_names);
    REQUIRE(s.textures.size() == 1);
    CHECK(s.textures[0].name == serial.textures[0].name);
    REQUIRE(s.texture_slots.size() == serial.texture_slots.size());
    CHECK(std::memcmp(s.texture_slots.data(), serial.texture_slots.data(),
                      serial.texture_slots.size() * sizeof(tp::TextureSlot)) == 0);
    REQUIRE(s.meshes.size() == serial.meshes.size());
    for (size_t m = 0; m < s.meshes.size(); ++m) {
        CHECK(s.meshes[m].name == serial.meshes[m].name);
        CHECK(s.meshes[m].positions == serial.meshes[m].positions);
        CHECK(s.meshes[m].triangles == serial.meshes[m].triangles);
    }
    // The objects name the meshes and materials of the parts load_obj returned.
    REQUIRE(s.objects.size() == parts.size());
    for (size_t i = 0; i < parts.size(); ++i) {
        CHECK(s.objects[i].mesh == parts[i].mesh);
        CHECK(s.objects[i].material == parts[i].material);
    }
    CHECK(s.skipped_triangles == 2);
    CHECK(s.skipped_triangles == serial.skipped_triangles);
    CHECK(mentions(l.warnings, "Ka"));
    fs::remove_all(dir);
}
