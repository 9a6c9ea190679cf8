// The glTF material in the CPU engine's debug outputs (docs/debugging.md), with a texture: a path
// log (render --debug-log) records at each hit the material as the path met it, textures applied
// (base_color, roughness, metallic, transmission, alpha), and the pbr.roughness and pbr.metallic
// AOV layers hold the textured values (tests/support/pbr_furnace.h, write_debug_scene). The
// Vulkan engine's agree with these (tests/gpu/pbr_render_test.cpp, untextured there).
#include "support/pbr_furnace.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>

namespace tp::test {

TEST_CASE("a textured PBR scene's path log and AOVs record the material as met on the CPU",
          "[integration][pbr]") {
    const std::string dir = temp_dir("pbr-debug-cpu");
    const std::string scene = pbr::write_debug_scene(dir, true, "mask");
    // A floor pixel, whose paths go on to the ball, and a ball pixel.
    for (const auto& [x, y] : {std::pair<int, int>{3, 13}, {8, 7}}) {
        const std::string out = fmt::format("{}/cpu-{}-{}", dir, x, y);
        const ProcessResult r = run(twinpath(fmt::format(
            "render {} --spp 8 --seed 5 --aov all --debug-pixel {},{} --debug-log {} -o {}",
            shell_quote(scene), x, y, shell_quote(out + ".json"), shell_quote(out + ".exr"))));
        INFO(r.out);
        REQUIRE(r.exit_code == 0);
        CHECK(read_json(out + ".json")["paths"].size() == 8);
        const auto [floor_hits, ball_hits] = pbr::check_debug_log(out + ".json", true);
        CHECK(floor_hits + ball_hits >= 8);
        CHECK((x == 3 ? floor_hits : ball_hits) >= 8); // every camera ray stops on it
    }
    pbr::check_debug_aovs(dir + "/cpu-3-13.exr", true);
}

} // namespace tp::test
