// The glTF material (MATERIAL_PBR) rendered by the Vulkan engine through the command line:
//   - the furnace (tests/support/pbr_furnace.h): a flat surface under a constant white
//     environment at max depth 1 renders its directional albedo, in compute mode and, where the
//     device offers it (not lavapipe), in pipeline mode; the expectation and the tolerance as in
//     tests/integration/pbr_furnace_test.cpp (4 SE + 0.5 %), with 256 samples per pixel, on the
//     cases marked on_gpu (lavapipe builds a pipeline for each render: seconds);
//   - path logs: a PBR scene's vertices record the material as the path met it (base_color,
//     roughness, metallic, transmission, alpha) on both engines, and pathdiff finds the CPU's and
//     compute mode's paths identical within tolerance;
//   - AOVs: the pbr.roughness and pbr.metallic layers hold those values and agree between the
//     engines under compare --exact.
// The scene is untextured here (lavapipe compiles the debug variant of a textured one in a
// minute); tests/integration/pbr_debug_test.cpp checks the textured values on the CPU.
//   - alpha BLEND: the two engines decide coverage alike for the same path.
#include "image/exr_io.h"
#include "support/pbr_furnace.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace tp::test {
namespace {

// The mode `twinpath info` says --vk-mode auto picks on the default device.
std::string auto_mode() {
    const ProcessResult r = run(twinpath("info --json"));
    REQUIRE(r.exit_code == 0);
    return nlohmann::json::parse(r.out)["backends"]["vulkan"]["devices"][0]["auto_mode"];
}

} // namespace

namespace {

void check_furnaces(bool transmitting) {
    std::vector<std::string> modes = {"compute"};
    if (auto_mode() == "pipeline") modes.push_back("pipeline");
    const std::string dir = temp_dir("pbr-furnace-vk");
    for (const std::string& mode : modes) {
        uint32_t seed = 170;
        for (const pbr::FurnaceCase& c : pbr::furnace_cases()) {
            ++seed;
            if (!c.on_gpu || c.transmits() != transmitting) continue;
            const std::string scene = pbr::write_furnace_scene(c, dir);
            const std::string out = dir + "/vk.exr";
            const ProcessResult r = run(twinpath(fmt::format(
                "render {} --backend vulkan --vk-mode {} --spp 256 --sampler random --seed {} "
                "-o {} --stats {}",
                shell_quote(scene), mode, seed, shell_quote(out), shell_quote(dir + "/vk.json"))));
            INFO(mode << " " << c.name << ": " << r.out);
            REQUIRE(r.exit_code == 0);
            CHECK(read_json(dir + "/vk.json")["nan_samples"] == 0);
            const pbr::ImageMean img = pbr::image_mean(out);
            const pbr::QuadratureResult albedo = pbr::albedo(c.p, pbr::furnace_view(c));
            for (int ch = 0; ch < 3; ++ch) {
                const double a = albedo.value[ch];
                std::printf("furnace %s %-36s %2.0f deg ch %d: image %.5f +- %.5f, albedo %.5f "
                            "(%+.2f SE, %+.3f %%)\n",
                            mode.c_str(), c.name.c_str(), c.view_degrees, ch, img.mean[ch],
                            img.se[ch], a, (img.mean[ch] - a) / img.se[ch],
                            100.0 * (img.mean[ch] - a) / a);
                CAPTURE(c.name, ch, img.mean[ch], img.se[ch], a);
                CHECK(std::abs(img.mean[ch] - a) <= 4.0 * img.se[ch] + 0.005 * a);
            }
        }
    }
}

} // namespace

TEST_CASE("glTF material furnace: a flat surface renders its directional albedo in Vulkan",
          "[gpu][pbr]") {
    check_furnaces(false);
}

// Light through the surface: see tests/integration/pbr_furnace_test.cpp.
TEST_CASE("glTF material furnace through the surface in Vulkan", "[gpu][pbr]") {
    check_furnaces(true);
}

namespace {

// Renders the PBR scene on one engine with its path log at pixel (x, y) (8 samples, seed 5) and
// its AOVs: out.exr, out.json.
void logged_render(const std::string& scene, const std::string& backend, const std::string& out,
                   int x, int y) {
    const ProcessResult r = run(twinpath(fmt::format(
        "render {} --backend {} --vk-mode compute --spp 8 --seed 5 --aov all --debug-pixel {},{} "
        "--debug-log {} -o {}",
        shell_quote(scene), backend, x, y, shell_quote(out + ".json"), shell_quote(out + ".exr"))));
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
}

} // namespace

TEST_CASE("a PBR scene's path logs and AOVs record its material fields alike on both engines",
          "[gpu][pbr]") {
    const std::string dir = temp_dir("pbr-debug");
    const std::string scene = pbr::write_debug_scene(dir, false, "mask");
    // A floor pixel: its paths go on to the ball and the floor.
    logged_render(scene, "cpu", dir + "/cpu", 3, 13);
    logged_render(scene, "vulkan", dir + "/vk", 3, 13);
    const ProcessResult d = run(twinpath(fmt::format(
        "pathdiff {} {}", shell_quote(dir + "/cpu.json"), shell_quote(dir + "/vk.json"))));
    INFO(d.out);
    CHECK(d.exit_code == 0);
    CHECK_THAT(d.out, Catch::Contains("identical within tolerance: 8 paths"));
    CHECK(read_json(dir + "/cpu.json")["paths"].size() == 8);
    for (const char* log : {"/cpu.json", "/vk.json"}) {
        const auto [floor_hits, ball_hits] = pbr::check_debug_log(dir + log, false);
        CHECK(floor_hits >= 8); // every camera ray of the pixel stops on the floor
        CHECK(ball_hits > 0);
    }
    const ProcessResult same = run(twinpath(fmt::format(
        "compare --exact {} {}", shell_quote(dir + "/cpu.exr"), shell_quote(dir + "/vk.exr"))));
    INFO(same.out);
    CHECK(same.exit_code == 0);
    pbr::check_debug_aovs(dir + "/cpu.exr", false);
    pbr::check_debug_aovs(dir + "/vk.exr", false);
}

// Alpha BLEND keeps a surface where alpha > alpha_blend_threshold(the ray's tag, instance,
// primitive) (shared/alpha.h): the tag names the ray by its path, not by its floats, which the
// two engines compute only to rounding, so same-seed renders of a blended floor make the same
// decisions on both engines and agree to float rounding (docs/stress.md, "Same-seed twins").
TEST_CASE("alpha BLEND: same-seed renders of a blended surface agree on both engines",
          "[gpu][pbr]") {
    const std::string dir = temp_dir("pbr-blend");
    const std::string scene = pbr::write_debug_scene(dir, false, "blend");
    for (const char* backend : {"cpu", "vulkan"})
        REQUIRE(run(twinpath(fmt::format(
                        "render {} --backend {} --vk-mode compute --spp 8 --seed 5 -o {}",
                        shell_quote(scene), backend, shell_quote(dir + "/" + backend + ".exr"))))
                    .exit_code == 0);
    const ProcessResult same =
        run(twinpath(fmt::format("compare --exact --tolerance 1e-3 {} {}",
                                 shell_quote(dir + "/cpu.exr"), shell_quote(dir + "/vulkan.exr"))));
    INFO(same.out);
    CHECK(same.exit_code == 0);
}

} // namespace tp::test
