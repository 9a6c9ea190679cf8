// What the driver says about the render pipeline (vulkan_rt/device/pipeline_report.h, docs/gpu.md):
// VK_EXT_pipeline_creation_feedback in `--stats` (`pipeline_creation`), and
// VK_KHR_pipeline_executable_properties through `--pipeline-stats` on render and on
// `bench --specialization` (and its register column in `twinpath-lab markdown`). Lavapipe (CI) has
// the first and not the second: there the second must be one note, not an error. CTest runs this
// with TWINPATH_VALIDATION=1, so a render that drew a validation message fails (exit 3) and
// `validation_messages` is checked besides.
#include "shared/features.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace tp::test {
namespace {

using nlohmann::json;

size_t count_of(const std::string& text, const std::string& part) {
    size_t n = 0;
    for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

std::string text_of(const std::string& path) {
    std::ifstream in(path);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

const std::string kNote = "does not offer VK_KHR_pipeline_executable_properties";

// A tiny compute-mode render of Cornell with the pipeline cache in `cache`; returns its
// statistics.
json render(const std::string& dir, const std::string& name, const std::string& cache,
            const std::string& extra, std::string* out = nullptr) {
    const ProcessResult r = run(fmt::format(
        "TWINPATH_CACHE={} {}", shell_quote(cache),
        twinpath(fmt::format("render cornell --backend vulkan --vk-mode compute --width 8 "
                             "--height 8 --spp 1 -o {} --stats {} {}",
                             shell_quote(dir + "/" + name + ".exr"),
                             shell_quote(dir + "/" + name + ".json"), extra))));
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    if (out) *out = r.out;
    const json s = read_json(dir + "/" + name + ".json");
    CHECK(s["extra"]["validation_messages"] == "0");
    return s;
}

bool lavapipe(const json& stats) {
    return stats["device"].get<std::string>().find("llvmpipe") != std::string::npos;
}

} // namespace

TEST_CASE("creation feedback: the driver's word on the pipeline cache is in --stats",
          "[gpu][pipeline-report]") {
    const std::string dir = temp_dir("creation-feedback");
    const std::string cache = dir + "/cache";
    const json first = render(dir, "first", cache, "");
    const json second = render(dir, "second", cache, "");
    CHECK(first["extra"]["pipeline_cache"] == "miss");
    CHECK(second["extra"]["pipeline_cache"] == "hit");
    for (const json* s : {&first, &second}) {
        const json& c = (*s)["pipeline_creation"];
        INFO(c.dump(2));
        REQUIRE(c["feedback"] == true);
        CHECK(c["valid"] == true);
        CHECK(c["duration_ms"].get<double>() >= 0.0);
        REQUIRE(c["stages"].size() == 1);
        CHECK(c["stages"][0]["stage"] == "compute");
    }
    // A fresh cache directory cannot spare the compilation.
    CHECK(first["pipeline_creation"]["cache_hit"] == false);
    if (lavapipe(second)) {
        // Lavapipe (Mesa 22.3) stores only the cache's header (docs/gpu.md) and never sets
        // APPLICATION_PIPELINE_CACHE_HIT: it compiles again, and says so.
        CHECK(second["pipeline_creation"]["cache_hit"] == false);
    } else {
        // A driver that keeps compiled pipelines in the application's cache (NVIDIA).
        CHECK(second["pipeline_creation"]["cache_hit"] == true);
    }
    // The CPU backend has no pipeline.
    const ProcessResult cpu =
        run(twinpath(fmt::format("render cornell --width 4 --height 4 --spp 1 -o {} --stats {}",
                                 shell_quote(dir + "/cpu.exr"), shell_quote(dir + "/cpu.json"))));
    REQUIRE(cpu.exit_code == 0);
    CHECK_FALSE(read_json(dir + "/cpu.json").contains("pipeline_creation"));
}

TEST_CASE("render --pipeline-stats writes the executables or says in one line why not",
          "[gpu][pipeline-report]") {
    const std::string dir = temp_dir("pipeline-stats");
    const std::string file = dir + "/pipeline.json";
    std::string out;
    const json s = render(dir, "render", dir + "/cache",
                          "--features all --pipeline-stats " + shell_quote(file), &out);
    const json p = read_json(file);
    INFO(out << "\n" << p.dump(2));
    CHECK(p["schema"] == "twinpath-pipeline-stats/1");
    CHECK(p["device"] == s["device"]);
    REQUIRE(p["pipelines"].size() == 1);
    const json& pl = p["pipelines"][0];
    CHECK(pl["mode"] == "compute");
    CHECK(pl["variant"] == "all");
    CHECK(pl["feature_mask"] == tp::FEATURES_ALL);
    CHECK(pl["creation"] == s["pipeline_creation"]);
    if (pl["statistics_available"] == true) {
        CHECK(count_of(out, kNote) == 0);
        REQUIRE(!pl["executables"].empty());
        for (const json& e : pl["executables"]) {
            CHECK(!e["stages"].empty());
            CHECK(e["name"].is_string());
            CHECK(e["subgroup_size"].is_number());
            for (const json& st : e["statistics"]) {
                CHECK(st["name"].is_string());
                CHECK(st["description"].is_string());
                CHECK(st.contains("value"));
            }
        }
    } else {
        CHECK(count_of(out, kNote) == 1);
        CHECK(out.find("error") == std::string::npos);
        CHECK(pl["executables"].empty());
        CHECK(pl["statistics_note"].get<std::string>().find(kNote) != std::string::npos);
    }

    // Asked of the CPU backend: bad usage, and no file.
    const ProcessResult cpu = run(twinpath(
        fmt::format("render cornell --width 4 --height 4 --spp 1 -o {} --pipeline-stats {}",
                    shell_quote(dir + "/cpu.exr"), shell_quote(dir + "/cpu_pipeline.json"))));
    CHECK(cpu.exit_code == 2);
    CHECK(cpu.out.find("--backend vulkan") != std::string::npos);
}

TEST_CASE("bench --specialization --pipeline-stats: both variants' pipelines per row, and a "
          "register column where the driver counts registers",
          "[gpu][pipeline-report]") {
    const std::string dir = temp_dir("bench-pipeline-stats");
    const std::string out = dir + "/out";
    const ProcessResult r = run(twinpath(
        fmt::format("bench --quick --specialization --pipeline-stats --spec-spp 1 --spec-rounds 1 "
                    "--backends vulkan:compute --out {} --cache {}",
                    shell_quote(out), shell_quote(dir + "/cache"))));
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    json result = read_json(out + "/bench.json");
    CHECK(result["settings"]["pipeline_stats"] == true);
    json& row = result["scenes"][0]["specialization"][0];
    CHECK(row["all"]["pipeline"]["variant"] == "all");
    CHECK(row["all"]["pipeline"]["feature_mask"] == tp::FEATURES_ALL);
    CHECK(row["specialized"]["pipeline"]["variant"] == "scene");
    CHECK(row["specialized"]["pipeline"]["feature_mask"] == row["feature_mask"]);
    if (row["specialized"]["pipeline"]["statistics_available"] == false) {
        CHECK(count_of(r.out, kNote) == 1); // once for the device, not per render
        // No register counts, no register column in the lab's markdown of the result.
        const ProcessResult m = run(twinpath_lab("markdown " + shell_quote(out + "/bench.json")));
        INFO(m.out);
        REQUIRE(m.exit_code == 0);
        CHECK(text_of(out + "/bench.md").find("registers |") == std::string::npos);
    }

    // The markdown from a result whose driver counts registers (as NVIDIA's "Register Count"),
    // brought back as JSON: a column with all → specialized.
    const auto executables = [](int registers) {
        return json::array({{{"stages", {"compute"}},
                             {"name", "main"},
                             {"description", "compute shader"},
                             {"subgroup_size", 32},
                             {"statistics",
                              {{{"name", "Binary Size"},
                                {"description", "bytes"},
                                {"format", "uint64"},
                                {"value", 4096}},
                               {{"name", "Register Count"},
                                {"description", "registers per thread"},
                                {"format", "uint64"},
                                {"value", registers}}}}}});
    };
    row["all"]["pipeline"]["executables"] = executables(128);
    row["specialized"]["pipeline"]["executables"] = executables(96);
    const std::string gpu = dir + "/gpu";
    std::filesystem::create_directories(gpu);
    std::ofstream(gpu + "/bench.json") << result.dump(2);
    const std::string md = dir + "/BENCHMARKS.md";
    const ProcessResult m = run(twinpath_lab("markdown " + shell_quote(gpu + "/bench.json") +
                                             " --markdown " + shell_quote(md)));
    INFO(m.out);
    REQUIRE(m.exit_code == 0);
    const std::string text = text_of(md);
    INFO(text);
    CHECK(text.find("| ratio | registers |") != std::string::npos);
    CHECK(text.find("| 128 → 96 |") != std::string::npos);
}

} // namespace tp::test
