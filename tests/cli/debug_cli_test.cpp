// The debugging command line on the CPU backend (docs/debugging.md): path logs and their
// format, `twinpath pathdiff` exit codes (0 identical, 1 diverging, 2 bad input), the checks
// of --debug-pixel/--debug-log/--aov, the AOV layers and the CPU's debug views.
#include "image/exr_io.h"
#include "support/test_paths.h"
#include "util/json_file.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace tp::test {
namespace {

std::string log_of(const std::string& dir, const std::string& name, const std::string& pixel) {
    const std::string path = dir + "/" + name + ".json";
    const ProcessResult r = run(twinpath(
        fmt::format("render cornell --width 16 --height 16 --spp 2 --seed 4 -o {} --debug-pixel {} "
                    "--debug-log {}",
                    shell_quote(dir + "/" + name + ".exr"), pixel, shell_quote(path))));
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    return path;
}

} // namespace

TEST_CASE("a path log records every vertex of the pixel's paths", "[cli][debug]") {
    const std::string dir = temp_dir("pathlog");
    const nlohmann::json j = read_json(log_of(dir, "a", "8,12"));
    CHECK(j["format"] == "twinpath path log");
    CHECK(j["pixel"] == nlohmann::json({8, 12}));
    REQUIRE(j["paths"].size() == 2);
    for (const auto& p : j["paths"]) {
        const auto& v = p["vertices"];
        REQUIRE(v.size() >= 1);
        CHECK(v[0]["bounce"] == 0);
        // Only the last vertex ends the path, and it says why.
        for (size_t i = 0; i + 1 < v.size(); ++i) CHECK(v[i]["termination"] == "continue");
        CHECK(v.back()["termination"] != "continue");
        CHECK(p["radiance"] == v.back()["radiance"]);
        CHECK(v[0]["rng.lobe"].get<double>() >= 0.0);
        // Positions are camera-relative, as the engines trace them (FlatScene::origin): the
        // camera ray leaves the eye, 0.
        for (int c = 0; c < 3; ++c) CHECK(v[0]["ray_origin"][c].get<double>() == 0.0);
    }
    // The eye in the scene's coordinates, as cornell.json gives it (in double).
    CHECK(j["version"] == 2);
    CHECK(j["origin"] == nlohmann::json({0.278, 0.273, -0.8}));
}

TEST_CASE("pathdiff exit codes: identical 0, diverging 1 with vertex and field, bad input 2",
          "[cli][debug]") {
    const std::string dir = temp_dir("pathdiff-cli");
    const std::string a = log_of(dir, "a", "8,12");
    const auto pathdiff = [&](const std::string& x, const std::string& y) {
        return run(twinpath("pathdiff " + shell_quote(x) + " " + shell_quote(y)));
    };
    const ProcessResult same = pathdiff(a, a);
    CHECK(same.exit_code == 0);
    CHECK_THAT(same.out, Catch::Contains("identical within tolerance: 2 paths"));

    // One field of the first vertex of sample 1, off by 50 %: named, with both values.
    nlohmann::json j = read_json(a);
    auto& path = j["paths"][1]["vertices"];
    REQUIRE(path[0]["bsdf_pdf"].get<double>() > 0.0);
    path[0]["bsdf_pdf"] = path[0]["bsdf_pdf"].get<double>() * 1.5;
    write_json(dir + "/b.json", j);
    const ProcessResult d = pathdiff(a, dir + "/b.json");
    INFO(d.out);
    CHECK(d.exit_code == 1);
    CHECK_THAT(d.out, Catch::Contains("sample 1, vertex 0 (bounce 0), field bsdf_pdf"));
    // Within the radiometric tolerance (1 %) it is not a divergence.
    j = read_json(a);
    j["paths"][1]["vertices"][0]["bsdf_pdf"] =
        j["paths"][1]["vertices"][0]["bsdf_pdf"].get<double>() * 1.001;
    write_json(dir + "/c.json", j);
    CHECK(pathdiff(a, dir + "/c.json").exit_code == 0);

    CHECK(pathdiff(a, dir + "/missing.json").exit_code == 2);
    write_json(dir + "/other.json", nlohmann::json{{"format", "something else"}});
    CHECK(pathdiff(a, dir + "/other.json").exit_code == 2);
    std::ofstream(dir + "/broken.json") << "{ not json";
    CHECK(pathdiff(a, dir + "/broken.json").exit_code == 2);
    const ProcessResult other_pixel = pathdiff(a, log_of(dir, "p", "3,3"));
    CHECK(other_pixel.exit_code == 2);
    CHECK_THAT(other_pixel.out, Catch::Contains("different renders"));
}

TEST_CASE("debug options are checked before rendering", "[cli][debug]") {
    const std::string dir = temp_dir("debug-opts");
    const auto render = [&](const std::string& extra) {
        return run(twinpath("render cornell --width 16 --height 16 --spp 2 -o " +
                            shell_quote(dir + "/x.exr") + " " + extra));
    };
    CHECK(render("--debug-pixel 16,3 --debug-log " + shell_quote(dir + "/l.json")).exit_code == 2);
    CHECK(render("--debug-pixel 3 --debug-log " + shell_quote(dir + "/l.json")).exit_code == 2);
    CHECK(render("--debug-log " + shell_quote(dir + "/l.json")).exit_code == 2);
    CHECK(render("--debug-pixel 3,3 --debug-sample 2 --debug-log " + shell_quote(dir + "/l.json"))
              .exit_code == 2);
    CHECK(render("--debug-pixel 3,3 --debug-log /nonexistent/dir/l.json").exit_code == 2);
    CHECK(render("--aov albedo,colour").exit_code == 2);
    CHECK(render("--integrator wireframe").exit_code == 2);
}

TEST_CASE("AOV layers and debug views on the CPU", "[cli][debug]") {
    const std::string dir = temp_dir("aov-cpu");
    REQUIRE(run(twinpath("render spheres --width 16 --height 16 --spp 1 --aov all -o " +
                         shell_quote(dir + "/a.exr")))
                .exit_code == 0);
    const ExrImage a = read_exr(dir + "/a.exr");
    for (const char* ch : {"albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z",
                           "depth.Z", "id.instance", "id.material"})
        CHECK(a.has(ch));
    for (size_t i = 0; i < a.channel("depth.Z").size(); ++i) {
        const bool miss = a.channel("id.instance")[i] < 0;
        CHECK((miss ? std::isinf(a.channel("depth.Z")[i]) : a.channel("depth.Z")[i] > 0.0f));
    }
    // The same AOVs twice: identical under compare --exact.
    REQUIRE(run(twinpath("render spheres --width 16 --height 16 --spp 1 --seed 9 --aov all -o " +
                         shell_quote(dir + "/b.exr")))
                .exit_code == 0);
    CHECK(run(twinpath("compare --exact " + shell_quote(dir + "/a.exr") + " " +
                       shell_quote(dir + "/b.exr")))
              .exit_code == 0);

    REQUIRE(
        run(twinpath("render cornell --width 16 --height 16 --spp 1 --integrator cost -o " +
                     shell_quote(dir + "/cost.exr") + " --png " + shell_quote(dir + "/cost.png")))
            .exit_code == 0);
    const ExrImage cost = read_exr(dir + "/cost.exr");
    CHECK(cost.strings.at("twinpath:integrator") == "cost");
    for (float v : cost.channel("R")) CHECK(v > 0.0f);
}

} // namespace tp::test
