// `twinpath bench` at a tiny size through the real command line: the ladder and the table run
// and write a well-formed result (bench.json, and nothing else: its tables and plots are the
// lab's, tests/lab/), the reference cache is reused and keyed by the scene, missing assets, bad
// options and the options that moved to twinpath-lab say so clearly. Never a timing: only that
// times are there.
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using nlohmann::json;
using tp::test::read_json;
using tp::test::run;
using tp::test::shell_quote;

namespace {

// `twinpath bench` with the CI smoke size (--quick: 24x24, ladder 1, 2, 4 spp, reference 32 spp)
// and the given arguments.
tp::test::ProcessResult bench(const std::string& args) {
    return run(tp::test::twinpath_bin() + " bench --quick " + args);
}

std::string dir_args(const std::string& out, const std::string& cache) {
    return " --out " + shell_quote(out) + " --cache " + shell_quote(cache) + " ";
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

std::vector<std::string> labels_of(const json& result) {
    std::vector<std::string> labels;
    for (const json& b : result["backends"])
        labels.push_back(b["backend"].get<std::string>() + "/" + b["mode"].get<std::string>());
    return labels;
}

// The skipped entry whose `what` contains `what`, or null.
json skipped_entry(const json& result, const std::string& what) {
    for (const json& s : result["skipped"])
        if (contains(s["what"].get<std::string>(), what)) return s;
    return nullptr;
}

void check_ladder(const json& r) {
    const std::vector<std::string> labels = labels_of(r);
    const json& sc = r["scenes"][0];
    REQUIRE(sc["ladder"].size() == labels.size());
    for (const json& l : sc["ladder"]) {
        REQUIRE(l["points"].size() == 3);
        for (size_t i = 0; i < 3; ++i) {
            const json& p = l["points"][i];
            CHECK(p["spp"] == (1u << i));
            CHECK(p["wall_s"].is_number());
            CHECK(p["relmse"].is_number());
            CHECK(p["mape"].is_number());
            CHECK(p["rays"]["camera"] == 24 * 24 * (1u << i)); // one camera ray per sample
        }
    }
    CHECK(sc["reference"]["spp"] == 32);
}

void check_table(const json& r) {
    const std::vector<std::string> labels = labels_of(r);
    const json& sc = r["scenes"][0];
    REQUIRE(sc["table"].size() == labels.size());
    for (const json& t : sc["table"]) {
        REQUIRE(t["depth_rows"].size() == 2); // --quick: D = 1, 2
        REQUIRE(t["spp_rows"].size() == 2);   // --quick: S = 1, 4
        CHECK(t["depth_rows"][1]["depth"] == 2);
        CHECK(t["depth_rows"][1]["spp"] == 2); // at the fixed spp
        CHECK(t["spp_rows"][1]["spp"] == 4);
        CHECK(t["spp_rows"][1]["depth"] == 2); // at the fixed depth
    }
}

} // namespace

TEST_CASE("bench ladder and table at a tiny size write a well-formed result and nothing else") {
    const std::string dir = tp::test::temp_dir("bench-smoke");
    const std::string out = dir + "/out";
    // vulkan stands for every mode the device offers (compute on lavapipe); without a Vulkan
    // driver it is reported as skipped and the CPU rows are checked alone.
    const auto p = bench("--ladder --table --scenes cornell --backends cpu,vulkan" +
                         dir_args(out, dir + "/cache"));
    INFO(p.out);
    REQUIRE(p.exit_code == 0);
    const json r = read_json(out + "/bench.json");
    CHECK(r["schema"] == "twinpath-bench/1");
    CHECK(r["sections"] == json::array({"ladder", "table"}));
    CHECK(contains(r["command"].get<std::string>(), "twinpath bench --quick"));
    REQUIRE(r["scenes"].size() == 1);
    REQUIRE(!labels_of(r).empty());
    CHECK(labels_of(r).front() == "cpu/embree");
    if (labels_of(r).size() == 1) WARN("no Vulkan backend here: " << r["skipped"].dump());
    check_ladder(r);
    check_table(r);
    // The result is the whole output; the lab renders it (tests/lab/).
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(out)) files.push_back(e.path().filename());
    CHECK(files == std::vector<std::string>{"bench.json"});
    CHECK(contains(p.out, "twinpath-lab markdown " + out + "/bench.json"));
}

TEST_CASE("bench names the lab tool for the peer comparisons and the markdown") {
    const std::string dir = tp::test::temp_dir("bench-moved");
    for (const auto& [args, instead] : std::vector<std::pair<std::string, std::string>>{
             {"--peer", "twinpath-lab peer"},
             {"--peer-threads 2", "twinpath-lab peer"},
             {"--blender /usr/bin/blender", "twinpath-lab peer"},
             {"--markdown " + dir + "/B.md", "twinpath-lab markdown"},
             {"--from-json " + dir + "/bench.json", "twinpath-lab markdown"}}) {
        const auto p = bench(args + dir_args(dir + "/out", dir + "/cache"));
        INFO(args << "\n" << p.out);
        CHECK(p.exit_code == 2);
        CHECK(contains(p.out, "moved to the lab tool: " + instead));
        CHECK(!fs::exists(dir + "/out"));
        CHECK(!fs::exists(dir + "/B.md"));
    }
    const auto help = run(tp::test::twinpath_bin() + " bench --help");
    CHECK(help.exit_code == 0);
    CHECK(!contains(help.out, "--peer"));
    CHECK(!contains(help.out, "--markdown"));
}

TEST_CASE("bench takes the cache directory by the one rule, and asks for one where there is none") {
    const std::string dir = tp::test::temp_dir("bench-cache-dir");
    const std::string bench_cpu = tp::test::twinpath_bin() + " bench --quick --backends cpu --out ";
    // Set but empty counts as unset (util/cache_dir.h): $XDG_CACHE_HOME/twinpath comes next.
    auto p = run("TWINPATH_CACHE= XDG_CACHE_HOME=" + shell_quote(dir + "/xdg") + " " + bench_cpu +
                 shell_quote(dir + "/a"));
    INFO(p.out);
    REQUIRE(p.exit_code == 0);
    CHECK(read_json(dir + "/a/bench.json")["settings"]["cache"] == dir + "/xdg/twinpath");
    CHECK(fs::exists(dir + "/xdg/twinpath/references"));

    p = run("env -u TWINPATH_CACHE -u XDG_CACHE_HOME -u HOME " + bench_cpu +
            shell_quote(dir + "/b"));
    INFO(p.out);
    CHECK(p.exit_code == 2);
    CHECK(contains(p.out, "no cache directory for the references: give --cache DIR"));
    CHECK(!fs::exists(dir + "/b"));
}

TEST_CASE("bench reuses the cached reference and renders it again when the scene changes") {
    const std::string dir = tp::test::temp_dir("bench-cache");
    const std::string scene = dir + "/box.json", cache = dir + "/cache";
    json s = read_json(tp::test::scenes_dir() + "/cornell.json");
    std::ofstream(scene) << s.dump(2);
    const auto reference_of = [&](const std::string& out) {
        const auto p =
            bench("--backends cpu --scenes " + shell_quote(scene) + dir_args(out, cache));
        INFO(p.out);
        REQUIRE(p.exit_code == 0);
        return read_json(out + "/bench.json")["scenes"][0]["reference"];
    };
    const auto references = [&] {
        size_t n = 0;
        for ([[maybe_unused]] const auto& e : fs::directory_iterator(cache + "/references")) ++n;
        return n;
    };

    const json first = reference_of(dir + "/1");
    CHECK(first["cached"] == false);
    CHECK(fs::exists(first["file"].get<std::string>()));
    const json second = reference_of(dir + "/2");
    CHECK(second["cached"] == true);
    CHECK(second["key"] == first["key"]);
    CHECK(second["file"] == first["file"]);
    CHECK(references() == 1);

    // A different colour of one material: a different image, so a new reference.
    REQUIRE(s["materials"].is_object());
    json& material = s["materials"].begin().value();
    material["Kd"] = json::array({0.2, 0.3, 0.4});
    std::ofstream(scene) << s.dump(2);
    const json third = reference_of(dir + "/3");
    CHECK(third["cached"] == false);
    CHECK(third["key"] != first["key"]);
    CHECK(references() == 2);
}

TEST_CASE("bench finds a bundled glTF scene by its name") {
    const std::string dir = tp::test::temp_dir("bench-gltf");
    const auto p =
        bench("--backends cpu --scenes gltf_materials" + dir_args(dir + "/out", dir + "/cache"));
    INFO(p.out);
    REQUIRE(p.exit_code == 0);
    const json r = read_json(dir + "/out/bench.json");
    REQUIRE(r["scenes"].size() == 1);
    CHECK(r["scenes"][0]["name"] == "gltf_materials");
    // scenes/generate_scenes.py: 11 spheres of 32 x 16 quads less the poles' 2 x 32 triangles,
    // and four quads of 2 triangles each: the floor, the leaf, the pane and the emissive panel.
    CHECK(r["scenes"][0]["triangles"] == 11 * (2 * 32 * 16 - 2 * 32) + 4 * 2);
    CHECK(r["scenes"][0]["ladder"].size() == 1);
    CHECK(r["skipped"].empty());
}

TEST_CASE("bench says which shared asset is missing when --assets is empty") {
    const std::string dir = tp::test::temp_dir("bench-assets");
    const std::string empty = dir + "/empty-assets";
    fs::create_directories(empty);

    // Only scenes that need the assets: nothing to benchmark, a usage error.
    auto p = bench("--scenes bunny --assets " + shell_quote(empty) +
                   dir_args(dir + "/a", dir + "/cache"));
    INFO(p.out);
    CHECK(p.exit_code == 2);
    CHECK(contains(p.out, "scene 'bunny' needs bunny/stanford-bunny.obj from the shared test "
                          "meshes, which is not in '" +
                              empty + "' (give --assets DIR"));
    CHECK(!fs::exists(dir + "/a"));

    // With a scene that can run: it runs, the other is reported as skipped.
    p = bench("--backends cpu --scenes cornell,monkeys --assets " + shell_quote(empty) +
              dir_args(dir + "/b", dir + "/cache"));
    INFO(p.out);
    REQUIRE(p.exit_code == 0);
    const json r = read_json(dir + "/b/bench.json");
    CHECK(r["scenes"].size() == 1);
    const json s = skipped_entry(r, "monkeys");
    REQUIRE(!s.is_null());
    CHECK(contains(s["reason"].get<std::string>(), "suzanne/suzanne.obj"));
}

TEST_CASE("bench rejects bad options with exit code 2 and writes nothing") {
    const std::string dir = tp::test::temp_dir("bench-bad");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"--backends cpu,metal", "unknown backend 'metal'"},
        {"--scenes no_such_scene", "'no_such_scene' is neither a benchmark scene"},
        {"--max-spp 1", "--max-spp"},
        {"--ref-spp 2", "--ref-spp (2) must be at least --max-spp (4)"},
        {"--seed 2120155137", "is the references' seed"},
        {"--table --table-depths 0", "--table-depths: depths start at 1"},
        {"--width 0", "--width"},
        {"--no-such-option", "--no-such-option"},
    };
    for (const auto& [args, message] : cases) {
        const std::string out = dir + "/out";
        const auto p = bench(args + dir_args(out, dir + "/cache"));
        INFO(args << "\n" << p.out);
        CHECK(p.exit_code == 2);
        CHECK(contains(p.out, message));
        CHECK(!fs::exists(out));
    }
}
