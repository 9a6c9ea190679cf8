// twinpath bench's command line: the options of bench/options.h, and --stress for the stress
// suite (stress/stress.h). The measuring is bench/run_bench.h's; the peer comparisons and the
// BENCHMARKS.md writers are the lab tool's (tools/lab).
#include "commands.h"

#include "bench/host_info.h"
#include "bench/image_options.h"
#include "bench/options.h"
#include "bench/quick.h"
#include "bench/run_bench.h"
#include "bench/scenes.h"
#include "stress/stress.h"
#include "util/error.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace tp {
namespace {

using namespace bench;

// The flags and options of the peer comparisons and the BENCHMARKS.md writers, which are the
// lab tool's now (docs/bench.md, "The lab"): out of the help, each names what to run instead.
struct MovedOption {
    const char* name;
    bool flag;
    const char* instead;
};
constexpr const char* kLabPeer = "twinpath-lab peer";
constexpr const char* kLabMarkdown = "twinpath-lab markdown OUT/bench.json --markdown FILE";
constexpr MovedOption kMovedOptions[] = {
    {"--peer", true, kLabPeer},          {"--peer-spp", false, kLabPeer},
    {"--peer-threads", false, kLabPeer}, {"--peer-binary", false, kLabPeer},
    {"--peer-budget", false, kLabPeer},  {"--blender", false, kLabPeer},
    {"--markdown", false, kLabMarkdown}, {"--from-json", false, kLabMarkdown}};

void add_moved_options(CLI::App* c, std::vector<std::string>& values) {
    for (const MovedOption& m : kMovedOptions)
        (m.flag ? c->add_flag(m.name) : c->add_option(m.name, values))->group("");
}

void refuse_moved_options(const CLI::App& c) {
    for (const MovedOption& m : kMovedOptions)
        if (c.count(m.name))
            input_error("bench {} moved to the lab tool: {} (docs/bench.md, \"The lab\")", m.name,
                        m.instead);
}

} // namespace

Subcommand add_bench_command(CLI::App& app) {
    auto options = std::make_shared<BenchOptions>();
    BenchOptions& o = *options;
    o.scenes.clear();
    for (const CatalogueEntry& e : scene_catalogue()) o.scenes.push_back(e.name);
    o.backends = {"cpu", "vulkan"};
    o.section = "local";
    CLI::App* c = app.add_subcommand("bench", "Benchmark run time against error (BENCHMARKS.md)");
    c->add_flag("--ladder", o.ladder, "Error against time for each backend/mode (the default)");
    c->add_flag("--table", o.table, "Rays/s and time over depth and spp (thesis Table 5.3)");
    c->add_flag("--specialization", o.specialization,
                "Time per spp: scene-specialized path loop against --features all");
    c->add_option("--spec-spp", o.spec_spp, "Specialization: spp of each timed render")
        ->check(CLI::Range(1u, 1u << 20))
        ->capture_default_str();
    c->add_option("--spec-rounds", o.spec_rounds, "Specialization: alternating rounds per variant")
        ->check(CLI::Range(1u, 100u))
        ->capture_default_str();
    c->add_flag("--pipeline-stats", o.pipeline_stats,
                "Specialization: the Vulkan driver's statistics of both variants' pipelines "
                "(register counts, ...; docs/gpu.md)");
    c->add_flag("--sizes", o.sizes,
                "Rays/s against image size, per backend/mode (table and plot; docs/bench.md)");
    c->add_option("--sizes-list", o.sizes_list,
                  "Sizes: image sizes WxH (or N for NxN); rates are also given over 1920x1080's "
                  "(else the largest's)")
        ->delimiter(',')
        ->capture_default_str();
    c->add_option("--sizes-time", o.sizes_time_s,
                  "Sizes: each point renders at least this many seconds (whole passes)")
        ->check(CLI::Range(1e-3, 3600.0))
        ->capture_default_str();
    c->add_option("--sizes-rounds", o.sizes_rounds, "Sizes: best of this many rounds")
        ->check(CLI::Range(1u, 100u))
        ->capture_default_str();
    c->add_option("--sizes-spp", o.sizes_spp,
                  "Sizes: each point renders exactly this many spp instead of --sizes-time")
        ->check(CLI::Range(1u, 1u << 24));
    c->add_option("--scene-sizes", o.scene_sizes,
                  "Sizes: also the scenes of N distinct copies of --scene-sizes-family's mesh on "
                  "a floor, for each N (e.g. 1,10,30; alone unless --scenes is given)")
        ->delimiter(',');
    c->add_option("--scene-sizes-family", o.scene_sizes_family,
                  "Sizes: the mesh of --scene-sizes: buddhas (112k triangles) or suzannes (968)")
        ->capture_default_str();
    c->add_flag("--frame-loop", o.frame_loop,
                "The viewer's frame loop per Vulkan backend/mode: time per frame and its split "
                "(trace, resolve, display, host) at --frame-loop-spp samples per frame");
    c->add_option("--frame-loop-spp", o.frame_loop_spp, "Frame loop: samples per frame")
        ->delimiter(',')
        ->check(CLI::Range(1u, 1024u))
        ->capture_default_str();
    c->add_option("--frame-loop-frames", o.frame_loop_frames, "Frame loop: timed frames per point")
        ->check(CLI::Range(1u, 100000u))
        ->capture_default_str();
    c->add_option("--scenes", o.scenes,
                  "Scenes: " + catalogue_names() + ", or .json/.obj/.gltf/.glb files")
        ->delimiter(',')
        ->capture_default_str();
    c->add_option("--backends", o.backends,
                  "cpu, vulkan (every mode of the device), vulkan:compute, vulkan:compute-wide "
                  "(--bvh wide), vulkan:compute-auto (--bvh auto), vulkan:pipeline")
        ->delimiter(',')
        ->capture_default_str();
    c->add_option("--samplers", o.samplers,
                  "Ladder: run every backend with each sampler (random, sobol; "
                  "docs/sampling.md)")
        ->delimiter(',')
        ->check(CLI::IsMember({"random", "sobol"}))
        ->capture_default_str();
    c->add_option("--device", o.device, "Vulkan device index or name substring");
    add_image_options(c, o);
    c->add_option("--max-spp", o.max_spp, "Ladder: 1, 2, 4, ... up to this spp")
        ->check(CLI::Range(1u, 1u << 24))
        ->capture_default_str();
    c->add_option("--ref-spp", o.ref_spp, "Reference spp (CPU, cached)")
        ->check(CLI::Range(1u, 1u << 24))
        ->capture_default_str();
    c->add_option("--seed", o.seed, "Seed of the measured renders")->capture_default_str();
    c->add_option("--threads", o.threads, "CPU threads for the ladder and table (0: all)")
        ->check(CLI::Range(0u, 4096u));
    c->add_option("--table-depths", o.table_depths, "Table: depths D at the fixed spp")
        ->delimiter(',')
        ->capture_default_str();
    c->add_option("--table-spp", o.table_spp, "Table: spp S at the fixed depth")
        ->delimiter(',')
        ->capture_default_str();
    c->add_option("--table-fixed-spp", o.table_fixed_spp, "Table: spp of the depth rows")
        ->check(CLI::Range(1u, 1u << 24))
        ->capture_default_str();
    c->add_option("--table-fixed-depth", o.table_fixed_depth, "Table: depth of the spp rows")
        ->check(CLI::Range(1u, 1000u))
        ->capture_default_str();
    c->add_option("--out", o.out_dir, "Output directory")->capture_default_str();
    c->add_option("--cache", o.cache_dir,
                  "Reference cache (default: $TWINPATH_CACHE, $XDG_CACHE_HOME/twinpath, "
                  "~/.cache/twinpath)");
    c->add_option("--assets", o.assets_dir,
                  "Shared test meshes (default $TWINPATH_ASSETS, else ../shared/assets)");
    c->add_option("--section", o.section,
                  "Id of the result's section in BENCHMARKS.md (twinpath-lab markdown)")
        ->capture_default_str();
    c->add_flag("--quick", o.quick, "Tiny CI smoke size");
    // The numerical stress sweeps (stress, docs/stress.md) instead of benchmarks; they use --out
    // (default out/stress), --assets, --backends, --device, --threads, --quick.
    auto stress = std::make_shared<bool>(false);
    c->add_flag("--stress", *stress, "Numerical stress sweeps and their report (docs/stress.md)");
    auto moved = std::make_shared<std::vector<std::string>>();
    add_moved_options(c, *moved);
    return {c, [options, c, stress, moved] {
                refuse_moved_options(*c);
                BenchOptions& o = *options;
                o.command = command_line();
                if (*stress) {
                    stress::StressOptions so;
                    so.out_dir = c->count("--out") ? o.out_dir : "out/stress";
                    so.assets_dir = resolve_assets_dir(o.assets_dir);
                    so.backends = o.backends;
                    so.device = o.device;
                    so.threads = o.threads;
                    so.quick = o.quick;
                    so.self = fs::read_symlink("/proc/self/exe").string();
                    so.command = o.command;
                    return stress::run_stress(so);
                }
                if (o.quick)
                    apply_quick(o, [&](const std::string& opt) { return c->count(opt) > 0; });
                if (!o.scene_sizes.empty() && !c->count("--scenes")) o.scenes.clear();
                return run_bench(o);
            }};
}

} // namespace tp
