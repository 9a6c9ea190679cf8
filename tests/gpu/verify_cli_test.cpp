// twinpath verify through the command line, on lavapipe (docs/debugging.md, "verify"):
// - each planted shader bug of debug_tests.cmake is found with verify's defaults at 64 x 64 and
//   named: the field pathdiff reports at the first divergence, with both values;
// - the unmodified shader is found consistent, and the report's commands.sh redoes the renders
//   bit for bit;
// - a time budget too short for the bias asked for says what it can detect; bad input is one
//   message and exit 2; pipeline mode where the device has none is exit 3 before any render.
#include "image/exr_io.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <set>
#include <string>

namespace tp::test {
namespace {

std::string bug_spirv(const std::string& bug) {
    return std::string(TP_BUG_SPIRV_DIR) + "/" + bug + ".spv";
}

struct PlantedBug {
    const char* define;           // the bug's name in tests/gpu/debug_tests.cmake
    const char* scene;            // the bundled scene it changes beyond doubt
    std::set<std::string> fields; // what verify may name (docs/debugging.md, "Planted bugs")
};

} // namespace

namespace {

// verify SCENE at 64 x 64 with the bug's module loaded through the test hook: exit 1, and the
// first divergence of the triage names one of `fields`, with two different values.
void check_found_and_named(const PlantedBug& bug) {
    const std::string dir = temp_dir(std::string("verify-") + bug.define);
    const ProcessResult r = run("TWINPATH_DEBUG_SPIRV=" + shell_quote(bug_spirv(bug.define)) + " " +
                                twinpath(fmt::format("verify {} --width 64 --height 64 --report {}",
                                                     bug.scene, shell_quote(dir + "/report"))));
    INFO(r.out);
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Catch::Contains("different: p = "));
    const nlohmann::json j = read_json(dir + "/report/verify.json");
    REQUIRE(j["pairs"].size() == 1);
    const nlohmann::json& first = j["pairs"][0]["triage"]["first_divergence"];
    REQUIRE(first.is_object());
    INFO(first.dump());
    CHECK(bug.fields.count(first["field"].get<std::string>()) == 1);
    CHECK(first["value_a"] != first["value_b"]);
    CHECK_THAT(r.out,
               Catch::Contains("first divergence: field " + first["field"].get<std::string>()));
    // The shader bug is loaded by the test hook: the commands that redo the steps say so.
    const ProcessResult script =
        run("grep -c TWINPATH_DEBUG_SPIRV= " + shell_quote(dir + "/report/commands.sh"));
    CHECK(script.out != "0\n");
}

} // namespace

// One test case per bug, so that CTest runs them side by side.
TEST_CASE("verify finds the planted bug RNG_DIM and names rng.dir_v", "[gpu][verify]") {
    check_found_and_named({"RNG_DIM", "cornell", {"rng.dir_v"}});
}

TEST_CASE("verify finds the planted bug LIGHT_PDF and names light_pdf", "[gpu][verify]") {
    check_found_and_named({"LIGHT_PDF", "cornell", {"light_pdf"}});
}

TEST_CASE("verify finds the planted bug SWAP_BARY and names bary", "[gpu][verify]") {
    check_found_and_named({"SWAP_BARY", "spheres", {"bary"}});
}

TEST_CASE("verify finds the planted bug FRESNEL_SIGN and names bsdf_pdf or lobe", "[gpu][verify]") {
    // A larger reflectance: either the pdf of the chosen lobe (F) or the lobe itself.
    check_found_and_named({"FRESNEL_SIGN", "spheres", {"bsdf_pdf", "lobe"}});
}

TEST_CASE("verify finds the unmodified shader consistent, and commands.sh redoes it bit for bit",
          "[gpu][verify]") {
    const std::string dir = temp_dir("verify-clean");
    const std::string report = dir + "/report";
    const ProcessResult r = run(
        twinpath("verify cornell --width 32 --height 32 --seed 3 --report " + shell_quote(report)));
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("consistent: p = "));
    CHECK_THAT(r.out, Catch::Contains("plan: cpu "));
    CHECK_THAT(r.out, Catch::Contains("power: at these spp a uniform bias of "));
    CHECK(r.out.find("share samples") == std::string::npos);
    const nlohmann::json j = read_json(report + "/verify.json");
    CHECK(j["verdict"] == "consistent");
    CHECK(j["pairs"][0]["triage"].is_null());
    // Independent seeds for every image and pilot.
    std::set<uint32_t> seeds;
    for (const nlohmann::json& e : j["engines"]) {
        seeds.insert(e["pilot"]["seed"].get<uint32_t>());
        seeds.insert(e["image"]["seed"].get<uint32_t>());
    }
    CHECK(seeds.size() == 4);

    // The commands rewrite every image with the same pixels, in a copy of the report.
    const std::string again = dir + "/again";
    const ProcessResult redo =
        run(fmt::format("mkdir -p {0} && cp {1}/commands.sh {0}/ && cd {0} && TWINPATH={2} sh "
                        "commands.sh",
                        shell_quote(again), shell_quote(report), shell_quote(twinpath_bin())));
    INFO(redo.out);
    CHECK_THAT(redo.out, Catch::Contains("consistent: p = "));
    for (const char* file :
         {"cpu.exr", "vulkan-compute.exr", "pilot-cpu.exr", "pilot-vulkan-compute.exr"}) {
        const ProcessResult same =
            run(twinpath(fmt::format("compare --exact {} {}", shell_quote(report + "/" + file),
                                     shell_quote(again + "/" + file))));
        INFO(file << ": " << same.out);
        CHECK(same.exit_code == 0);
    }
}

TEST_CASE("verify on a scene without light warns, plans no more than the minimum and finds the "
          "black images consistent",
          "[gpu][verify]") {
    // The furnace without its emission: both engines render 0 everywhere, with variance 0.
    const std::string dir = temp_dir("verify-dark");
    nlohmann::json j = read_json(scenes_dir() + "/furnace.json");
    j["materials"]["wall"].erase("Ke");
    const std::string scene = dir + "/dark.json";
    std::ofstream(scene) << j.dump(2);
    const ProcessResult r =
        run(twinpath("verify " + shell_quote(scene) + " --width 16 --height 16"));
    INFO(r.out);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("nothing in the scene emits light"));
    CHECK_THAT(r.out, Catch::Contains("plan: the pilots have no noise"));
    CHECK_THAT(r.out, Catch::Contains("consistent: p = 1 "));
}

TEST_CASE("verify with a time budget too short says what it can detect in it", "[gpu][verify]") {
    const ProcessResult r =
        run(twinpath("verify cornell --width 16 --height 16 --time-budget 0.001"));
    INFO(r.out);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("plan: the time budget allows cpu 16 spp, vulkan compute 16 "
                                      "spp"));
    CHECK_THAT(r.out, Catch::Contains("(--time-budget)"));
}

TEST_CASE("verify: bad input is one message and exit 2, a mode the device lacks exit 3",
          "[gpu][verify]") {
    for (const char* args :
         {"cornell --detect 0", "cornell --detect 150%", "cornell --detect x", "cornell --alpha 1",
          "no_such_scene", "cornell --vk-mode fast", "cornell --report /proc/version/report"}) {
        const ProcessResult r = run(twinpath(std::string("verify ") + args));
        INFO(args << ": " << r.out);
        CHECK(r.exit_code == 2);
        CHECK(r.out.find("rendering") == std::string::npos);
    }
    // lavapipe has no ray-tracing pipeline: refused before the pilots.
    const ProcessResult r = run(twinpath("verify cornell --width 16 --height 16 --vk-mode both"));
    INFO(r.out);
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.out, Catch::Contains("pipeline mode"));
    CHECK(r.out.find("pilots:") == std::string::npos);
}

} // namespace tp::test
