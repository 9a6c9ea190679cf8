// twinpath render through the command line, on good input: the EXR of docs/design.md ("Image
// output"), the PNG preview, the statistics JSON, skipped degenerate triangles, auto-framing of
// a bare OBJ, and the usage errors of the argument parser itself.
#include "image/exr_io.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
using tp::test::run;
using tp::test::shell_quote;

namespace {

std::string bin() {
    return tp::test::twinpath_bin();
}

} // namespace

TEST_CASE("render writes the EXR and PNG and statistics docs/design.md describes", "[cli]") {
    const fs::path dir = tp::test::temp_dir("cli-render");
    const auto r = run(bin() + " render furnace --spp 4 --width 8 --height 6 --seed 9 -o " +
                       shell_quote((dir / "f.exr").string()) + " --png " +
                       shell_quote((dir / "f.png").string()) + " --stats " +
                       shell_quote((dir / "f.json").string()));
    INFO(r.out);
    REQUIRE(r.exit_code == 0);

    const tp::ExrImage img = tp::read_exr((dir / "f.exr").string());
    CHECK(img.width == 8);
    CHECK(img.height == 6);
    for (const char* c : {"R", "G", "B", "variance.R", "variance.G", "variance.B"})
        CHECK(img.has(c));
    CHECK(img.integers.at("twinpath:spp") == 4);
    CHECK(img.integers.at("twinpath:seed") == 9);
    CHECK(img.strings.at("twinpath:backend").rfind("cpu", 0) == 0);
    CHECK(img.strings.at("twinpath:scene").find("furnace") != std::string::npos);
    CHECK(img.strings.count("twinpath:device") == 1);
    CHECK(img.reals.count("twinpath:render_time_s") == 1);
    for (float v : img.channel("variance.R")) CHECK(v >= 0.0f);

    std::ifstream png(dir / "f.png", std::ios::binary);
    char sig[8] = {};
    png.read(sig, 8);
    CHECK(std::string(sig + 1, 3) == "PNG");

    const nlohmann::json stats = nlohmann::json::parse(std::ifstream(dir / "f.json"));
    CHECK(stats.at("spp") == 4);
    CHECK(stats.at("width") == 8);
    CHECK(stats.at("nan_samples") == 0);
    CHECK(stats.at("samples") == 8 * 6 * 4);
    CHECK(stats.at("rays").at("camera") == 8 * 6 * 4);
    fs::remove_all(dir);
}

TEST_CASE("render without -o writes <scene stem>.exr in the working directory", "[cli]") {
    const fs::path dir = tp::test::temp_dir("cli-default-out");
    const auto r = run("cd " + shell_quote(dir.string()) + " && " + bin() +
                       " render furnace --spp 1 --width 4 --height 4");
    INFO(r.out);
    CHECK(r.exit_code == 0);
    CHECK(fs::exists(dir / "furnace.exr"));
    fs::remove_all(dir);
}

TEST_CASE("zero-area triangles are skipped with a count and the image still renders", "[cli]") {
    // Two degenerate triangles (three collinear points; a repeated vertex) next to a good one.
    const fs::path dir = tp::test::temp_dir("cli-degenerate");
    std::ofstream(dir / "d.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\n"
                                    "f 1 2 3\nf 1 2 4\nf 1 1 3\n";
    const auto r = run(bin() + " render " + shell_quote((dir / "d.obj").string()) +
                       " --spp 2 --width 8 --height 8 -o " + shell_quote((dir / "d.exr").string()));
    INFO(r.out);
    CHECK(r.exit_code == 0);
    CHECK(r.out.find("d.obj") != std::string::npos);
    CHECK(r.out.find("skipped 2 degenerate") != std::string::npos);
    CHECK(fs::exists(dir / "d.exr"));
    fs::remove_all(dir);
}

TEST_CASE("a bare OBJ is framed automatically and lit by a white environment", "[cli]") {
    const fs::path dir = tp::test::temp_dir("cli-obj");
    std::ofstream(dir / "q.obj") << "v -1 -1 5\nv 1 -1 5\nv 1 1 5\nv -1 1 5\nf 1 2 3 4\n";
    const auto r = run(bin() + " render " + shell_quote((dir / "q.obj").string()) +
                       " --spp 4 --width 8 --height 8 -o " + shell_quote((dir / "q.exr").string()));
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("white environment") != std::string::npos);
    // The quad fills the centre of the frame: the centre pixel sees it, lit (not black).
    const tp::ExrImage img = tp::read_exr((dir / "q.exr").string());
    CHECK(img.channel("R")[size_t(4 * 8 + 4)] > 0.0f);
    fs::remove_all(dir);
}

// Where a scene sits (docs/stress.md, "Scale and position"): an OBJ whose vertices are written in
// full double precision 1e4 away, with the camera moved alike by --eye/--target, renders the image
// and path log of the same scene at the origin for the same seed. Every coordinate is on the grid
// of 2^-14 (finer than float's 2^-10 at 1e4), so each moved number is exact in double and the scene
// is the same scene exactly; the loaders, --eye/--target and flatten() keep double until the camera
// is subtracted. Before, the file and the flags were read as floats and meshes stored in their own
// coordinates, where hit points were interpolated in float: 130 of 256 pixels differed (99 with
// every coordinate on the grid of 2^-4, which float holds exactly at 1e4).
TEST_CASE("a scene moved 1e4 away with its camera renders the same image", "[cli]") {
    const fs::path dir = tp::test::temp_dir("cli-moved");
    std::ofstream(dir / "m.mtl") << "newmtl wall\nKd 0.6 0.5 0.4\nnewmtl lamp\nKe 4 4 4\n";
    // A floor, a back wall, a tilted box face and a lamp facing down.
    const double points[16][3] = {{-1, 0, -1},
                                  {1, 0, -1},
                                  {1, 0, 1},
                                  {-1, 0, 1},
                                  {-1, 0, -1},
                                  {-1, 2, -1},
                                  {1, 2, -1},
                                  {1, 0, -1},
                                  {-0.31256103515625, 0, 0.25},
                                  {0.1875, 0, -0.06243896484375},
                                  {0.1875, 0.5, -0.06243896484375},
                                  {-0.31256103515625, 0.5, 0.25},
                                  {-0.25, 1.9375, -0.25},
                                  {0.25, 1.9375, -0.25},
                                  {0.25, 1.9375, 0.25},
                                  {-0.25, 1.9375, 0.25}};
    const auto render = [&](double d, const std::string& name) {
        std::string obj = "mtllib m.mtl\n";
        for (const auto& p : points)
            obj += fmt::format("v {:.17g} {:.17g} {:.17g}\n", p[0] + d, p[1] + d, p[2] + d);
        obj += "usemtl wall\nf 1 4 3 2\nf 5 8 7 6\nf 9 10 11 12\nusemtl lamp\nf 13 14 15 16\n";
        const fs::path file = dir / (name + ".obj");
        std::ofstream(file) << obj;
        const auto r =
            run(fmt::format("{} render {} --eye {:.17g},{:.17g},{:.17g} --target "
                            "{:.17g},{:.17g},{:.17g} --width 16 "
                            "--height 16 --spp 8 --seed 3 -o {} --debug-pixel 8,9 --debug-log {}",
                            bin(), shell_quote(file.string()), 0.06256103515625 + d, 1.0 + d,
                            3.5 + d, d, 0.5 + d, d, shell_quote((dir / (name + ".exr")).string()),
                            shell_quote((dir / (name + ".json")).string())));
        INFO(r.out);
        REQUIRE(r.exit_code == 0);
        return std::make_pair(tp::read_exr((dir / (name + ".exr")).string()),
                              tp::test::read_json((dir / (name + ".json")).string()));
    };
    const auto [image, log] = render(0.0, "origin");
    const auto [moved_image, moved_log] = render(1e4, "moved");
    for (const char* c : {"R", "G", "B", "variance.R", "variance.G", "variance.B"}) {
        INFO(c);
        CHECK(image.channel(c) == moved_image.channel(c));
    }
    // The logs record camera-relative positions (docs/debugging.md): the same paths.
    CHECK(log["paths"] == moved_log["paths"]);
    CHECK(moved_log["origin"] == nlohmann::json({0.06256103515625 + 1e4, 1.0 + 1e4, 3.5 + 1e4}));
    fs::remove_all(dir);
}

TEST_CASE("usage errors exit with 2 and --help with 0", "[cli]") {
    CHECK(run(bin() + " --help").exit_code == 0);
    CHECK(run(bin() + " render --help").exit_code == 0);
    CHECK(run(bin()).exit_code == 2);
    CHECK(run(bin() + " frobnicate").exit_code == 2);
    CHECK(run(bin() + " render").exit_code == 2);
    CHECK(run(bin() + " render furnace --bogus").exit_code == 2);
    CHECK(run(bin() + " render furnace --backend opengl").exit_code == 2);
}

TEST_CASE("a scene without light: render warns, and the black file against itself is consistent "
          "with a warning that it shares its samples",
          "[cli]") {
    // The furnace without its emission: nothing emits, every pixel is 0 with variance 0.
    const fs::path dir = tp::test::temp_dir("cli-dark");
    const std::string scene = (dir / "dark.json").string();
    std::ifstream in(tp::test::scenes_dir() + "/furnace.json");
    nlohmann::json j = nlohmann::json::parse(in);
    j["materials"]["wall"].erase("Ke");
    std::ofstream(scene) << j.dump(2);
    const std::string exr = shell_quote((dir / "x.exr").string());
    const auto r =
        run(bin() + " render " + shell_quote(scene) + " --spp 4 --width 16 --height 16 -o " + exr);
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("warning: " + scene + ": nothing in the scene emits light") !=
          std::string::npos);

    const auto c = run(bin() + " compare " + exr + " " + exr);
    INFO(c.out);
    CHECK(c.exit_code == 0);
    CHECK(c.out.find("consistent: p = 1 ") != std::string::npos);
    CHECK(c.out.find("share samples 0 to 3 of seed 0 (sobol sampler)") != std::string::npos);
    CHECK(c.out.find("\"consistent\" proves nothing") != std::string::npos);

    // A scene that emits draws no such warning.
    const auto lit = run(bin() + " render furnace --spp 1 --width 4 --height 4 -o " + exr);
    CHECK(lit.out.find("emits") == std::string::npos);
    fs::remove_all(dir);
}
