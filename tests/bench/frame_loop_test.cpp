// bench --frame-loop (bench/frame_loop.h): one tiny real run on Vulkan (lavapipe in CI) through the
// command line, its table in the lab's markdown, the fixed cost's line, and bad options. Never a
// timing: only that each point's parts are the frame's.
#include "support/test_paths.h"
#include "tools/lab/frame_loop_report.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using nlohmann::json;
using tp::test::shell_quote;

TEST_CASE("bench --frame-loop times frames at each spp per frame and splits them", "[frames]") {
    const std::string dir = tp::test::temp_dir("bench-frame-loop");
    const std::string out = dir + "/out";
    const auto p = tp::test::run(
        tp::test::twinpath_bin() +
        " bench --frame-loop --scenes cornell --backends cpu,vulkan:compute --width 8 --height 8 "
        "--frame-loop-spp 1,3 --frame-loop-frames 3 --out " +
        shell_quote(out) + " --cache " + shell_quote(dir + "/cache"));
    INFO(p.out);
    REQUIRE(p.exit_code == 0);
    const json r = tp::test::read_json(out + "/bench.json");
    CHECK(r["sections"] == json::array({"frame_loop"}));
    CHECK(r["settings"]["frame_loop"]["spp"] == json::array({1, 3}));
    // The CPU has no frame loop: said, not run.
    CHECK(r["skipped"].dump().find("the frame loop is the Vulkan viewer's") != std::string::npos);
    const json& runs = r["scenes"][0]["frame_loop"];
    if (runs.empty()) {
        WARN("no Vulkan backend here: " << r["skipped"].dump());
        return;
    }
    const json& run = runs[0];
    CHECK(run["mode"] == "compute");
    REQUIRE(run["points"].size() == 2);
    for (const json& pt : run["points"]) {
        CHECK(pt["frames"] == 3);
        CHECK(pt["ms_mean"].get<double>() > 0);
        if (pt["gpu_ms"].is_null()) continue; // a device without timestamps
        const double parts = pt["gpu_ms"]["trace"].get<double>() +
                             pt["gpu_ms"]["resolve"].get<double>() +
                             pt["gpu_ms"]["display"].get<double>() + pt["host_ms"].get<double>();
        CHECK(parts == Approx(pt["ms_mean"].get<double>()));
    }
    const auto lab =
        tp::test::run(tp::test::twinpath_lab("markdown " + shell_quote(out) + "/bench.json"));
    INFO(lab.out);
    REQUIRE(lab.exit_code == 0);
    std::stringstream md;
    md << std::ifstream(out + "/bench.md").rdbuf();
    CHECK(md.str().find("### Frame loop") != std::string::npos);
    CHECK(md.str().find("| cornell | vulkan/compute | 8x8 | 1 |") != std::string::npos);
}

TEST_CASE("the fixed cost of a frame is the frame time at 0 spp on the line", "[frames]") {
    const json run = {{"points",
                       {{{"spp_per_frame", 1}, {"ms_mean", 3.0}},
                        {{"spp_per_frame", 4}, {"ms_mean", 6.0}},
                        {{"spp_per_frame", 16}, {"ms_mean", 18.0}}}}};
    CHECK(tp::lab::frame_loop_fixed_ms(run).get<double>() == Approx(2.0));
    CHECK(tp::lab::frame_loop_fixed_ms({{"points", {{{"spp_per_frame", 1}, {"ms_mean", 3.0}}}}})
              .is_null());
}

TEST_CASE("bench --frame-loop-spp takes sample counts from 1", "[frames]") {
    const std::string dir = tp::test::temp_dir("bench-frame-loop-bad");
    const auto p =
        tp::test::run(tp::test::twinpath_bin() + " bench --frame-loop --frame-loop-spp 0 --out " +
                      shell_quote(dir + "/out"));
    INFO(p.out);
    CHECK(p.exit_code == 2);
    CHECK(!fs::exists(dir + "/out"));
}
