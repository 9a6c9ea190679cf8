// `twinpath bench --sizes` (bench/sizes.h): the size list's parsing and order, bad options, and
// one tiny real run on the CPU and Vulkan (lavapipe in CI) through the command line. Its table
// and plot are the lab's (tests/lab/sizes_report_test.cpp). Never a timing: only that the rates
// are the render's rays over its own time.
#include "bench/scenes.h"
#include "bench/sizes.h"
#include "support/test_paths.h"
#include "util/error.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using nlohmann::json;
using tp::bench::ImageSize;
using tp::test::read_json;
using tp::test::shell_quote;

namespace {

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace

TEST_CASE("bench --sizes-list words parse to sizes in ascending order of pixels", "[sizes]") {
    using tp::bench::parse_image_size;
    using tp::bench::parse_image_sizes;
    CHECK(parse_image_size("256") == ImageSize{256, 256});
    CHECK(parse_image_size("1920x1080") == ImageSize{1920, 1080});
    CHECK(parse_image_size("3840X2160") == ImageSize{3840, 2160});
    CHECK(parse_image_size("1920×1080") == ImageSize{1920, 1080});
    CHECK(parse_image_size("16384x1") == ImageSize{16384, 1});
    CHECK(ImageSize{1920, 1080}.name() == "1920x1080");
    CHECK(ImageSize{1920, 1080}.pixels() == 2073600);
    for (const char* bad : {"", "x", "0", "0x64", "64x0", "16385", "64x", "x64", "-64", "6 4",
                            "64x64x64", "1e3", "99999999999999999999", "64.5"}) {
        INFO(bad);
        CHECK_THROWS_AS(parse_image_size(bad), tp::InputError);
    }
    const std::vector<ImageSize> sorted =
        parse_image_sizes({"1920x1080", "64", "64x64", "1080x1920", "128x32", "32x128"});
    CHECK(sorted ==
          std::vector<ImageSize>{{32, 128}, {64, 64}, {128, 32}, {1080, 1920}, {1920, 1080}});
    CHECK_THROWS_AS(parse_image_sizes({}), tp::InputError);
}

TEST_CASE("sized scene names give a family and a number of copies", "[sizes]") {
    using tp::bench::parse_sized_scene;
    const auto sized = parse_sized_scene("buddhas_30");
    REQUIRE(sized);
    CHECK(sized->family == "buddhas");
    CHECK(sized->copies == 30);
    CHECK(tp::bench::sized_scene_name({"suzannes", 4}) == "suzannes_4");
    for (const char* other : {"buddhas", "buddhas_", "buddhas_0", "buddhas_07", "buddhas_10001",
                              "buddhas_instanced", "buddhas_3x", "bunnies_3", "cornell"}) {
        INFO(other);
        CHECK(!parse_sized_scene(other));
    }
    const auto entry = tp::bench::find_catalogue_entry("suzannes_5");
    REQUIRE(entry);
    const json scene = entry->generate("/assets");
    CHECK(scene["objects"].size() == 6); // the floor and five copies
    CHECK(scene["meshes"].size() == 6);  // each copy its own mesh: no instancing
    CHECK(scene["meshes"]["suzannes_4"]["file"] == "/assets/suzanne/suzanne.obj");
}

TEST_CASE("bench --sizes rejects bad sizes, times and rounds with exit code 2", "[sizes]") {
    const std::string dir = tp::test::temp_dir("bench-sizes-bad");
    for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
             {"--sizes-list 64x0", "each side must be 1 to 16384"},
             {"--sizes-list 64,big", "'big' is not an image size"},
             {"--sizes-time 0", "--sizes-time"},
             {"--sizes-rounds 0", "--sizes-rounds"},
             {"--sizes-spp 0", "--sizes-spp"},
             {"--scene-sizes 0", "--scene-sizes: copies are 1 to"},
             {"--scene-sizes 2 --scene-sizes-family bunnies", "'bunnies' is not one of"}}) {
        const auto p = tp::test::run(tp::test::twinpath_bin() + " bench --quick --sizes " + args +
                                     " --out " + shell_quote(dir + "/out"));
        INFO(args << "\n" << p.out);
        CHECK(p.exit_code == 2);
        CHECK(contains(p.out, message));
        CHECK(!fs::exists(dir + "/out"));
    }
}

TEST_CASE("bench --sizes measures every size on the CPU and Vulkan", "[sizes]") {
    const std::string dir = tp::test::temp_dir("bench-sizes");
    const std::string out = dir + "/out";
    const auto p = tp::test::run(tp::test::twinpath_bin() +
                                 " bench --quick --sizes --scenes cornell --backends cpu,vulkan "
                                 "--sizes-list 8,4x4 --sizes-time 0.01 --width 4 --height 4 "
                                 "--out " +
                                 shell_quote(out) + " --cache " + shell_quote(dir + "/cache"));
    INFO(p.out);
    REQUIRE(p.exit_code == 0);
    const json r = read_json(out + "/bench.json");
    CHECK(r["sections"] == json::array({"sizes"}));
    CHECK(r["settings"]["sizes"]["list"] == json::array({"4x4", "8x8"}));
    const json& runs = r["scenes"][0]["sizes"];
    REQUIRE(runs.size() == r["backends"].size());
    if (runs.size() == 1) WARN("no Vulkan backend here: " << r["skipped"].dump());
    CHECK(runs[0]["backend"] == "cpu");
    CHECK(runs[0]["timer"] == "wall"); // the CPU has no GPU time
    for (const json& run : runs) {
        REQUIRE(run["points"].size() == 2);
        for (const json& pt : run["points"]) {
            const double n = pt["pixels"], spp = pt["spp"];
            CHECK(n == pt["width"].get<double>() * pt["height"].get<double>());
            CHECK(spp >= 1);
            CHECK(pt["rays"]["camera"] == n * spp); // one camera ray per sample: whole passes
            // At least the time asked for: the limit ends a render after the pass that crosses
            // it.
            CHECK(pt["wall_s"].get<double>() >= 0.01);
            // The rate is the render's rays over its own time, the timer the run names.
            const double seconds = run["timer"] == "gpu" ? pt["gpu_s"] : pt["wall_s"];
            const double rays = pt["rays"]["camera"].get<double>() +
                                pt["rays"]["extension"].get<double>() +
                                pt["rays"]["shadow"].get<double>();
            CHECK(pt["mrays_s"].get<double>() == Approx(1e-6 * rays / seconds));
            CHECK(pt["rounds_mrays_s"].size() == 1); // --quick: one round
        }
    }
}

TEST_CASE("bench --sizes --scene-sizes measures scenes of N distinct meshes", "[sizes]") {
    const std::string dir = tp::test::temp_dir("bench-scene-sizes");
    const std::string out = dir + "/out";
    const auto p =
        tp::test::run(tp::test::twinpath_bin() +
                      " bench --quick --sizes --scene-sizes 2,1 --scene-sizes-family suzannes "
                      "--backends cpu,vulkan:compute --sizes-list 8x6 --sizes-spp 2 --out " +
                      shell_quote(out) + " --cache " + shell_quote(dir + "/cache"));
    INFO(p.out);
    REQUIRE(p.exit_code == 0);
    const json r = read_json(out + "/bench.json");
    if (r["scenes"].empty()) {
        WARN("the shared test meshes are missing: " << r["skipped"].dump());
        return;
    }
    CHECK(r["settings"]["sizes"]["scene_sizes"] == json::array({2, 1}));
    REQUIRE(r["scenes"].size() == 2); // only the sized scenes: --scenes was not given
    const json &two = r["scenes"][0], &one = r["scenes"][1];
    CHECK(two["name"] == "suzannes_2");
    CHECK(one["name"] == "suzannes_1");
    // Suzanne's 968 triangles a copy, and the floor's two; each copy stored on its own.
    CHECK(one["unique_triangles"] == 970);
    CHECK(two["unique_triangles"] == 2 * 968 + 2);
    CHECK(two["triangles"] == two["unique_triangles"]);
    for (const json& sc : r["scenes"]) {
        const json& runs = sc["sizes"];
        REQUIRE(runs.size() == r["backends"].size());
        if (runs.size() == 1) WARN("no Vulkan backend here: " << r["skipped"].dump());
        for (const json& run : runs) {
            REQUIRE(run["points"].size() == 1);
            const json& pt = run["points"][0];
            CHECK(pt["spp"] == 2); // --sizes-spp: exactly that many, no time limit
            CHECK(pt["triangles"] == sc["unique_triangles"]);
            CHECK(pt["build_s"].get<double>() > 0);
            if (run["backend"] == "cpu") {
                CHECK(pt["build_stages"].is_null());
                CHECK(pt["device_memory_peak_bytes"].is_null());
                continue;
            }
            for (const char* stage : {"primitives", "embree", "layout", "write", "estimate"})
                CHECK(pt["build_stages"][stage].get<double>() >= 0);
            CHECK(pt["upload_s"].get<double>() >= 0);
            CHECK(pt["device_memory_peak_bytes"].get<uint64_t>() >=
                  pt["accel_bytes"].get<uint64_t>());
        }
    }
}
