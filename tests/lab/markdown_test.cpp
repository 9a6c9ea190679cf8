// `twinpath-lab markdown` on results of `twinpath bench` at a tiny size: the ladder's and the
// table's CSV, SVG plots and markdown are well-formed and say what the result holds, sections
// merge into a markdown file in place, a result brought back without its files renders the
// same way, and bad input exits 2 and writes nothing.
#include "file_readers.h"
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

// `twinpath bench` at the CI smoke size (--quick) into `out`, with its reference cache in `cache`.
void bench(const std::string& args, const std::string& out, const std::string& cache) {
    const auto p = run(tp::test::twinpath("bench --quick " + args + " --out " + shell_quote(out) +
                                          " --cache " + shell_quote(cache)));
    INFO(p.out);
    REQUIRE(p.exit_code == 0);
}

tp::test::ProcessResult lab_markdown(const std::string& args) {
    return run(tp::test::twinpath_lab("markdown " + args));
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

size_t count_of(const std::string& text, const std::string& part) {
    size_t n = 0;
    for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

std::vector<std::string> labels_of(const json& result) {
    std::vector<std::string> labels;
    for (const json& b : result["backends"])
        labels.push_back(b["backend"].get<std::string>() + "/" + b["mode"].get<std::string>());
    return labels;
}

void check_ladder_files(const std::string& out, const json& r) {
    const std::vector<std::string> labels = labels_of(r);
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
    const std::string svg = read_file(out + "/plots/cornell.svg");
    const auto elements = tp::test::xml_element_counts(svg);
    CHECK(elements.at("svg") == 1);
    CHECK(elements.at("polyline") == int(labels.size()));
    for (const std::string& l : labels) CHECK(contains(svg, "<title>" + l + "</title>"));

    const std::string md = read_file(out + "/bench.md");
    CHECK(contains(md, "| backend/mode | spp | time [s] |"));
    for (const std::string& l : labels) CHECK(contains(md, "| " + l + " | 4 |"));
    CHECK(contains(md, "(./plots/cornell.svg)")); // the link to the plot
}

void check_table_files(const std::string& out, const json& r) {
    const std::vector<std::string> labels = labels_of(r);
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

} // namespace

TEST_CASE("lab markdown renders a ladder and table result as well-formed CSV, plots and markdown",
          "[lab]") {
    const std::string dir = tp::test::temp_dir("lab-markdown");
    const std::string out = dir + "/out";
    // vulkan stands for every mode the device offers (compute on lavapipe); without a Vulkan
    // driver the CPU rows are checked alone.
    bench("--ladder --table --scenes cornell --backends cpu,vulkan", out, dir + "/cache");
    const auto p = lab_markdown(shell_quote(out + "/bench.json"));
    INFO(p.out);
    REQUIRE(p.exit_code == 0);
    const json r = read_json(out + "/bench.json");
    REQUIRE(!labels_of(r).empty());
    if (labels_of(r).size() == 1) WARN("no Vulkan backend here: " << r["skipped"].dump());
    check_ladder_files(out, r);
    check_table_files(out, r);
}

TEST_CASE("lab markdown merges sections in place, also from results brought back", "[lab]") {
    const std::string dir = tp::test::temp_dir("lab-merge");
    const std::string md = dir + "/BENCHMARKS.md", out = dir + "/results/local";
    const std::string empty = dir + "/empty-assets";
    fs::create_directories(empty);
    std::ofstream(md) << "# Benchmarks\n\nHand-written text.\n";
    // monkeys needs a shared mesh that is not in the empty assets: skipped, and said so.
    bench("--backends cpu --scenes cornell,monkeys --assets " + shell_quote(empty) +
              " --section local",
          out, dir + "/cache");
    for (int i = 0; i < 2; ++i) { // the same section again: replaced, not appended
        const auto p =
            lab_markdown(shell_quote(out + "/bench.json") + " --markdown " + shell_quote(md));
        INFO(p.out);
        REQUIRE(p.exit_code == 0);
    }
    CHECK(contains(read_file(out + "/bench.md"), "- monkeys: scene 'monkeys' needs"));

    // A result brought back from another machine: only its bench.json travels.
    const std::string gpu = dir + "/results/gpu";
    fs::create_directories(gpu);
    json r = read_json(out + "/bench.json");
    r["section"] = "gpu";
    r["title"] = "`gpu`: ladder on cpu/embree";
    std::ofstream(gpu + "/bench.json") << r.dump(2);
    for (int i = 0; i < 2; ++i) {
        const auto p =
            lab_markdown(shell_quote(gpu + "/bench.json") + " --markdown " + shell_quote(md));
        INFO(p.out);
        REQUIRE(p.exit_code == 0);
    }
    for (const char* file : {"ladder.csv", "bench.md", "plots/cornell.svg"})
        CHECK(fs::exists(gpu + "/" + file));
    CHECK(read_file(gpu + "/ladder.csv") == read_file(out + "/ladder.csv"));

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

TEST_CASE("lab markdown rejects what is not a bench result with exit code 2 and writes nothing",
          "[lab]") {
    const std::string dir = tp::test::temp_dir("lab-markdown-bad");
    const std::string not_json = dir + "/not.json", other_json = dir + "/other.json";
    const std::string md = dir + "/B.md";
    std::ofstream(not_json) << "{ not json";
    std::ofstream(other_json) << R"({"schema": "something-else"})";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {dir + "/missing.json", "cannot open file"},
        {not_json, "not a JSON file"},
        {other_json, "not a twinpath bench result"},
    };
    for (const auto& [file, message] : cases) {
        const auto p = lab_markdown(shell_quote(file) + " --markdown " + shell_quote(md));
        INFO(file << "\n" << p.out);
        CHECK(p.exit_code == 2);
        CHECK(contains(p.out, message));
        CHECK(!fs::exists(md));
        CHECK(!fs::exists(dir + "/bench.md"));
    }
    const auto none = lab_markdown("--markdown " + shell_quote(md));
    CHECK(none.exit_code == 2);
    CHECK(contains(none.out, "results"));
}
