#include "bench/run_sections.h"

#include "bench/host_info.h"
#include "bench/reference.h"
#include "bench/renderer_version.h"
#include "bench/scenes.h"
#include "bench/sizes.h"
#include "util/clock.h"
#include "util/error.h"
#include "util/json_file.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>

namespace fs = std::filesystem;
using nlohmann::json;

namespace tp::bench {
namespace {

// What every section needs: scenes, and measured renders independent of their references.
void validate(const BenchOptions& o) {
    if (o.seed == kReferenceSeed)
        input_error("--seed {} is the references' seed; choose another so that the measured "
                    "renders are independent of their reference",
                    o.seed);
    if (o.scenes.empty()) input_error("--scenes must not be empty");
}

json lights_json(const FlatScene& f) {
    int point = 0, directional = 0, triangles = 0;
    for (const Light& l : f.lights) {
        point += l.type == LIGHT_POINT;
        directional += l.type == LIGHT_DIRECTIONAL;
        triangles += l.type == LIGHT_TRIANGLE;
    }
    const std::string env = f.params.env_light == NO_INDEX       ? "none"
                            : f.params.env_texture == NO_TEXTURE ? "constant"
                                                                 : "map";
    return {{"point", point},
            {"directional", directional},
            {"emissive_triangles", triangles},
            {"environment", env}};
}

json result_header(const BenchRun& run, const std::vector<Section>& run_sections) {
    const BenchOptions& o = run.o;
    json sections = json::array();
    std::string names;
    for (const Section& s : run_sections) {
        sections.push_back(s.name);
        names += (names.empty() ? "" : ", ") + s.name;
    }
    json backends = json::array();
    std::string labels;
    for (const Backend& b : run.backends) {
        backends.push_back({{"backend", b.name}, {"mode", b.mode}, {"device", b.device}});
        labels += (labels.empty() ? "" : ", ") + b.label();
    }
    json size_list = json::array();
    for (const ImageSize& s : parse_image_sizes(o.sizes_list)) size_list.push_back(s.name());
    json r;
    r["schema"] = "twinpath-bench/1";
    r["section"] = o.section;
    r["title"] =
        fmt::format("`{}`: {} on {}", o.section, names, labels.empty() ? "the CPU" : labels);
    r["command"] = o.command;
    r["twinpath_version"] = TWINPATH_VERSION;
    r["renderer_version"] = renderer_version();
    r["started"] = utc_timestamp();
    r["host"] = {
        {"cpu", cpu_model()}, {"cores", cpu_cores()}, {"load_average_start", load_average()}};
    r["sections"] = sections;
    r["backends"] = backends;
    r["settings"] = {{"width", o.width},
                     {"height", o.height},
                     {"max_depth", o.max_depth ? json(*o.max_depth) : json(nullptr)},
                     {"max_spp", o.max_spp},
                     {"ref_spp", o.ref_spp},
                     {"seed", o.seed},
                     {"threads", o.threads},
                     {"table",
                      {{"depths", o.table_depths},
                       {"spp", o.table_spp},
                       {"fixed_spp", o.table_fixed_spp},
                       {"fixed_depth", o.table_fixed_depth}}},
                     {"spec_spp", o.spec_spp},
                     {"spec_rounds", o.spec_rounds},
                     {"pipeline_stats", o.pipeline_stats},
                     {"sizes",
                      {{"list", size_list},
                       {"time_s", o.sizes_time_s},
                       {"spp", o.sizes_spp > 0 ? json(o.sizes_spp) : json(nullptr)},
                       {"rounds", o.sizes_rounds},
                       {"scene_sizes", o.scene_sizes},
                       {"scene_sizes_family", o.scene_sizes_family}}},
                     {"frame_loop", {{"spp", o.frame_loop_spp}, {"frames", o.frame_loop_frames}}},
                     {"peer",
                      {{"spp", o.peer_spp},
                       {"threads", o.peer_threads},
                       {"binary", o.peer_binary},
                       {"budget_s", o.peer_budget_s},
                       {"blender", o.blender},
                       {"samplers", o.samplers}}},
                     {"assets", run.assets_dir},
                     {"cache", run.cache_dir}};
    return r;
}

} // namespace

std::string BenchRun::next_label(const std::string& what) {
    return fmt::format("[bench {}/{}] {}", ++step, steps, what);
}

void BenchRun::skip(const std::string& what, const std::string& reason) {
    fmt::print(stderr, "twinpath: bench: skipping {}: {}\n", what, reason);
    skipped.push_back({what, reason});
}

void BenchRun::guarded(const std::string& what, const std::function<void()>& f) {
    try {
        f();
    } catch (const RuntimeError& e) {
        skip(what, fmt::format("failed: {}", e.what()));
        failed = true;
    }
}

FlatScene flatten_for_bench(Scene scene, const BenchOptions& o) {
    SceneOverrides ov;
    ov.width = o.width;
    ov.height = o.height;
    ov.max_depth = o.max_depth;
    apply_overrides(scene, ov);
    return flatten(scene);
}

int run_sections(const BenchOptions& options, const std::vector<Section>& sections) {
    BenchRun run;
    run.o = options;
    BenchOptions& o = run.o;
    validate(o);
    std::sort(o.table_spp.begin(), o.table_spp.end());
    o.table_spp.erase(std::unique(o.table_spp.begin(), o.table_spp.end()), o.table_spp.end());
    run.cache_dir = resolve_cache_dir(o.cache_dir);
    run.assets_dir = resolve_assets_dir(o.assets_dir);
    if (std::any_of(sections.begin(), sections.end(),
                    [](const Section& s) { return s.on_backends; })) {
        std::vector<Skip> unavailable;
        run.backends = expand_backends(o.backends, o.device, o.threads, unavailable);
        for (const Skip& s : unavailable) run.skip(s.what, s.reason);
    }
    json r = result_header(run, sections);
    const auto t0 = std::chrono::steady_clock::now();

    std::vector<std::pair<std::string, Scene>> scenes;
    for (const std::string& name : o.scenes) {
        std::string reason;
        std::optional<Scene> s = load_bench_scene(
            name, run.assets_dir, (fs::path(run.cache_dir) / "scenes").string(), reason);
        if (!s) {
            run.skip(name, reason);
            continue;
        }
        scenes.emplace_back(fs::path(name).stem().string(), std::move(*s));
    }
    if (scenes.empty()) input_error("bench: none of the scenes could be loaded (above)");
    for (const Section& s : sections) run.steps += s.steps(run) * int(scenes.size());

    r["scenes"] = json::array();
    for (const auto& [name, scene] : scenes) {
        FlatScene flat = flatten_for_bench(scene, o);
        flat.name = name;
        json record = {{"name", name},
                       {"source", scene.path},
                       {"width", flat.params.camera.width},
                       {"height", flat.params.camera.height},
                       {"max_depth", flat.params.max_depth},
                       {"min_depth", flat.params.min_depth},
                       {"triangles", flat.instanced_triangles},
                       {"unique_triangles", flat.unique_triangles},
                       {"lights", lights_json(flat)}};
        for (const Section& s : sections) s.run(run, {name, scene, flat}, record);
        r["scenes"].push_back(record);
    }

    r["skipped"] = json::array();
    for (const Skip& s : run.skipped)
        r["skipped"].push_back({{"what", s.what}, {"reason", s.reason}});
    r["host"]["load_average_end"] = load_average();
    r["elapsed_s"] = seconds_since(t0);
    fs::create_directories(o.out_dir);
    const std::string file = (fs::path(o.out_dir) / "bench.json").string();
    write_json(file, r);
    fmt::print("bench: wrote {} (tables, plots and markdown: twinpath-lab markdown {})\n", file,
               file);
    return run.failed ? 3 : 0;
}

} // namespace tp::bench
