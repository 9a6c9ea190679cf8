// `twinpath bench` at a tiny size through the real command line (issue 5): every section runs
// and writes well-formed files, the reference cache is reused and keyed by the scene, missing
// assets and bad options say so clearly. Never a timing: only that times are there.
#include "bench_files.h"
#include "compare/rgb_image.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using nlohmann::json;
using tp::test::read_csv;
using tp::test::read_file;
using tp::test::read_json;
using tp::test::run;
using tp::test::shell_quote;

namespace {

const std::string kPeerBinary = "/usr/bin/pathtracer"; // Embree's tutorial (embree-tools)

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

size_t count_of(const std::string& text, const std::string& part) {
    size_t n = 0;
    for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

// The skipped entry whose `what` contains `what`, or null.
json skipped_entry(const json& result, const std::string& what) {
    for (const json& s : result["skipped"])
        if (contains(s["what"].get<std::string>(), what)) return s;
    return nullptr;
}

void check_ladder_files(const std::string& out, const json& r) {
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

    const tp::test::Csv csv = read_csv(out + "/ladder.csv");
    for (const char* column :
         {"scene", "backend", "mode", "device", "spp", "wall_s", "gpu_s", "relmse", "relmse_excess",
          "mape", "efficiency", "camera_rays", "extension_rays", "shadow_rays", "mrays_s"})
        CHECK(std::count(csv.header.begin(), csv.header.end(), column) == 1);
    CHECK(csv.rows.size() == 3 * labels.size()); // one row per ladder step and backend/mode
    for (const auto& row : csv.rows) {
        CHECK(row.at("scene") == "cornell");
        CHECK(std::find(labels.begin(), labels.end(), row.at("backend") + "/" + row.at("mode")) !=
              labels.end());
        CHECK(!row.at("wall_s").empty());
    }

    // The plot: one polyline per backend/mode, titled with its label.
    REQUIRE(sc["plot"] == "plots/cornell.svg");
    const std::string svg = read_file(out + "/plots/cornell.svg");
    const auto elements = tp::test::xml_element_counts(svg);
    CHECK(elements.at("svg") == 1);
    CHECK(elements.at("polyline") == int(labels.size()));
    for (const std::string& l : labels) CHECK(contains(svg, "<title>" + l + "</title>"));

    const std::string md = read_file(out + "/bench.md");
    CHECK(contains(md, "| backend/mode | spp | time [s] |"));
    for (const std::string& l : labels) CHECK(contains(md, "| " + l + " | 4 |"));
    CHECK(contains(md, "plots/cornell.svg)")); // the link to the plot
}

void check_table_files(const std::string& out, const json& r) {
    const std::vector<std::string> labels = labels_of(r);
    const json& sc = r["scenes"][0];
    REQUIRE(sc["table"].size() == labels.size());
    for (const json& t : sc["table"]) {
        CHECK(t["depth_rows"].size() == 2); // --quick: D = 1, 2
        CHECK(t["spp_rows"].size() == 2);   // --quick: S = 1, 4
    }
    const tp::test::Csv csv = read_csv(out + "/table.csv");
    for (const char* column : {"scene", "backend", "mode", "accel_bytes", "sweep", "depth", "spp",
                               "wall_s", "mrays_s", "secondary_rays_per_sample"})
        CHECK(std::count(csv.header.begin(), csv.header.end(), column) == 1);
    CHECK(csv.rows.size() == 4 * labels.size());
    std::multiset<std::string> sweeps;
    for (const auto& row : csv.rows)
        sweeps.insert(row.at("sweep") + row.at("depth") + "x" + row.at("spp"));
    CHECK(sweeps.count("depth1x2") == labels.size()); // the depth rows at the fixed 2 spp
    CHECK(sweeps.count("spp2x4") == labels.size());   // the spp rows at the fixed depth 2

    const std::string md = read_file(out + "/bench.md");
    CHECK(contains(md, "(thesis Table 5.3)"));
    CHECK(contains(md, "| triangles | 32 |"));
    for (const std::string& l : labels) {
        CHECK(contains(md, "#### " + l + ": depth D at S = 2 spp"));
        CHECK(contains(md, "#### " + l + ": samples S at D = 2"));
    }
}

void check_peer_files(const std::string& out, const json& r, const tp::test::ProcessResult& p) {
    const std::string md = read_file(out + "/bench.md");
    CHECK(contains(md, "### Against Embree's path tracer tutorial"));
    const tp::test::Csv csv = read_csv(out + "/peer.csv");
    for (const char* column :
         {"scene", "threads", "ours_time_per_spp_s", "peer_time_per_spp_s", "speedup"})
        CHECK(std::count(csv.header.begin(), csv.header.end(), column) == 1);
    if (fs::exists(kPeerBinary)) {
        REQUIRE(r["scenes"][0].contains("peer"));
        const json& rows = r["scenes"][0]["peer"]["rows"];
        REQUIRE(rows.size() == 2); // threads 1 and 2
        for (const json& row : rows) {
            CHECK(row["peer"]["exit_code"] == 0);
            CHECK(row["ours"]["t_1spp_s"].is_number()); // measured, whatever its value
            CHECK(row["ours"]["t_nspp_s"].is_number());
        }
        CHECK(csv.rows.size() == 2);
        CHECK(fs::exists(r["scenes"][0]["peer"]["obj"].get<std::string>()));
        // The tutorial's counted rays (peer_ray_counter.c): each sample of each pixel starts
        // with one camera ray (rtcIntersect1), and a path of at most D scattering events under
        // the peer variant's single light traces at most D + 1 extension and D + 1 shadow rays.
        const json& sc = r["scenes"][0];
        const double pixels = sc["width"].get<double>() * sc["height"].get<double>();
        const double depth = sc["max_depth"].get<double>();
        const json& counted = rows[0]["peer"]["rays_per_spp"];
        REQUIRE(counted.is_number());
        CHECK(counted.get<double>() >= pixels);
        CHECK(counted.get<double>() <= 2.0 * (depth + 1.0) * pixels);
    } else {
        WARN("no " << kPeerBinary << ": checking the 'peer absent' report instead");
        CHECK(csv.rows.empty());
        CHECK(contains(p.out, "is not at " + kPeerBinary));
        CHECK(!skipped_entry(r, "peer").is_null());
    }
}

const std::string kBlender = "/usr/bin/blender"; // Cycles' host (Debian package blender)

// Mean of channel c over the left or right half of an image.
double half_mean(const tp::RgbImage& img, int c, bool right) {
    double sum = 0;
    const int x0 = right ? img.width / 2 : 0, x1 = right ? img.width : img.width / 2;
    for (int y = 0; y < img.height; ++y)
        for (int x = x0; x < x1; ++x) sum += img.mean[c][size_t(y) * img.width + x];
    return sum / (double(img.height) * (x1 - x0));
}

void check_efficiency(const std::string& out, const json& r) {
    const json& e = r["scenes"][0]["efficiency"];
    CHECK(
        contains(read_file(out + "/bench.md"), "### Time to error against a production renderer"));
    size_t ours = 0, peers = 0;
    for (const json& row : e["rows"]) {
        INFO(row.dump());
        CHECK(row["exit_code"] == 0);
        CHECK(row["spp"].get<int>() >= 2);
        CHECK(row["relmse"].is_number()); // measured, whatever its value
        ++(row.value("peer", false) ? peers : ours);
    }
    CHECK(ours == 2); // threads 1 and 2, the random sampler
    if (!fs::exists(kBlender)) {
        WARN("no " << kBlender << ": checking the 'peer absent' report instead");
        CHECK(peers == 0);
        CHECK(contains(e["skipped"][0].get<std::string>(), "Blender is not at"));
        return;
    }
    CHECK(peers == 2);
    // The export (peer_cycles.cpp, cycles_scene.py) gives Cycles the same scene: the two
    // references agree in the red of the box's left half (the red wall) and the green of its
    // right half (the green wall), which a mirrored camera, a missing emitter or a light off by a
    // factor of pi would break. Each mean is over 288 pixels of 32 spp (Cycles: 2 x 16), whose
    // noise is a few per cent; the materials are Lambertian in both, so 10 % is noise alone.
    const json& refs = e["references"];
    const tp::RgbImage ours_ref = tp::load_rgb_image(refs["twinpath"]["files"][0]);
    tp::RgbImage peer_ref = tp::load_rgb_image(refs["peer"]["files"][0]);
    const tp::RgbImage other = tp::load_rgb_image(refs["peer"]["files"][1]);
    for (int c = 0; c < 3; ++c)
        for (size_t i = 0; i < peer_ref.pixels(); ++i)
            peer_ref.mean[c][i] = 0.5 * (peer_ref.mean[c][i] + other.mean[c][i]);
    for (const auto& [c, right] : {std::pair{0, false}, std::pair{1, true}}) {
        const double a = half_mean(ours_ref, c, right), b = half_mean(peer_ref, c, right);
        INFO("channel " << c << (right ? ", right half" : ", left half") << ": twinpath " << a
                        << ", Cycles " << b);
        CHECK(std::abs(a - b) <= 0.1 * a);
    }
}

} // namespace

TEST_CASE("bench ladder table and peer at a tiny size write well-formed files") {
    const std::string dir = tp::test::temp_dir("bench-smoke");
    const std::string out = dir + "/out";
    // vulkan stands for every mode the device offers (compute on lavapipe); without a Vulkan
    // driver it is reported as skipped and the CPU rows are checked alone.
    const auto p = bench("--ladder --table --peer --scenes cornell --backends cpu,vulkan" +
                         dir_args(out, dir + "/cache"));
    INFO(p.out);
    REQUIRE(p.exit_code == 0);
    const json r = read_json(out + "/bench.json");
    CHECK(r["schema"] == "twinpath-bench/1");
    CHECK(r["sections"] == json::array({"ladder", "table", "peer"}));
    CHECK(contains(r["command"].get<std::string>(), "twinpath bench --quick"));
    REQUIRE(r["scenes"].size() == 1);
    REQUIRE(!labels_of(r).empty());
    CHECK(labels_of(r).front() == "cpu/embree");
    if (labels_of(r).size() == 1) WARN("no Vulkan backend here: " << r["skipped"].dump());
    check_ladder_files(out, r);
    check_table_files(out, r);
    check_peer_files(out, r, p);
    check_efficiency(out, r);
}

TEST_CASE("bench says clearly when the peer is absent") {
    const std::string dir = tp::test::temp_dir("bench-no-peer");
    const std::string missing = dir + "/no/pathtracer";
    const auto p = bench("--peer --peer-binary " + shell_quote(missing) + " --blender " +
                         shell_quote(missing) + dir_args(dir + "/out", dir + "/cache"));
    INFO(p.out);
    REQUIRE(p.exit_code == 0);
    CHECK(contains(p.out,
                   "skipping cornell peer: Embree's path tracer tutorial is not at " + missing));
    const json r = read_json(dir + "/out/bench.json");
    const json s = skipped_entry(r, "peer");
    REQUIRE(!s.is_null());
    CHECK(contains(s["reason"].get<std::string>(), "embree-tools"));
    CHECK(contains(read_file(dir + "/out/bench.md"), "- cornell peer: Embree's path tracer"));
    CHECK(contains(p.out, "skipping cornell time to error: Blender is not at " + missing));
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
    // the floor and the panel of 2 triangles each.
    CHECK(r["scenes"][0]["triangles"] == 11 * (2 * 32 * 16 - 2 * 32) + 2 + 2);
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
    CHECK(contains(read_file(dir + "/b/bench.md"), "- monkeys: scene 'monkeys' needs"));
}

TEST_CASE("bench rejects bad options with exit code 2 and writes nothing") {
    const std::string dir = tp::test::temp_dir("bench-bad");
    const std::string not_json = dir + "/not.json", other_json = dir + "/other.json";
    std::ofstream(not_json) << "{ not json";
    std::ofstream(other_json) << R"({"schema": "something-else"})";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"--backends cpu,metal", "unknown backend 'metal'"},
        {"--scenes no_such_scene", "'no_such_scene' is neither a benchmark scene"},
        {"--max-spp 1", "--max-spp"},
        {"--ref-spp 2", "--ref-spp (2) must be at least --max-spp (4)"},
        {"--seed 2120155137", "is the references' seed"},
        {"--table --table-depths 0", "--table-depths: depths start at 1"},
        {"--peer --peer-spp 1", "--peer-spp must be at least 2"},
        {"--width 0", "--width"},
        {"--no-such-option", "--no-such-option"},
        {"--from-json " + dir + "/missing.json --markdown " + dir + "/B.md", "cannot open file"},
        {"--from-json " + not_json + " --markdown " + dir + "/B.md", "not a JSON file"},
        {"--from-json " + other_json + " --markdown " + dir + "/B.md",
         "not a twinpath bench result"},
        {"--from-json " + other_json, "--from-json needs --markdown"},
    };
    for (const auto& [args, message] : cases) {
        const std::string out = dir + "/out";
        const auto p = bench(args + dir_args(out, dir + "/cache"));
        INFO(args << "\n" << p.out);
        CHECK(p.exit_code == 2);
        CHECK(contains(p.out, message));
        CHECK(!fs::exists(out));
        CHECK(!fs::exists(dir + "/B.md"));
    }
}

TEST_CASE("bench sections merge into a markdown file in place and from JSON brought back") {
    const std::string dir = tp::test::temp_dir("bench-merge");
    const std::string md = dir + "/BENCHMARKS.md", out = dir + "/results/local";
    std::ofstream(md) << "# Benchmarks\n\nHand-written text.\n";
    const std::string args = "--backends cpu --section local --markdown " + shell_quote(md) +
                             dir_args(out, dir + "/cache");
    REQUIRE(bench(args).exit_code == 0);
    REQUIRE(bench(args).exit_code == 0); // the same section again: replaced, not appended

    // A result brought back from another machine: only its bench.json travels.
    const std::string gpu = dir + "/results/gpu";
    fs::create_directories(gpu);
    json r = read_json(out + "/bench.json");
    r["section"] = "gpu";
    r["title"] = "`gpu`: ladder on cpu/embree";
    std::ofstream(gpu + "/bench.json") << r.dump(2);
    for (int i = 0; i < 2; ++i) {
        const auto p = run(tp::test::twinpath_bin() + " bench --from-json " +
                           shell_quote(gpu + "/bench.json") + " --markdown " + shell_quote(md));
        INFO(p.out);
        REQUIRE(p.exit_code == 0);
    }
    for (const char* file : {"ladder.csv", "bench.md", "plots/cornell.svg"})
        CHECK(fs::exists(gpu + "/" + file));

    const std::string text = read_file(md);
    INFO(text);
    CHECK(text.rfind("# Benchmarks\n\nHand-written text.\n", 0) == 0);
    CHECK(count_of(text, "<!-- twinpath-bench:begin local -->") == 1);
    CHECK(count_of(text, "<!-- twinpath-bench:end local -->") == 1);
    CHECK(count_of(text, "<!-- twinpath-bench:begin gpu -->") == 1);
    CHECK(count_of(text, "## `local`: ladder on cpu/embree") == 1);
    CHECK(count_of(text, "## `gpu`: ladder on cpu/embree") == 1);
    CHECK(text.find("begin local") < text.find("begin gpu"));
    // Plot links are relative to the markdown file.
    CHECK(contains(text, "(results/local/plots/cornell.svg)"));
    CHECK(contains(text, "(results/gpu/plots/cornell.svg)"));
}
