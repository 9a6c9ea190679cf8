// Scene features on the CPU: on every bundled scene the path loop specialized to the scene's
// features renders what the all-features loop renders. With different seeds the two images must be
// consistent under `twinpath compare` (alpha 0.01); with the same seed they follow the same
// paths with the same random numbers (shared/features.h promises the unrestricted result for
// every input the mask admits), so they must agree to rounding.
#include "shared/features.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace tp::test {
namespace {} // namespace

TEST_CASE("CPU: the specialized path loop agrees with the all-features loop on every scene",
          "[features]") {
    for (const char* scene :
         {"cornell", "cornell_glossy", "spheres", "furnace", "gltf_materials"}) {
        SECTION(scene) {
            const std::string dir = temp_dir(std::string("spec-cpu-") + scene);
            const auto render = [&](const std::string& name, const char* features, int seed) {
                const ProcessResult r = run(twinpath(fmt::format(
                    "render {} --width 32 --height 32 --spp 128 --seed {} --features {} -o {} "
                    "--stats {}",
                    scene, seed, features, shell_quote(dir + "/" + name + ".exr"),
                    shell_quote(dir + "/" + name + ".json"))));
                INFO(r.out);
                REQUIRE(r.exit_code == 0);
                return read_json(dir + "/" + name + ".json");
            };
            const nlohmann::json spec = render("scene", "scene", 11);
            const nlohmann::json all = render("all", "all", 12);
            const nlohmann::json same = render("all_same_seed", "all", 11);
            CHECK(spec["features"]["variant"] == "scene");
            CHECK(all["features"]["variant"] == "all");
            CHECK(all["features"]["mask"] == tp::FEATURES_ALL);
            CHECK(spec["features"]["mask"].get<uint32_t>() != tp::FEATURES_ALL);
            CHECK(spec["nan_samples"] == 0);
            // The same paths: the same number of rays of every kind.
            CHECK(spec["rays"] == same["rays"]);

            const ProcessResult cmp = run(
                twinpath(fmt::format("compare {} {} --alpha 0.01", shell_quote(dir + "/scene.exr"),
                                     shell_quote(dir + "/all.exr"))));
            INFO(cmp.out);
            CHECK(cmp.exit_code == 0);
            const ProcessResult same_cmp = run(twinpath(fmt::format(
                "compare {} {} --json {}", shell_quote(dir + "/scene.exr"),
                shell_quote(dir + "/all_same_seed.exr"), shell_quote(dir + "/same.json"))));
            INFO(same_cmp.out);
            CHECK(same_cmp.exit_code == 0);
        }
    }
}

TEST_CASE("info SCENE lists the scene's features", "[features]") {
    const ProcessResult r = run(twinpath("info spheres --json"));
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    CHECK(j["features"] ==
          nlohmann::json({"textures", "phong_specular", "mirror", "dielectric", "point_lights",
                          "directional_lights", "environment_constant", "instancing"}));
    const ProcessResult text = run(twinpath("info cornell"));
    CHECK(text.exit_code == 0);
    CHECK(text.out.find("features: emissive_triangles") != std::string::npos);
    CHECK(run(twinpath("info no_such_scene")).exit_code == 2);
}

} // namespace tp::test
