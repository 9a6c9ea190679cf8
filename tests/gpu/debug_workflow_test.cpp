// The debugging workflow of docs/debugging.md, through the command line as a user runs it:
// - without a bug, `pathdiff` finds the CPU and the Vulkan compute paths identical within
//   tolerance on every bundled scene, for pixels that include mirror, glass and silhouette
//   pixels (found from the CPU's AOVs);
// - with a bug planted in the debug shader by a compile-time definition (tests/gpu/
//   debug_tests.cmake: a wrong sign in the Fresnel term, swapped barycentrics, a light pdf off
//   by a factor 2, an off-by-one random-number dimension), `compare` rejects the image and
//   `pathdiff` names the vertex and the field where the bug first shows;
// - AOVs agree under `compare --exact`, and the debug views render on the GPU.
#include "image/exr_io.h"
#include "scene/flatten.h"
#include "scene/load.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <set>

namespace tp::test {
namespace {

std::string bug_spirv(const std::string& bug) {
    return std::string(TP_BUG_SPIRV_DIR) + "/" + bug + ".spv";
}

// A logged render of `scene`: image out.exr, path log out.json.
ProcessResult logged_render(const std::string& scene, const std::string& backend,
                            const std::string& out, uint32_t x, uint32_t y,
                            const std::string& extra, const std::string& env = "") {
    return run(env + twinpath(fmt::format(
                         "render {} --backend {} --vk-mode compute -o {} --debug-pixel {},{} "
                         "--debug-log {} {}",
                         scene, backend, shell_quote(out + ".exr"), x, y,
                         shell_quote(out + ".json"), extra)));
}

struct PixelPick {
    std::string kind;
    uint32_t x, y;
};

// Pixels worth logging in a W x H render of `scene`: the centre, the first mirror and glass
// pixels and the first silhouette pixel (an instance id differing from the right neighbour's)
// in scan order, from the CPU's AOVs.
std::vector<PixelPick> interesting_pixels(const std::string& scene, const std::string& dir, int W,
                                          int H) {
    const std::string aov = dir + "/aov.exr";
    REQUIRE(run(twinpath(fmt::format("render {} --width {} --height {} --spp 1 --aov all -o {}",
                                     scene, W, H, shell_quote(aov))))
                .exit_code == 0);
    const ExrImage img = read_exr(aov);
    std::vector<std::string> warnings;
    const FlatScene flat = flatten(load_scene(scenes_dir() + "/" + scene + ".json", warnings));
    const std::vector<float>& inst = img.channel("id.instance");
    const std::vector<float>& mat = img.channel("id.material");
    std::vector<PixelPick> picks = {{"centre", uint32_t(W / 2), uint32_t(H / 2)}};
    std::set<std::string> found;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const size_t i = size_t(y * W + x);
            std::string kind;
            if (mat[i] >= 0 && flat.materials[size_t(mat[i])].type == MATERIAL_MIRROR)
                kind = "mirror";
            else if (mat[i] >= 0 && flat.materials[size_t(mat[i])].type == MATERIAL_DIELECTRIC)
                kind = "glass";
            else if (x + 1 < W && inst[i] != inst[i + 1])
                kind = "silhouette";
            if (!kind.empty() && !found.count(kind)) {
                found.insert(kind);
                picks.push_back({kind, uint32_t(x), uint32_t(y)});
            }
        }
    return picks;
}

} // namespace

TEST_CASE("pathdiff finds CPU and Vulkan compute paths identical on every bundled scene", "[gpu]") {
    // 4 samples of each pixel, so that every path of the pixel's first samples is compared.
    const int W = 24, H = 24;
    for (const auto& entry : std::filesystem::directory_iterator(scenes_dir())) {
        if (entry.path().extension() != ".json") continue;
        const std::string scene = entry.path().stem().string();
        SECTION(scene) {
            const std::string dir = temp_dir("pathdiff-" + scene);
            for (const PixelPick& p : interesting_pixels(scene, dir, W, H)) {
                const std::string common =
                    fmt::format("--width {} --height {} --spp 4 --seed 11", W, H);
                const std::string a = fmt::format("{}/cpu-{}-{}", dir, p.x, p.y);
                const std::string b = fmt::format("{}/vk-{}-{}", dir, p.x, p.y);
                REQUIRE(logged_render(scene, "cpu", a, p.x, p.y, common).exit_code == 0);
                const ProcessResult vk = logged_render(scene, "vulkan", b, p.x, p.y, common);
                INFO(vk.out);
                REQUIRE(vk.exit_code == 0);
                const ProcessResult d = run(twinpath(fmt::format(
                    "pathdiff {} {}", shell_quote(a + ".json"), shell_quote(b + ".json"))));
                INFO(scene << " " << p.kind << " pixel " << p.x << "," << p.y << "\n" << d.out);
                CHECK(d.exit_code == 0);
                CHECK_THAT(d.out, Catch::Contains("identical within tolerance: 4 paths"));
                CHECK(read_json(b + ".json")["paths"].size() == 4);
            }
        }
    }
}

TEST_CASE("spheres has mirror glass and silhouette pixels to log", "[gpu]") {
    const std::string dir = temp_dir("pathdiff-picks");
    std::set<std::string> kinds;
    for (const PixelPick& p : interesting_pixels("spheres", dir, 24, 24)) kinds.insert(p.kind);
    CHECK(kinds.count("mirror"));
    CHECK(kinds.count("glass"));
    CHECK(kinds.count("silhouette"));
}

namespace {

struct PlantedBug {
    const char* define;           // the bug's name in tests/gpu/debug_tests.cmake
    const char* scene;            // where it shows
    uint32_t x, y;                // the logged pixel (a 32 x 32 render)
    size_t vertex;                // where pathdiff must find it first
    std::set<std::string> fields; // the field(s) it may name there
};

} // namespace

TEST_CASE("planted shader bugs: compare rejects the image and pathdiff names vertex and field",
          "[gpu]") {
    // The pixels: the floor of the Cornell box (a diffuse vertex that samples the ceiling light),
    // the middle of the glass sphere of spheres (its first vertex is the dielectric) and the
    // textured floor of spheres.
    const PlantedBug bugs[] = {
        {"RNG_DIM", "cornell", 16, 24, 0, {"rng.dir_v"}},
        {"LIGHT_PDF", "cornell", 16, 24, 0, {"light_pdf"}},
        // Swapped barycentrics move the shading point within its triangle. On cornell's flat
        // untextured triangles that only shifts what the point sees: compare's p was 0.007
        // against alpha = 0.01, and 0.93 with another random-number layout (docs/learnt.md,
        // "Four random numbers per hash"), a pass by luck. On spheres' textured floor they move
        // the texture and on the spheres the interpolated normal: p ~ 1e-70 with either layout.
        {"SWAP_BARY", "spheres", 16, 30, 0, {"bary"}},
        // A larger reflectance: either the pdf of the chosen lobe (F) or the lobe itself.
        {"FRESNEL_SIGN", "spheres", 12, 16, 0, {"bsdf_pdf", "lobe"}},
    };
    for (const PlantedBug& bug : bugs) {
        SECTION(bug.define) {
            const std::string dir = temp_dir(std::string("bug-") + bug.define);
            const std::string size = "--width 32 --height 32";
            // The bugged GPU image (seed 1) against an independent CPU image (seed 2).
            const std::string env =
                "TWINPATH_DEBUG_SPIRV=" + shell_quote(bug_spirv(bug.define)) + " ";
            const ProcessResult gpu =
                logged_render(bug.scene, "vulkan", dir + "/gpu", bug.x, bug.y,
                              size + " --spp 64 --seed 1 --debug-sample 0", env);
            INFO(gpu.out);
            REQUIRE(gpu.exit_code == 0);
            // Against an independent CPU image with as many samples, and with 8x as many, as
            // a user checks a GPU render against the reference (docs/compare.md, "Unequal
            // sample counts").
            for (const uint32_t spp : {64u, 512u}) {
                const std::string cpu = fmt::format("{}/cpu{}.exr", dir, spp);
                REQUIRE(run(twinpath(fmt::format("render {} {} --spp {} --seed 2 -o {}", bug.scene,
                                                 size, spp, shell_quote(cpu))))
                            .exit_code == 0);
                const ProcessResult cmp = run(twinpath(
                    fmt::format("compare {} {}", shell_quote(dir + "/gpu.exr"), shell_quote(cpu))));
                INFO(cmp.out);
                CHECK(cmp.exit_code == 1);
            }

            // The same path on the CPU (seed 1, sample 0) against the GPU's.
            REQUIRE(logged_render(bug.scene, "cpu", dir + "/ref", bug.x, bug.y,
                                  size + " --spp 1 --seed 1")
                        .exit_code == 0);
            const ProcessResult d = run(twinpath(fmt::format(
                "pathdiff {} {}", shell_quote(dir + "/ref.json"), shell_quote(dir + "/gpu.json"))));
            INFO(d.out);
            CHECK(d.exit_code == 1);
            bool named = false;
            for (const std::string& field : bug.fields)
                named =
                    named || d.out.find(fmt::format("vertex {} (bounce {}), field {}:", bug.vertex,
                                                    bug.vertex, field)) != std::string::npos;
            CHECK(named);
        }
    }
}

TEST_CASE("without a planted bug the same shader variant passes both checks", "[gpu]") {
    // The control for the test above: the debug variant itself, loaded the same way.
    const std::string dir = temp_dir("bug-none");
    const std::string gpu = dir + "/gpu";
    REQUIRE(
        logged_render("cornell", "vulkan", gpu, 16, 24, "--width 32 --height 32 --spp 1 --seed 1")
            .exit_code == 0);
    REQUIRE(logged_render("cornell", "cpu", dir + "/ref", 16, 24,
                          "--width 32 --height 32 --spp 1 --seed 1")
                .exit_code == 0);
    const ProcessResult d = run(twinpath(
        fmt::format("pathdiff {} {}", shell_quote(dir + "/ref.json"), shell_quote(gpu + ".json"))));
    INFO(d.out);
    CHECK(d.exit_code == 0);
}

TEST_CASE("AOVs of the two backends agree under compare --exact and a planted bug breaks them",
          "[gpu]") {
    const std::string dir = temp_dir("aov-exact");
    const std::string common = "spheres --width 40 --height 40 --spp 1 --aov all";
    REQUIRE(run(twinpath("render " + common + " -o " + shell_quote(dir + "/cpu.exr"))).exit_code ==
            0);
    REQUIRE(run(twinpath("render " + common + " --backend vulkan --vk-mode compute -o " +
                         shell_quote(dir + "/vk.exr")))
                .exit_code == 0);
    const ProcessResult ok = run(twinpath(fmt::format(
        "compare --exact {} {}", shell_quote(dir + "/cpu.exr"), shell_quote(dir + "/vk.exr"))));
    INFO(ok.out);
    CHECK(ok.exit_code == 0);
    CHECK_THAT(ok.out, Catch::Contains("silhouette pixels"));

    REQUIRE(run("TWINPATH_DEBUG_SPIRV=" + shell_quote(bug_spirv("SWAP_BARY")) + " " +
                twinpath("render " + common + " --backend vulkan --vk-mode compute -o " +
                         shell_quote(dir + "/bug.exr")))
                .exit_code == 0);
    const ProcessResult bad = run(twinpath(fmt::format(
        "compare --exact {} {}", shell_quote(dir + "/cpu.exr"), shell_quote(dir + "/bug.exr"))));
    INFO(bad.out);
    CHECK(bad.exit_code == 1);
    CHECK_THAT(bad.out, Catch::Contains("normal."));
}

TEST_CASE("debug views render on the GPU like on the CPU", "[gpu]") {
    const std::string dir = temp_dir("views");
    for (const char* view : {"normals", "albedo", "depth"}) {
        const std::string common =
            fmt::format("cornell --width 16 --height 16 --spp 2 --seed 3 --integrator {}", view);
        REQUIRE(run(twinpath(fmt::format("render {} -o {}", common, shell_quote(dir + "/c.exr"))))
                    .exit_code == 0);
        REQUIRE(run(twinpath(fmt::format("render {} --backend vulkan --vk-mode compute -o {}",
                                         common, shell_quote(dir + "/v.exr"))))
                    .exit_code == 0);
        const ExrImage c = read_exr(dir + "/c.exr"), v = read_exr(dir + "/v.exr");
        CHECK(v.strings.at("twinpath:integrator") == view);
        // The same jittered camera rays: the same means up to rounding (silhouettes aside).
        size_t differ = 0;
        for (const char* ch : {"R", "G", "B"})
            for (size_t i = 0; i < c.channel(ch).size(); ++i)
                differ += std::abs(c.channel(ch)[i] - v.channel(ch)[i]) > 1e-3f;
        INFO(view << ": " << differ << " pixel-channels differ");
        CHECK(differ <= 3 * 16 * 16 / 20);
    }
    // Cost: nodes and triangles of the software traversal, positive wherever a ray was traced.
    REQUIRE(
        run(twinpath(fmt::format("render cornell --width 16 --height 16 --spp 1 --backend "
                                 "vulkan --vk-mode compute --integrator cost -o {} --png {}",
                                 shell_quote(dir + "/cost.exr"), shell_quote(dir + "/cost.png"))))
            .exit_code == 0);
    const ExrImage cost = read_exr(dir + "/cost.exr");
    for (size_t i = 0; i < cost.channel("R").size(); ++i) {
        CHECK(cost.channel("R")[i] >= 1.0f);
        CHECK(cost.channel("B")[i] == cost.channel("R")[i] + cost.channel("G")[i]);
    }
}

} // namespace tp::test
