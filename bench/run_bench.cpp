// twinpath bench: the project's performance truth (issue 5). For each scene and each backend
// and mode it measures, in sections chosen on the command line:
//   --ladder  error against time: relMSE/MAPE against a cached CPU reference at 1, 2, 4, ...
//             spp, efficiency, rays/s by kind, time to reach relMSE 1e-2 and 1e-3 (default);
//   --table   rays/s and time over depth and spp (the seed thesis's Table 5.3);
//   --peer    time per spp next to Embree's path tracer tutorial, at 1 and 2 threads (issue 2), and
//             time to error next to Cycles (issue 36);
//   --sizes   rays/s against image size (issue 34).
// Everything measured goes into one JSON result (bench.json); the CSV files, the SVG plots
// and the markdown section are generated from it, so a result brought back from another
// machine renders the same way (--from-json). A new section is a flag, a function that fills
// its part of each scene's JSON, and its rendering in bench/markdown.cpp.
#include "bench/run_bench.h"

#include "bench/backends.h"
#include "bench/host_info.h"
#include "bench/ladder.h"
#include "bench/markdown.h"
#include "bench/peer.h"
#include "bench/peer_efficiency.h"
#include "bench/peer_scene.h"
#include "bench/reference.h"
#include "bench/report_files.h"
#include "bench/scene_hash.h"
#include "bench/scenes.h"
#include "bench/sizes.h"
#include "bench/specialization.h"
#include "bench/sweep.h"
#include "scene/flatten.h"
#include "util/error.h"
#include "util/output_file.h"
#include "util/progress_bar.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using nlohmann::json;

namespace tp::bench {
namespace {

// The state of one benchmark run: options, where things are, what ran and what did not.
struct BenchRun {
    BenchOptions o;
    std::string cache_dir, assets_dir;
    std::vector<Backend> backends;
    std::vector<Skip> skipped;
    bool failed = false; // a render failed at run time: exit code 3 once the files are written
    int step = 0, steps = 0;

    // "[bench 3/12] bunny vulkan/compute ladder" for the progress bar of the next step.
    std::string next_label(const std::string& what) {
        return fmt::format("[bench {}/{}] {}", ++step, steps, what);
    }
};

void validate(const BenchOptions& o) {
    if (o.max_spp < 2) input_error("--max-spp: the ladder needs at least 2 spp, got {}", o.max_spp);
    if (o.ref_spp < o.max_spp)
        input_error("--ref-spp ({}) must be at least --max-spp ({}): the reference must be less "
                    "noisy than what it judges",
                    o.ref_spp, o.max_spp);
    if (o.seed == kReferenceSeed)
        input_error("--seed {} is the references' seed; choose another so that the measured "
                    "renders are independent of their reference",
                    o.seed);
    if (o.table_depths.empty() || o.table_spp.empty())
        input_error("--table-depths and --table-spp must not be empty");
    for (uint32_t v : o.table_depths)
        if (v < 1) input_error("--table-depths: depths start at 1, got {}", v);
    for (uint32_t v : o.table_spp)
        if (v < 1) input_error("--table-spp: sample counts start at 1, got {}", v);
    if (o.peer_spp < 2) input_error("--peer-spp must be at least 2, got {}", o.peer_spp);
    if (o.peer_threads.empty()) input_error("--peer-threads must not be empty");
    if (o.pipeline_stats && !o.specialization)
        input_error("--pipeline-stats goes with --specialization (the statistics of both "
                    "variants' pipelines)");
    if (o.scenes.empty()) input_error("--scenes must not be empty");
    parse_image_sizes(o.sizes_list);
    if (!(o.sizes_time_s > 0) || !std::isfinite(o.sizes_time_s))
        input_error("--sizes-time must be a positive number of seconds, got {}", o.sizes_time_s);
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

FlatScene flatten_for_bench(Scene scene, const BenchOptions& o) {
    SceneOverrides ov;
    ov.width = o.width;
    ov.height = o.height;
    ov.max_depth = o.max_depth;
    apply_overrides(scene, ov);
    return flatten(scene);
}

// Records what was left out and why; it is said now on stderr and later in the report.
void skip(BenchRun& run, const std::string& what, const std::string& reason) {
    fmt::print(stderr, "twinpath: bench: skipping {}: {}\n", what, reason);
    run.skipped.push_back({what, reason});
}

// Runs `f` for one backend; a run-time failure (device lost, out of memory) is recorded and
// the benchmark goes on with the next backend.
template <typename F>
void guarded(BenchRun& run, const std::string& what, F&& f) {
    try {
        f();
    } catch (const RuntimeError& e) {
        skip(run, what, fmt::format("failed: {}", e.what()));
        run.failed = true;
    }
}

void ladder(BenchRun& run, const std::string& name, const FlatScene& flat, json& sj) {
    ProgressBar ref_bar(run.next_label(fmt::format("{} reference ({} spp)", name, run.o.ref_spp)));
    const Reference ref =
        reference_for(flat, name, run.o.ref_spp, run.cache_dir, ref_bar.callback());
    sj["reference"] = {{"spp", ref.spp}, {"seed", kReferenceSeed}, {"file", ref.file},
                       {"key", ref.key}, {"cached", ref.cached},   {"render_s", ref.render_s}};
    sj["ladder"] = json::array();
    for (const Backend& b : run.backends)
        for (const std::string& sampler : run.o.samplers) {
            const std::string what = fmt::format("{} {} {} ladder", name, b.label(), sampler);
            guarded(run, what, [&] {
                ProgressBar bar(run.next_label(what));
                const LadderRun lr = run_ladder(flat, b, sampler, ref, run.o, bar.callback());
                sj["ladder"].push_back(ladder_json(lr));
                const LadderPoint& p = lr.points.back();
                fmt::print("bench: {}: {} spp in {:.3g} s, relMSE {:.3g}\n", what, p.spp, p.wall_s,
                           p.excess);
            });
        }
}

void table(BenchRun& run, const std::string& name, const FlatScene& flat, json& sj) {
    sj["table"] = json::array();
    for (const Backend& b : run.backends) {
        const std::string what = fmt::format("{} {} table", name, b.label());
        guarded(run, what, [&] {
            ProgressBar bar(run.next_label(what));
            sj["table"].push_back(sweep_json(run_sweep(flat, b, run.o, bar.callback())));
            fmt::print("bench: {}: done\n", what);
        });
    }
}

// --specialization (bench/specialization.h): scene-specialized against all-features loops.
void specialization(BenchRun& run, const std::string& name, const FlatScene& flat, json& sj) {
    sj["specialization"] = json::array();
    for (const Backend& b : run.backends) {
        const std::string what = fmt::format("{} {} specialization", name, b.label());
        guarded(run, what, [&] {
            ProgressBar bar(run.next_label(what));
            const json row = run_specialization(flat, b, run.o, bar.callback());
            sj["specialization"].push_back(row);
            fmt::print("bench: {}: all/specialized = {:.3f}\n", what, row["ratio"].get<double>());
        });
    }
}

// --sizes (bench/sizes.h): rays/s against image size; the scene is flattened at each size once.
void sizes(BenchRun& run, const std::string& name, const Scene& scene, json& sj) {
    const std::vector<ImageSize> list = parse_image_sizes(run.o.sizes_list);
    std::vector<FlatScene> flats;
    for (const ImageSize& size : list) {
        BenchOptions at = run.o;
        at.width = size.width;
        at.height = size.height;
        flats.push_back(flatten_for_bench(scene, at));
        flats.back().name = name;
    }
    sj["sizes"] = json::array();
    for (const Backend& b : run.backends) {
        const std::string what = fmt::format("{} {} sizes", name, b.label());
        guarded(run, what, [&] {
            ProgressBar bar(run.next_label(what));
            const json row = run_sizes(flats, list, b, run.o, bar.callback());
            sj["sizes"].push_back(row);
            std::string rates;
            for (const json& p : row["points"])
                rates += fmt::format(" {}x{}: {}", p["width"].get<int>(), p["height"].get<int>(),
                                     p["mrays_s"].is_number()
                                         ? fmt::format("{:.4g}", p["mrays_s"].get<double>())
                                         : std::string("none"));
            fmt::print("bench: {}: Mrays/s{}\n", what, rates);
        });
    }
}

// --peer: time per spp next to Embree's tutorial (bench/peer.h) on the scene's peer variant, and
// time to error next to Cycles on the scene itself (bench/peer_efficiency.h).
void peer(BenchRun& run, const std::string& name, Scene scene, const FlatScene& flat, json& sj) {
    const std::string eff = fmt::format("{} time to error", name);
    guarded(run, eff, [&] {
        ProgressBar bar(run.next_label(eff));
        sj["efficiency"] = run_efficiency(flat, name, run.o, run.cache_dir, bar.callback());
        for (const json& s : sj["efficiency"]["skipped"]) skip(run, eff, s.get<std::string>());
        fmt::print("bench: {}: done\n", eff);
    });
    const std::string what = fmt::format("{} peer", name);
    std::string reason;
    const std::vector<std::string> changes = make_peer_variant(scene, reason);
    if (!fs::exists(run.o.peer_binary))
        reason = fmt::format("Embree's path tracer tutorial is not at {} (Debian package "
                             "embree-tools; --peer-binary PATH)",
                             run.o.peer_binary);
    ProgressBar bar(run.next_label(what)); // draws nothing unless updated
    if (!reason.empty()) {
        skip(run, what, reason);
        return;
    }
    FlatScene variant = flatten_for_bench(std::move(scene), run.o);
    variant.params.min_depth = variant.params.max_depth; // Russian roulette off (peer.h)
    variant.name = name;
    const PeerRun pr = run_peer(variant, run.o, (fs::path(run.cache_dir) / "peer" / name).string(),
                                bar.callback());
    sj["peer"] = peer_json(pr);
    sj["peer_variant"] = changes;
    fmt::print("bench: {}: done\n", what);
}

json result_header(const BenchRun& run) {
    const BenchOptions& o = run.o;
    json sections = json::array();
    std::string names;
    for (const auto& [on, name] : {std::pair{o.ladder, "ladder"},
                                   {o.table, "table"},
                                   {o.peer, "peer"},
                                   {o.specialization, "specialization"},
                                   {o.sizes, "sizes"}})
        if (on) {
            sections.push_back(name);
            names += (names.empty() ? "" : ", ") + std::string(name);
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
    r["settings"] = {
        {"width", o.width},
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
        {"sizes", {{"list", size_list}, {"time_s", o.sizes_time_s}, {"rounds", o.sizes_rounds}}},
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

// The files derived from a result (plots, CSV, bench.md) into `dir`, and its section merged
// into `markdown` when one is given, with links relative to the markdown file.
void write_derived_files(json& r, const std::string& dir, const std::string& markdown) {
    write_plots(r, dir);
    write_csv_files(r, dir);
    write_output_file((fs::path(dir) / "bench.md").string(), markdown_section(r, "."));
    if (markdown.empty()) return;
    const fs::path md_dir = fs::absolute(markdown).parent_path();
    const std::string section = r["section"].get<std::string>();
    merge_markdown_section(
        markdown, section,
        markdown_section(r, fs::relative(fs::absolute(dir), md_dir).generic_string()));
    fmt::print("bench: section '{}' of {}\n", section, markdown);
}

void write_outputs(json& r, const BenchOptions& o) {
    fs::create_directories(o.out_dir);
    write_derived_files(r, o.out_dir, o.markdown);
    write_output_file((fs::path(o.out_dir) / "bench.json").string(), r.dump(2) + "\n");
    fmt::print("bench: wrote {}/bench.json, bench.md, CSV and plots\n", o.out_dir);
}

} // namespace

int run_bench(const BenchOptions& options) {
    BenchRun run;
    run.o = options;
    BenchOptions& o = run.o;
    if (!o.ladder && !o.table && !o.peer && !o.specialization && !o.sizes) o.ladder = true;
    validate(o);
    std::sort(o.table_spp.begin(), o.table_spp.end());
    o.table_spp.erase(std::unique(o.table_spp.begin(), o.table_spp.end()), o.table_spp.end());
    run.cache_dir = resolve_cache_dir(o.cache_dir);
    run.assets_dir = resolve_assets_dir(o.assets_dir);
    if (o.ladder || o.table || o.specialization || o.sizes) {
        std::vector<Skip> unavailable;
        run.backends = expand_backends(o.backends, o.device, o.threads, unavailable);
        for (const Skip& s : unavailable) skip(run, s.what, s.reason);
    }
    json r = result_header(run);
    const auto t0 = std::chrono::steady_clock::now();

    std::vector<std::pair<std::string, Scene>> scenes;
    for (const std::string& name : o.scenes) {
        std::string reason;
        std::optional<Scene> s = load_bench_scene(
            name, run.assets_dir, (fs::path(run.cache_dir) / "scenes").string(), reason);
        if (!s) {
            skip(run, name, reason);
            continue;
        }
        scenes.emplace_back(fs::path(name).stem().string(), std::move(*s));
    }
    if (scenes.empty()) input_error("bench: none of the scenes could be loaded (above)");
    const int per_scene = (o.ladder ? 1 + int(run.backends.size() * o.samplers.size()) : 0) +
                          (o.table ? int(run.backends.size()) : 0) + (o.peer ? 2 : 0) +
                          (o.specialization ? int(run.backends.size()) : 0) +
                          (o.sizes ? int(run.backends.size()) : 0);
    run.steps = per_scene * int(scenes.size());

    r["scenes"] = json::array();
    for (const auto& [name, scene] : scenes) {
        FlatScene flat = flatten_for_bench(scene, o);
        flat.name = name;
        json sj = {{"name", name},
                   {"source", scene.path},
                   {"width", flat.params.camera.width},
                   {"height", flat.params.camera.height},
                   {"max_depth", flat.params.max_depth},
                   {"min_depth", flat.params.min_depth},
                   {"triangles", flat.instanced_triangles},
                   {"unique_triangles", flat.unique_triangles},
                   {"lights", lights_json(flat)}};
        if (o.ladder) ladder(run, name, flat, sj);
        if (o.table) table(run, name, flat, sj);
        if (o.peer) peer(run, name, scene, flat, sj);
        if (o.specialization) specialization(run, name, flat, sj);
        if (o.sizes) sizes(run, name, scene, sj);
        r["scenes"].push_back(sj);
    }

    r["skipped"] = json::array();
    for (const Skip& s : run.skipped)
        r["skipped"].push_back({{"what", s.what}, {"reason", s.reason}});
    r["host"]["load_average_end"] = load_average();
    r["elapsed_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    write_outputs(r, o);
    return run.failed ? 3 : 0;
}

// --from-json: results of earlier runs (this machine's or another's, where only bench.json
// came back) rendered again: plots, CSV and bench.md beside each JSON file, and its section
// merged into the markdown file.
int render_results(const BenchOptions& o) {
    if (o.markdown.empty()) input_error("--from-json needs --markdown FILE to merge into");
    for (const std::string& path : o.from_json) {
        std::ifstream in(path);
        if (!in) input_error("{}: cannot open file", path);
        json r;
        try {
            r = json::parse(in);
        } catch (const json::exception& e) {
            input_error("{}: not a JSON file: {}", path, e.what());
        }
        if (r.value("schema", "") != "twinpath-bench/1")
            input_error("{}: not a twinpath bench result (schema twinpath-bench/1)", path);
        try {
            write_derived_files(r, fs::absolute(path).parent_path().string(), o.markdown);
        } catch (const json::exception& e) {
            input_error("{}: a field of the bench result is missing or malformed: {}", path,
                        e.what());
        }
    }
    return 0;
}

} // namespace tp::bench
