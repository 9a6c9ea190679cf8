// twinpath bench: the project's performance truth. For each scene and each backend and mode it
// measures, in sections chosen on the command line:
//   --ladder          error against time: relMSE/MAPE against a cached CPU reference at 1, 2,
//                     4, ... spp, efficiency, rays/s by kind, time to reach relMSE 1e-2 and 1e-3
//                     (the default; docs/bench.md, "Error, reference and efficiency");
//   --table           rays/s and time over depth and spp (the seed thesis's Table 5.3);
//   --specialization  the scene-specialized path loop against the one with every feature;
//   --sizes           rays/s against image size (and, with --scene-sizes, scene size);
//   --frame-loop      the viewer's frame loop: time per frame and its split at 1, 4, 16 spp.
// Everything measured goes into one JSON result (bench.json, run_sections.h), which is the
// record of the run; its tables, plots and markdown section are the lab's (twinpath-lab
// markdown), so a result brought back from another machine renders the same way. A new section
// is a flag, a Section here that fills its part of each scene's record, and its rendering in
// the lab (tools/lab/markdown.cpp).
#include "bench/run_bench.h"

#include "bench/frame_loop.h"
#include "bench/ladder.h"
#include "bench/reference.h"
#include "bench/run_sections.h"
#include "bench/scenes.h"
#include "bench/sizes.h"
#include "bench/specialization.h"
#include "bench/sweep.h"
#include "util/error.h"
#include "util/progress_bar.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

using nlohmann::json;

namespace tp::bench {
namespace {

int per_backend(const BenchRun& run) {
    return int(run.backends.size());
}

// A reference, then each backend with each sampler.
int ladder_steps(const BenchRun& run) {
    return 1 + int(run.backends.size() * run.o.samplers.size());
}

void ladder(BenchRun& run, const BenchScene& scene, json& sj) {
    ProgressBar ref_bar(
        run.next_label(fmt::format("{} reference ({} spp)", scene.name, run.o.ref_spp)));
    const Reference ref =
        reference_for(scene.flat, scene.name, run.o.ref_spp, run.cache_dir, ref_bar.callback());
    sj["reference"] = {{"spp", ref.spp}, {"seed", kReferenceSeed}, {"file", ref.file},
                       {"key", ref.key}, {"cached", ref.cached},   {"render_s", ref.render_s}};
    sj["ladder"] = json::array();
    for (const Backend& b : run.backends)
        for (const std::string& sampler : run.o.samplers) {
            const std::string what = fmt::format("{} {} {} ladder", scene.name, b.label(), sampler);
            run.guarded(what, [&] {
                ProgressBar bar(run.next_label(what));
                const LadderRun lr = run_ladder(scene.flat, b, sampler, ref, run.o, bar.callback());
                sj["ladder"].push_back(ladder_json(lr));
                const LadderPoint& p = lr.points.back();
                fmt::print("bench: {}: {} spp in {:.3g} s, relMSE {:.3g}\n", what, p.spp, p.wall_s,
                           p.excess);
            });
        }
}

// The thesis's Table 5.3 (bench/sweep.h).
void table(BenchRun& run, const BenchScene& scene, json& sj) {
    sj["table"] = json::array();
    for (const Backend& b : run.backends) {
        const std::string what = fmt::format("{} {} table", scene.name, b.label());
        run.guarded(what, [&] {
            ProgressBar bar(run.next_label(what));
            sj["table"].push_back(sweep_json(run_sweep(scene.flat, b, run.o, bar.callback())));
            fmt::print("bench: {}: done\n", what);
        });
    }
}

// Scene-specialized against all-features loops (bench/specialization.h).
void specialization(BenchRun& run, const BenchScene& scene, json& sj) {
    sj["specialization"] = json::array();
    for (const Backend& b : run.backends) {
        const std::string what = fmt::format("{} {} specialization", scene.name, b.label());
        run.guarded(what, [&] {
            ProgressBar bar(run.next_label(what));
            const json row = run_specialization(scene.flat, b, run.o, bar.callback());
            sj["specialization"].push_back(row);
            fmt::print("bench: {}: all/specialized = {:.3f}\n", what, row["ratio"].get<double>());
        });
    }
}

// Rays/s against image size (bench/sizes.h); the scene is flattened at each size once.
void sizes(BenchRun& run, const BenchScene& scene, json& sj) {
    const std::vector<ImageSize> list = parse_image_sizes(run.o.sizes_list);
    std::vector<FlatScene> flats;
    for (const ImageSize& size : list) {
        BenchOptions at = run.o;
        at.width = size.width;
        at.height = size.height;
        flats.push_back(flatten_for_bench(scene.scene, at));
        flats.back().name = scene.name;
    }
    sj["sizes"] = json::array();
    for (const Backend& b : run.backends) {
        const std::string what = fmt::format("{} {} sizes", scene.name, b.label());
        run.guarded(what, [&] {
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

// The viewer's frame loop (bench/frame_loop.h), on the Vulkan backends only.
void frame_loop(BenchRun& run, const BenchScene& scene, json& sj) {
    sj["frame_loop"] = json::array();
    for (const Backend& b : run.backends) {
        const std::string what = fmt::format("{} {} frame loop", scene.name, b.label());
        if (b.name != "vulkan") {
            run.skip(what, "the frame loop is the Vulkan viewer's");
            continue;
        }
        run.guarded(what, [&] {
            ProgressBar bar(run.next_label(what));
            const json row = run_frame_loop(scene.flat, b, run.o, bar.callback());
            sj["frame_loop"].push_back(row);
            std::string times;
            for (const json& p : row["points"])
                times += fmt::format(" {} spp: {:.3f} ms", p["spp_per_frame"].get<int>(),
                                     p["ms_median"].get<double>());
            fmt::print("bench: {}: median per frame{}\n", what, times);
        });
    }
}

void validate(const BenchOptions& o) {
    if (o.max_spp < 2) input_error("--max-spp: the ladder needs at least 2 spp, got {}", o.max_spp);
    if (o.ref_spp < o.max_spp)
        input_error("--ref-spp ({}) must be at least --max-spp ({}): the reference must be less "
                    "noisy than what it judges",
                    o.ref_spp, o.max_spp);
    if (o.table_depths.empty() || o.table_spp.empty())
        input_error("--table-depths and --table-spp must not be empty");
    for (uint32_t v : o.table_depths)
        if (v < 1) input_error("--table-depths: depths start at 1, got {}", v);
    for (uint32_t v : o.table_spp)
        if (v < 1) input_error("--table-spp: sample counts start at 1, got {}", v);
    if (o.pipeline_stats && !o.specialization)
        input_error("--pipeline-stats goes with --specialization (the statistics of both "
                    "variants' pipelines)");
    parse_image_sizes(o.sizes_list);
    if (o.frame_loop_spp.empty()) input_error("--frame-loop-spp must not be empty");
    for (uint32_t v : o.frame_loop_spp)
        if (v < 1) input_error("--frame-loop-spp: samples per frame start at 1, got {}", v);
    if (!(o.sizes_time_s > 0) || !std::isfinite(o.sizes_time_s))
        input_error("--sizes-time must be a positive number of seconds, got {}", o.sizes_time_s);
    if (!o.scene_sizes.empty() && !o.sizes)
        input_error("--scene-sizes goes with --sizes (the scenes' rays/s at each image size)");
    const std::vector<std::string>& families = sized_scene_families();
    if (std::find(families.begin(), families.end(), o.scene_sizes_family) == families.end())
        input_error("--scene-sizes-family: '{}' is not one of {}", o.scene_sizes_family,
                    fmt::join(families, ", "));
    for (uint32_t n : o.scene_sizes)
        if (n < 1 || n > kMaxCopies)
            input_error("--scene-sizes: copies are 1 to {}, got {}", kMaxCopies, n);
}

} // namespace

int run_bench(const BenchOptions& options) {
    validate(options);
    BenchOptions o = options;
    for (uint32_t n : o.scene_sizes)
        o.scenes.push_back(sized_scene_name({o.scene_sizes_family, n}));
    const bool none = !o.ladder && !o.table && !o.specialization && !o.sizes && !o.frame_loop;
    std::vector<Section> sections;
    if (o.ladder || none) sections.push_back({"ladder", true, ladder_steps, ladder});
    if (o.table) sections.push_back({"table", true, per_backend, table});
    if (o.specialization) sections.push_back({"specialization", true, per_backend, specialization});
    if (o.sizes) sections.push_back({"sizes", true, per_backend, sizes});
    if (o.frame_loop) sections.push_back({"frame_loop", true, per_backend, frame_loop});
    return run_sections(o, sections);
}

} // namespace tp::bench
