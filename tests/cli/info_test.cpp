// twinpath info on a glTF file (docs/scene-format.md): each material with what the mapping of
// docs/scene-format.md ("glTF materials") made of it and what it gave that is not rendered, and
// what else the asset gave that is not rendered, as text and as JSON.
#include "support/gltf_builder.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

using json = nlohmann::json;
using tp::test::run;
using tp::test::shell_quote;

namespace {

bool contains(const std::string& text, const std::string& s) {
    return text.find(s) != std::string::npos;
}

} // namespace

TEST_CASE("info model.glb lists each material, what it became and what was dropped", "[cli]") {
    tp::test::GltfBuilder g;
    const tp::test::CubeData c = tp::test::unit_cube();
    g.mesh({{"POSITION", g.vec3s(c.positions)}}, int(g.indices(c.indices)));
    // Rows of the mapping table (unit test "glTF material mapping table"): metallic 1 and
    // roughness 0 is the mirror; transmission 1 with ior 1.33 the dielectric; plastic at
    // roughness 0.5 Phong with F0 0.04 over 0.96 of the base colour and Ns 1/(2 r^4) - 1/2 = 7.5,
    // its normal map not rendered.
    g.add("materials", {{"name", "chrome"},
                        {"pbrMetallicRoughness", {{"metallicFactor", 1}, {"roughnessFactor", 0}}}});
    g.add("materials", {{"name", "water"},
                        {"pbrMetallicRoughness", {{"metallicFactor", 0}, {"roughnessFactor", 0}}},
                        {"extensions",
                         {{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
                          {"KHR_materials_ior", {{"ior", 1.33}}}}}});
    g.add("textures", json::object());
    g.add("materials", {{"name", "plastic"},
                        {"normalTexture", {{"index", 0}}},
                        {"pbrMetallicRoughness",
                         {{"baseColorFactor", {0.5, 0.5, 0.5, 1}},
                          {"metallicFactor", 0},
                          {"roughnessFactor", 0.5}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_ior"};
    // Three meshes naming the cube's accessors, one per material (copies: mesh() appends).
    const json attributes = g.doc["meshes"][0]["primitives"][0]["attributes"];
    const int indices = g.doc["meshes"][0]["primitives"][0]["indices"];
    std::vector<uint32_t> roots;
    for (int m = 0; m < 3; ++m) {
        const uint32_t mesh = g.mesh(attributes, indices, m);
        roots.push_back(g.add("nodes", {{"mesh", mesh}, {"translation", {2.0 * m, 0, 0}}}));
    }
    g.doc["animations"] = json::array({json::object()});
    g.scene(roots);
    const std::string dir = tp::test::temp_dir("cli-info-gltf");
    const std::string path = g.write_glb(dir, "materials");

    // stdout alone (the warning that points at info goes to stderr).
    const auto j_run =
        run("{ " + tp::test::twinpath("info --json " + shell_quote(path)) + " 2>/dev/null; }");
    INFO(j_run.out);
    REQUIRE(j_run.exit_code == 0);
    const json j = json::parse(j_run.out);
    REQUIRE(j["material_list"].size() == 3);
    CHECK(j["material_list"][0]["name"] == "chrome");
    CHECK(j["material_list"][0]["became"] == "mirror Ks (1, 1, 1)");
    CHECK(j["material_list"][0]["dropped"].empty());
    CHECK(j["material_list"][1]["name"] == "water");
    CHECK(contains(j["material_list"][1]["became"], "dielectric Ni 1.33"));
    CHECK(j["material_list"][2]["name"] == "plastic");
    CHECK(j["material_list"][2]["became"] ==
          "phong Kd (0.48, 0.48, 0.48) Ks (0.04, 0.04, 0.04) Ns 7.5");
    REQUIRE(j["material_list"][2]["dropped"].size() == 1);
    CHECK(contains(j["material_list"][2]["dropped"][0], "normalTexture"));
    bool animations = false;
    for (const auto& d : j["dropped"]) animations |= contains(d, "animations");
    CHECK(animations);

    const auto text = run(tp::test::twinpath("info " + shell_quote(path)));
    INFO(text.out);
    REQUIRE(text.exit_code == 0);
    CHECK(contains(text.out, "chrome: mirror"));
    CHECK(contains(text.out, "water: dielectric Ni 1.33"));
    CHECK(contains(text.out, "plastic: phong"));
    CHECK(contains(text.out, "not rendered: normalTexture"));
    CHECK(contains(text.out, "not rendered: animations"));
}
