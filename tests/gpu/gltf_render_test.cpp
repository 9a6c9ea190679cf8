// glTF scenes through the command line on both engines (issue 37): the Cornell box as glTF and
// as OBJ (tests/support/cornell_files.h) render the same image bit for bit with the same seed on
// the CPU and in compute mode, since they flatten to the same floats (unit test "the Cornell box
// flattens exactly as its OBJ twin") and the paths depend only on those and the seed; and glTF
// scenes rendered on the CPU and in compute mode with independent seeds are found consistent by
// twinpath compare.
#include "image/exr_io.h"
#include "support/cornell_files.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cstring>

namespace tp::test {
namespace {

ProcessResult render(const std::string& scene, const std::string& out, const std::string& args) {
    return run(
        twinpath(fmt::format("render {} -o {} {}", shell_quote(scene), shell_quote(out), args)));
}

// Every channel of a and b holds the same bits.
void check_identical(const std::string& a, const std::string& b) {
    const ExrImage x = read_exr(a), y = read_exr(b);
    REQUIRE(x.width == y.width);
    REQUIRE(x.height == y.height);
    for (const char* ch : {"R", "G", "B", "variance.R", "variance.G", "variance.B"}) {
        CAPTURE(ch);
        const std::vector<float>&u = x.channel(ch), &v = y.channel(ch);
        REQUIRE(u.size() == v.size());
        CHECK(std::memcmp(u.data(), v.data(), u.size() * sizeof(float)) == 0);
    }
}

} // namespace

TEST_CASE("the Cornell box as glTF and as OBJ renders the same image with the same seed",
          "[gpu][gltf]") {
    const std::string dir = temp_dir("gltf-obj-cornell");
    const CornellFiles files = write_cornell_files(dir);
    const std::string common = files.camera_flags + " --width 32 --height 32 --spp 4 --seed 9";
    for (const char* engine : {"--backend cpu", "--backend vulkan --vk-mode compute"}) {
        SECTION(engine) {
            const std::string args = common + " " + engine;
            const ProcessResult obj = render(files.obj, dir + "/obj.exr", args);
            INFO(obj.out);
            REQUIRE(obj.exit_code == 0);
            const ProcessResult glb = render(files.glb, dir + "/glb.exr", args);
            INFO(glb.out);
            REQUIRE(glb.exit_code == 0);
            check_identical(dir + "/obj.exr", dir + "/glb.exr");
            const ProcessResult exact =
                run(twinpath(fmt::format("compare --exact {} {}", shell_quote(dir + "/obj.exr"),
                                         shell_quote(dir + "/glb.exr"))));
            INFO(exact.out);
            CHECK(exact.exit_code == 0);
            // The image is the Cornell box's, not an empty one: the light's pixels are bright.
            const ExrImage img = read_exr(dir + "/glb.exr");
            float brightest = 0.0f;
            for (float v : img.channel("R")) brightest = std::max(brightest, v);
            CHECK(brightest > 1.0f);
        }
    }
}

TEST_CASE("glTF scenes on the CPU and in compute mode are consistent", "[gpu][gltf]") {
    // Independent seeds, as the bundled scenes' test (render_test.cpp): the Cornell box as GLB
    // and the bundled glTF example with its camera, lights, textures and materials.
    const std::string dir = temp_dir("gltf-consistent");
    const CornellFiles files = write_cornell_files(dir);
    struct Case {
        std::string name, scene, flags;
        uint32_t spp;
    };
    for (const Case& c : {Case{"cornell.glb", files.glb, files.camera_flags, 256},
                          Case{"gltf_materials", "gltf_materials", "", 64}}) {
        SECTION(c.name) {
            const std::string size =
                fmt::format("{} --width 32 --height 32 --spp {}", c.flags, c.spp);
            const ProcessResult vk = render(c.scene, dir + "/vk.exr",
                                            size + " --seed 6 --backend vulkan --vk-mode compute");
            INFO(vk.out);
            REQUIRE(vk.exit_code == 0);
            const ProcessResult cpu = render(c.scene, dir + "/cpu.exr", size + " --seed 5");
            INFO(cpu.out);
            REQUIRE(cpu.exit_code == 0);
            const ProcessResult cmp =
                run(twinpath(fmt::format("compare {} {} --alpha 0.01", shell_quote(dir + "/vk.exr"),
                                         shell_quote(dir + "/cpu.exr"))));
            INFO(cmp.out);
            CHECK(cmp.exit_code == 0);
        }
    }
}

} // namespace tp::test
