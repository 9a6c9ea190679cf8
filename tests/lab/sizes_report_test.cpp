// The report of `twinpath bench --sizes` (tools/lab/sizes_report.h): the ratios, the table and
// the plot from a synthetic result whose numbers are known, and a tiny real run rendered by
// `twinpath-lab markdown`, again from its JSON alone.
#include "file_readers.h"
#include "support/test_paths.h"
#include "tools/lab/sizes_report.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using nlohmann::json;
using tp::bench::ImageSize;
using tp::test::read_file;
using tp::test::read_json;
using tp::test::shell_quote;

namespace {

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

const std::vector<std::string> kSizes = {"64x64",     "128x128",   "256x256",  "512x512",
                                         "1024x1024", "1920x1080", "3840x2160"};

// A run as run_sizes writes it, with the given rates at the first rates.size() sizes of kSizes.
json synthetic_run(const std::string& backend, const std::string& mode, const std::string& timer,
                   const std::vector<double>& rates) {
    json run = {{"backend", backend}, {"mode", mode}, {"device", "test device"},
                {"timer", timer},     {"rounds", 2},  {"points", json::array()}};
    for (size_t i = 0; i < rates.size(); ++i) {
        const ImageSize s = tp::bench::parse_image_size(kSizes[i]);
        run["points"].push_back({{"width", s.width},
                                 {"height", s.height},
                                 {"pixels", s.pixels()},
                                 {"spp", 1024 >> i},
                                 {"wall_s", 0.5},
                                 {"gpu_s", timer == "gpu" ? json(0.45) : json(nullptr)},
                                 {"samples", s.pixels() * (1024 >> i)},
                                 {"rays", {{"camera", 1}, {"extension", 2}, {"shadow", 3}}},
                                 {"mrays_s", rates[i]},
                                 {"rounds_mrays_s", {rates[i], rates[i] / 2}}});
    }
    return run;
}

json synthetic_scene(const std::string& name, json runs) {
    return {{"name", name},
            {"triangles", 1000},
            {"unique_triangles", 1000},
            {"max_depth", 8},
            {"sizes", std::move(runs)}};
}

// A result of `bench --sizes` at the default sizes: bunny on compute and pipeline (the latter
// without 3840x2160), cornell on compute and the CPU. The 256x256 and 1920x1080 rates are of
// the order of the H200's (BENCHMARKS.md, `h200-sizes`).
json synthetic_result() {
    json r;
    r["schema"] = "twinpath-bench/1";
    r["sections"] = {"sizes"};
    r["settings"] = {{"width", 256},
                     {"height", 256},
                     {"seed", 1},
                     {"sizes", {{"list", kSizes}, {"time_s", 0.5}, {"rounds", 2}}}};
    r["scenes"] = json::array(
        {synthetic_scene(
             "bunny",
             {synthetic_run("vulkan", "compute", "gpu", {40, 120, 314, 900, 2500, 3408, 3500}),
              synthetic_run("vulkan", "pipeline", "gpu", {60, 200, 576, 1500, 2900, 3206})}),
         synthetic_scene(
             "cornell",
             {synthetic_run("vulkan", "compute", "gpu", {100, 400, 1454, 3000, 4000, 4328, 4400}),
              synthetic_run("cpu", "embree", "wall", {5, 6, 6.5, 7, 7, 7, 7})})});
    return r;
}

// The vertices of the polyline titled `label`.
std::vector<std::pair<double, double>> polyline(const std::string& svg, const std::string& label) {
    const std::regex re("points=\"([^\"]*)\"><title>" + label + "</title>");
    std::smatch m;
    REQUIRE(std::regex_search(svg, m, re));
    std::vector<std::pair<double, double>> pts;
    std::istringstream in(m[1].str());
    std::string xy;
    while (in >> xy) {
        const size_t comma = xy.find(',');
        pts.emplace_back(std::stod(xy.substr(0, comma)), std::stod(xy.substr(comma + 1)));
    }
    return pts;
}

} // namespace

TEST_CASE("sizes' rates are divided by 1920x1080's, else by the largest size's", "[sizes]") {
    using tp::bench::parse_image_sizes;
    using tp::lab::ratio_base;
    CHECK(ratio_base(parse_image_sizes(kSizes)) == ImageSize{1920, 1080});
    CHECK(ratio_base(parse_image_sizes({"64", "256", "512x64"})) == ImageSize{256, 256});

    const json r = synthetic_result();
    const json& compute = r["scenes"][0]["sizes"][0];
    const std::vector<json> ratios = tp::lab::rate_ratios(compute, {1920, 1080});
    REQUIRE(ratios.size() == 7);
    for (size_t i = 0; i < 7; ++i)
        CHECK(ratios[i].get<double>() ==
              Approx(compute["points"][i]["mrays_s"].get<double>() / 3408));
    CHECK(ratios[5].get<double>() == 1.0);
    // No point at the base: no ratios, rather than ratios to something else.
    for (const json& q : tp::lab::rate_ratios(r["scenes"][0]["sizes"][1], {3840, 2160}))
        CHECK(q.is_null());
}

TEST_CASE("the sizes table gives each rate, its ratio to 1920x1080 and its spp", "[sizes]") {
    const std::string md = tp::lab::sizes_section(synthetic_result(), "results");
    INFO(md);
    CHECK(contains(md, "### Rays per second against image size"));
    CHECK(contains(md, "at least 0.5 s"));
    CHECK(contains(md, "best of 2 rounds"));
    // The summary at the run's own size (256x256) against 1920x1080.
    CHECK(contains(md, "| scene | vulkan/compute | vulkan/pipeline | cpu/embree |"));
    CHECK(contains(md, "| bunny | 314 / 3408 = 0.09 | 576 / 3206 = 0.18 | – |"));
    CHECK(contains(md, "| cornell | 1454 / 4328 = 0.34 | – | 6.5 / 7 = 0.93 |"));
    // Per scene: sizes as columns; rate, ratio and spp rows per backend/mode.
    CHECK(contains(md, "**bunny**: 1000 triangles (1000 unique); max depth 8"));
    CHECK(contains(md, "| backend/mode | time | | 64×64 | 128×128 | 256×256 | 512×512 | "
                       "1024×1024 | 1920×1080 | 3840×2160 |"));
    CHECK(contains(md, "| vulkan/compute | GPU time | Mrays/s | 40 | 120 | 314 | 900 | 2500 | "
                       "3408 | 3500 |\n"
                       "| | | × 1920×1080 | 0.01 | 0.04 | 0.09 | 0.26 | 0.73 | 1.00 | 1.03 |\n"
                       "| | | spp | 1024 | 512 | 256 | 128 | 64 | 32 | 16 |\n"));
    // A size the backend did not measure is a dash, not a number.
    CHECK(contains(md, "| vulkan/pipeline | GPU time | Mrays/s | 60 | 200 | 576 | 1500 | 2900 | "
                       "3206 | – |"));
    CHECK(contains(md, "| cpu/embree | wall time | Mrays/s | 5 | 6 | 6.5 | 7 | 7 | 7 | 7 |"));

    // No summary when the run's own size is not measured.
    json r = synthetic_result();
    r["settings"]["width"] = 300;
    CHECK(!contains(tp::lab::sizes_section(r, "."), " = 0.09 |"));
}

TEST_CASE("the sizes plot draws Mrays/s linearly over log pixels, a line per backend/mode",
          "[sizes]") {
    const json r = synthetic_result();
    const tp::lab::LinePlot plot = tp::lab::sizes_plot(r["scenes"][0]);
    REQUIRE(plot.series.size() == 2);
    CHECK(plot.series[0].label == "vulkan/compute (GPU)");
    CHECK(plot.series[1].points.size() == 6);
    CHECK(plot.series[0].points[2] == std::pair<double, double>(65536, 314));
    REQUIRE(plot.x_ticks.size() == 7);
    CHECK(plot.x_ticks[5] == std::pair<double, std::string>(2073600, "1920×1080"));

    const std::string svg = tp::lab::svg_line_plot(plot);
    const auto elements = tp::test::xml_element_counts(svg);
    CHECK(elements.at("polyline") == 2);
    CHECK(elements.at("circle") == 13); // a marker per point
    CHECK(contains(svg, ">1920×1080</text>"));
    // x is log10(pixels) and y is Mrays/s, each an affine map to the page, so ratios of
    // differences are preserved. The tolerance covers the coordinates' 0.1-unit rounding over
    // differences of tens to hundreds of units.
    const auto pts = polyline(svg, "vulkan/compute \\(GPU\\)");
    REQUIRE(pts.size() == 7);
    const std::vector<double> pixels = {4096, 16384, 65536, 262144, 1048576, 2073600, 8294400};
    const std::vector<double> rates = {40, 120, 314, 900, 2500, 3408, 3500};
    for (size_t i = 1; i + 1 < 7; ++i) {
        CHECK(
            (pts[i].first - pts[0].first) / (pts[6].first - pts[0].first) ==
            Approx(std::log(pixels[i] / pixels[0]) / std::log(pixels[6] / pixels[0])).margin(5e-3));
        CHECK((pts[i].second - pts[0].second) / (pts[6].second - pts[0].second) ==
              Approx((rates[i] - rates[0]) / (rates[6] - rates[0])).margin(5e-3));
    }
    CHECK(pts[6].second < pts[0].second); // higher rates are drawn higher (smaller SVG y)
}

TEST_CASE("lab markdown renders a --sizes result as CSV, plot and table, again from its JSON",
          "[lab][sizes]") {
    const std::string dir = tp::test::temp_dir("lab-sizes");
    const std::string out = dir + "/out";
    // --width 4 --height 4: the run's own size is measured, so the summary against the largest
    // size (8x8, no 1920x1080 here) is written.
    const auto p = tp::test::run(tp::test::twinpath(
        "bench --quick --sizes --scenes cornell --backends cpu,vulkan --sizes-list 8,4x4 "
        "--sizes-time 0.01 --width 4 --height 4 --out " +
        shell_quote(out) + " --cache " + shell_quote(dir + "/cache")));
    INFO(p.out);
    REQUIRE(p.exit_code == 0);
    const auto m =
        tp::test::run(tp::test::twinpath_lab("markdown " + shell_quote(out + "/bench.json")));
    INFO(m.out);
    REQUIRE(m.exit_code == 0);
    const json r = read_json(out + "/bench.json");
    const json& runs = r["scenes"][0]["sizes"];
    size_t points = 0;
    for (const json& run : runs) points += run["points"].size();

    const tp::test::Csv csv = tp::test::read_csv(out + "/sizes.csv");
    CHECK(csv.rows.size() == points);
    for (const auto& row : csv.rows) {
        CHECK(row.at("base") == "8x8");
        if (row.at("width") == "8") CHECK(row.at("ratio_to_base") == "1");
    }
    const std::string svg = read_file(out + "/plots/sizes/cornell.svg");
    CHECK(tp::test::xml_element_counts(svg).at("polyline") == int(runs.size()));
    const std::string md = read_file(out + "/bench.md");
    CHECK(contains(md, "4×4 against 8×8"));
    CHECK(contains(md, "| cpu/embree | wall time | Mrays/s |"));
    CHECK(contains(md, "[plot](./plots/sizes/cornell.svg)"));

    // Brought back from another machine: only bench.json travels; the same files again.
    const std::string back = dir + "/back";
    fs::create_directories(back);
    fs::copy_file(out + "/bench.json", back + "/bench.json");
    const auto q =
        tp::test::run(tp::test::twinpath_lab("markdown " + shell_quote(back + "/bench.json") +
                                             " --markdown " + shell_quote(dir + "/BENCHMARKS.md")));
    INFO(q.out);
    REQUIRE(q.exit_code == 0);
    CHECK(read_file(back + "/sizes.csv") == read_file(out + "/sizes.csv"));
    CHECK(read_file(back + "/plots/sizes/cornell.svg") == svg);
    CHECK(read_file(back + "/bench.md") == md);
    CHECK(contains(read_file(dir + "/BENCHMARKS.md"), "(back/plots/sizes/cornell.svg)"));
}
