// --exact: the simple channel-by-channel equality that the AOV comparison of docs/debugging.md
// builds on.
#include "image/exr_io.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <limits>

using namespace tp;
using namespace tp::test;

TEST_CASE("exact mode counts mismatching pixels per channel, with and without tolerance",
          "[compare][exact][cli]") {
    const std::string dir = temp_dir("exact");
    ExrImage a;
    a.width = a.height = 8;
    for (const char* c : {"albedo.R", "albedo.G", "albedo.B", "depth.Z"})
        a.channels[c].assign(64, 0.25f);
    a.channels["depth.Z"][63] = std::numeric_limits<float>::infinity(); // a background pixel
    ExrImage b = a;
    b.channels["albedo.R"][3] = 0.2501f;     // 1e-4 off
    b.channels["albedo.G"][3] = 0.3f;        // same pixel, another channel
    b.channels["depth.Z"][10] = 0.5f;        // another pixel
    b.channels["normal.X"].assign(64, 0.0f); // only in B: listed, not compared
    write_exr(dir + "/a.exr", a);
    write_exr(dir + "/b.exr", b);
    const std::string cmd = fmt::format("{} compare --exact {} {} --json {}",
                                        shell_quote(twinpath_bin()), shell_quote(dir + "/a.exr"),
                                        shell_quote(dir + "/b.exr"), shell_quote(dir + "/e.json"));

    const ProcessResult strict = run(cmd);
    INFO(strict.out);
    CHECK(strict.exit_code == 1);
    CHECK(strict.out.rfind("different: 2 of 64 pixels", 0) == 0);
    auto j = nlohmann::json::parse(std::ifstream(dir + "/e.json"));
    CHECK(j["mismatches"]["albedo.R"] == 1);
    CHECK(j["mismatches"]["albedo.G"] == 1);
    CHECK(j["mismatches"]["depth.Z"] == 1);
    CHECK(j["mismatches"]["albedo.B"] == 0);
    CHECK(j["only_in_b"] == nlohmann::json::array({"normal.X"}));
    CHECK(j["max_abs_difference"].get<double>() == Approx(0.25));

    // Tolerance 0.06 forgives albedo.R (1e-4) and albedo.G (0.05) but not depth (0.25).
    const ProcessResult tolerant = run(cmd + " --tolerance 0.06");
    CHECK(tolerant.exit_code == 1);
    j = nlohmann::json::parse(std::ifstream(dir + "/e.json"));
    CHECK(j["mismatching_pixels"] == 1);

    const ProcessResult same =
        run(fmt::format("{} compare --exact {} {}", shell_quote(twinpath_bin()),
                        shell_quote(dir + "/a.exr"), shell_quote(dir + "/a.exr")));
    CHECK(same.exit_code == 0);
    CHECK(same.out.rfind("identical: 4 channels", 0) == 0);
}
