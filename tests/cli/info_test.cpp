// twinpath info on a glTF file (docs/scene-format.md, "glTF 2.0"): each material as the engines
// see it (glTF's own BSDF, its factors one for one) with its texture slots, what a path tracer
// ignores, what is not rendered (nothing, for an asset that uses only what twinpath reads), and
// each light in twinpath's units and the file's, as text and as JSON.
#include "image/png_io.h"
#include "support/gltf_builder.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

using json = nlohmann::json;
using tp::test::run;
using tp::test::shell_quote;

namespace {

bool contains(const std::string& text, const std::string& s) {
    return text.find(s) != std::string::npos;
}

// The unit cube under one node per material, mesh k using material k.
void cubes(tp::test::GltfBuilder& g, int materials) {
    const tp::test::CubeData c = tp::test::unit_cube();
    std::vector<glm::vec2> uv(c.positions.size(), glm::vec2(0.5f));
    const json attributes = {{"POSITION", g.vec3s(c.positions)}, {"TEXCOORD_0", g.vec2s(uv)}};
    const int indices = int(g.indices(c.indices));
    std::vector<uint32_t> roots;
    for (int m = 0; m < materials; ++m) {
        const uint32_t mesh = g.mesh(attributes, indices, m);
        roots.push_back(g.add("nodes", {{"mesh", mesh}, {"translation", {2.0 * m, 0, 0}}}));
    }
    g.scene(roots);
}

} // namespace

TEST_CASE("info model.glb lists materials, texture slots, lights, ignored and dropped", "[cli]") {
    const std::string dir = tp::test::temp_dir("cli-info-gltf");
    tp::write_png(dir + "/wood.png", 4, 2, std::vector<uint8_t>(4 * 2 * 3, 128));
    tp::test::GltfBuilder g;
    g.add("images", {{"uri", "wood.png"}});
    g.add("samplers", {{"wrapS", 33071}, {"magFilter", 9728}, {"minFilter", 9987}});
    g.add("textures", {{"source", 0}, {"sampler", 0}});
    g.add("materials", {{"name", "chrome"},
                        {"pbrMetallicRoughness", {{"metallicFactor", 1}, {"roughnessFactor", 0}}}});
    g.add("materials", {{"name", "water"},
                        {"pbrMetallicRoughness", {{"metallicFactor", 0}, {"roughnessFactor", 0}}},
                        {"extensions",
                         {{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
                          {"KHR_materials_ior", {{"ior", 1.33}}},
                          {"KHR_materials_volume",
                           {{"thicknessFactor", 0.1},
                            {"attenuationColor", {0.5, 0.5, 0.5}},
                            {"attenuationDistance", 2},
                            {"thicknessTexture", {{"index", 0}}}}}}}});
    g.add("materials",
          {{"name", "wood"},
           {"alphaMode", "MASK"},
           {"occlusionTexture", {{"index", 0}}},
           {"pbrMetallicRoughness",
            {{"baseColorFactor", {0.5, 0.5, 0.5, 1}},
             {"metallicFactor", 0},
             {"roughnessFactor", 0.5},
             {"baseColorTexture",
              {{"index", 0},
               {"extensions",
                {{"KHR_texture_transform", {{"scale", {2, 2}}, {"offset", {0.25, 0}}}}}}}}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_ior",
                               "KHR_materials_volume", "KHR_texture_transform",
                               "KHR_lights_punctual"};
    g.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"type", "spot"}, {"intensity", 683}, {"spot", {{"outerConeAngle", M_PI / 6}}}},
        {{"type", "directional"}, {"intensity", 6830}}};
    cubes(g, 3);
    g.add("nodes",
          {{"translation", {0, 4, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    g.add("nodes", {{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
    g.doc["scenes"][0]["nodes"].push_back(3);
    g.doc["scenes"][0]["nodes"].push_back(4);
    const std::string path = g.write_glb(dir, "materials");

    // stdout alone (a warning would go to stderr).
    const auto j_run =
        run("{ " + tp::test::twinpath("info --json " + shell_quote(path)) + " 2>/dev/null; }");
    INFO(j_run.out);
    REQUIRE(j_run.exit_code == 0);
    const json j = json::parse(j_run.out);
    REQUIRE(j["material_list"].size() == 3);
    const json& chrome = j["material_list"][0];
    CHECK(chrome["name"] == "chrome");
    CHECK(chrome["became"] == "pbr base colour (1, 1, 1) metallic 1 roughness 0 ior 1.5 "
                              "transmission 0 specular 1 specular colour (1, 1, 1) thin opaque");
    CHECK(chrome["textures"].empty());
    CHECK(chrome["ignored"].empty());
    const json& water = j["material_list"][1];
    CHECK(contains(water["became"], "metallic 0 roughness 0 ior 1.33 transmission 1"));
    CHECK(contains(water["became"], "volume (attenuation colour (0.5, 0.5, 0.5) at 2 m)"));
    REQUIRE(water["ignored"].size() == 1);
    CHECK(contains(water["ignored"][0], "thicknessTexture: ignored (a ray tracer measures"));
    const json& wood = j["material_list"][2];
    CHECK(contains(wood["became"], "base colour (0.5, 0.5, 0.5) metallic 0 roughness 0.5"));
    CHECK(contains(wood["became"], "alpha mask (alpha 1, cutoff 0.5)"));
    REQUIRE(wood["textures"].size() == 1);
    const json& slot = wood["textures"][0];
    CHECK(slot["slot"] == "base colour");
    CHECK(slot["image"] == "wood.png");
    CHECK(slot["width"] == 4);
    CHECK(slot["height"] == 2);
    CHECK(slot["uv_set"] == 0);
    CHECK(slot["wrap_s"] == "clamp");
    CHECK(slot["wrap_t"] == "repeat");
    CHECK(slot["filter"] == "nearest");
    CHECK(slot["srgb"] == true);
    CHECK(slot["transform"] == json({{2, 0, 0.25}, {0, 2, 0}}));
    bool occlusion = false, min_filter = false;
    for (const auto& i : wood["ignored"]) {
        occlusion |= contains(i, "occlusionTexture: ignored by a path tracer");
        min_filter |= contains(i, "minFilter 9987: ignored");
    }
    CHECK(occlusion);
    CHECK(min_filter);
    // Only what twinpath reads: nothing dropped.
    for (const json& m : j["material_list"]) CHECK(m["dropped"].empty());
    CHECK(j["dropped"].empty());
    // Lights: 683 cd is 1 W/sr, 6830 lx 10 W/m^2.
    REQUIRE(j["light_list"].size() == 2);
    const json& spot = j["light_list"][0];
    CHECK(spot["type"] == "spot");
    CHECK(spot["value"] == json({1.0, 1.0, 1.0}));
    CHECK(spot["unit"] == "W/sr");
    CHECK(spot["file_value"][0].get<double>() == Approx(683.0));
    CHECK(spot["file_unit"] == "cd");
    CHECK(spot["inner_cone_degrees"] == 0.0);
    CHECK(spot["outer_cone_degrees"].get<double>() == Approx(30.0));
    const json& sun = j["light_list"][1];
    CHECK(sun["type"] == "directional");
    CHECK(sun["value"][0].get<double>() == Approx(10.0));
    CHECK(sun["unit"] == "W/m^2");
    CHECK(sun["file_value"][0].get<double>() == Approx(6830.0));
    CHECK(sun["file_unit"] == "lx");

    const auto text = run(tp::test::twinpath("info " + shell_quote(path)));
    INFO(text.out);
    REQUIRE(text.exit_code == 0);
    CHECK(contains(text.out, "chrome: pbr base colour (1, 1, 1) metallic 1 roughness 0"));
    CHECK(contains(text.out, "water: pbr"));
    CHECK(contains(text.out, "base colour texture: 'wood.png' 4x2, uv 0, clamp/repeat, nearest, "
                             "sRGB, s = 2 u + 0.25, t = 2 v"));
    CHECK(contains(text.out, "occlusionTexture: ignored by a path tracer (it computes occlusion)"));
    CHECK(contains(text.out, "spot at (0, 4, 0): (1, 1, 1) W/sr ((683, 683, 683) cd in the file), "
                             "shining along (0, 0, -1), cone 0 to 30 degrees"));
    CHECK(contains(text.out, "directional towards (0, 0, 1): (10, 10, 10) W/m^2"));
    CHECK_FALSE(contains(text.out, "not rendered"));
}

TEST_CASE("info model.gltf lists what is not rendered", "[cli]") {
    tp::test::GltfBuilder g;
    g.add("textures", json::object()); // no image twinpath decodes
    g.add("materials", {{"name", "plastic"}, {"normalTexture", {{"index", 0}}}});
    g.add("materials",
          {{"name", "coated"}, {"extensions", {{"KHR_materials_clearcoat", json::object()}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_clearcoat"};
    cubes(g, 2);
    g.doc["animations"] = json::array({json::object()});
    const std::string dir = tp::test::temp_dir("cli-info-dropped");
    const std::string path = g.write_gltf(dir, "dropped");
    const auto j_run =
        run("{ " + tp::test::twinpath("info --json " + shell_quote(path)) + " 2>/dev/null; }");
    INFO(j_run.out);
    REQUIRE(j_run.exit_code == 0);
    const json j = json::parse(j_run.out);
    REQUIRE(j["material_list"][0]["dropped"].size() == 1);
    CHECK(contains(j["material_list"][0]["dropped"][0], "normalTexture: textures[0] has no image"));
    CHECK(contains(j["material_list"][1]["dropped"][0], "KHR_materials_clearcoat"));
    bool animations = false;
    for (const auto& d : j["dropped"]) animations |= contains(d, "animations");
    CHECK(animations);
    const auto text = run(tp::test::twinpath("info " + shell_quote(path)));
    INFO(text.out);
    REQUIRE(text.exit_code == 0);
    CHECK(contains(text.out, "not rendered: materials[0].normalTexture"));
    CHECK(contains(text.out, "not rendered: animations"));
    CHECK(contains(text.out, "twinpath info")); // the warning that points here
}
