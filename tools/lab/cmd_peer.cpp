// twinpath-lab peer: the peer comparisons (peer_section.h) on the benchmark scenes, into a bench
// result (OUT/bench.json) that `twinpath-lab markdown` renders. Its options are `twinpath
// bench`'s for the scenes, the image and the reference, and the peers' own.
#include "tools/lab/commands.h"

#include "bench/host_info.h"
#include "bench/image_options.h"
#include "bench/options.h"
#include "bench/quick.h"
#include "bench/scenes.h"
#include "tools/lab/peer_section.h"

#include <memory>

namespace tp::lab {

Subcommand add_peer_command(CLI::App& app) {
    auto options = std::make_shared<bench::BenchOptions>();
    bench::BenchOptions& o = *options;
    for (const bench::CatalogueEntry& e : bench::scene_catalogue()) o.scenes.push_back(e.name);
    o.section = "local";
    CLI::App* c = app.add_subcommand(
        "peer", "Time per spp next to Embree's path tracer tutorial; time to error next to Cycles");
    c->add_option("--scenes", o.scenes,
                  "Scenes: " + bench::catalogue_names() + ", or .json/.obj/.gltf/.glb files")
        ->delimiter(',')
        ->capture_default_str();
    c->add_option("--samplers", o.samplers,
                  "Time to error: twinpath's rows with each sampler (random, sobol; "
                  "docs/sampling.md)")
        ->delimiter(',')
        ->check(CLI::IsMember({"random", "sobol"}))
        ->capture_default_str();
    bench::add_image_options(c, o);
    c->add_option("--ref-spp", o.ref_spp, "Reference spp of each renderer (cached)")
        ->check(CLI::Range(1u, 1u << 24))
        ->capture_default_str();
    c->add_option("--seed", o.seed, "Seed of the measured renders")->capture_default_str();
    c->add_option("--peer-spp", o.peer_spp, "N of the tutorial's (t(N) - t(1)) / (N - 1) timing")
        ->check(CLI::Range(1u, 1u << 20))
        ->capture_default_str();
    c->add_option("--peer-threads", o.peer_threads, "Thread counts")
        ->delimiter(',')
        ->check(CLI::Range(1u, 4096u))
        ->capture_default_str();
    c->add_option("--peer-binary", o.peer_binary, "Embree's path tracer tutorial")
        ->capture_default_str();
    c->add_option("--peer-budget", o.peer_budget_s,
                  "Seconds of sampling per renderer in the time-to-error table")
        ->check(CLI::Range(0.01, 1e6))
        ->capture_default_str();
    c->add_option("--blender", o.blender, "Blender, whose Cycles renders the scenes too")
        ->capture_default_str();
    c->add_option("--out", o.out_dir, "Output directory (bench.json)")->capture_default_str();
    c->add_option("--cache", o.cache_dir,
                  "Reference cache (default: $TWINPATH_CACHE, $XDG_CACHE_HOME/twinpath, "
                  "~/.cache/twinpath)");
    c->add_option("--assets", o.assets_dir,
                  "Shared test meshes (default $TWINPATH_ASSETS, else ../shared/assets)");
    c->add_option("--section", o.section, "Id of the result's section in BENCHMARKS.md")
        ->capture_default_str();
    c->add_flag("--quick", o.quick, "Tiny CI smoke size");
    return {c, [options, c] {
                bench::BenchOptions& o = *options;
                o.command = bench::command_line();
                // --quick sets the smoke size of each setting not given, also of those that
                // have no option here (they are recorded with the result).
                const auto given = [&](const std::string& name) {
                    const CLI::Option* opt = c->get_option_no_throw(name);
                    return opt && opt->count() > 0;
                };
                if (o.quick) bench::apply_quick(o, given);
                validate_peer_options(o);
                return bench::run_sections(o, {peer_section()});
            }};
}

} // namespace tp::lab
