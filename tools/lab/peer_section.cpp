#include "tools/lab/peer_section.h"

#include "tools/lab/peer_efficiency.h"
#include "tools/lab/peer_scene.h"
#include "tools/lab/peer_tutorial.h"
#include "util/error.h"
#include "util/progress_bar.h"

#include <fmt/core.h>

#include <filesystem>

namespace fs = std::filesystem;
using nlohmann::json;

namespace tp::lab {
namespace {

// Time to error next to Cycles, on the scene itself.
void efficiency(bench::BenchRun& run, const bench::BenchScene& scene, json& sj) {
    const std::string what = fmt::format("{} time to error", scene.name);
    run.guarded(what, [&] {
        ProgressBar bar(run.next_label(what));
        sj["efficiency"] =
            run_efficiency(scene.flat, scene.name, run.o, run.cache_dir, bar.callback());
        for (const json& s : sj["efficiency"]["skipped"]) run.skip(what, s.get<std::string>());
        fmt::print("bench: {}: done\n", what);
    });
}

// Time per spp next to Embree's tutorial, on the scene's peer variant.
void tutorial(bench::BenchRun& run, const bench::BenchScene& scene, json& sj) {
    const std::string what = fmt::format("{} peer", scene.name);
    Scene variant_scene = scene.scene;
    std::string reason;
    const std::vector<std::string> changes = make_peer_variant(variant_scene, reason);
    if (!fs::exists(run.o.peer_binary))
        reason = fmt::format("Embree's path tracer tutorial is not at {} (Debian package "
                             "embree-tools; --peer-binary PATH)",
                             run.o.peer_binary);
    ProgressBar bar(run.next_label(what)); // draws nothing unless updated
    if (!reason.empty()) {
        run.skip(what, reason);
        return;
    }
    FlatScene variant = bench::flatten_for_bench(std::move(variant_scene), run.o);
    variant.params.min_depth = variant.params.max_depth; // Russian roulette off (peer_tutorial.h)
    variant.name = scene.name;
    const PeerRun pr = run_peer(
        variant, run.o, (fs::path(run.cache_dir) / "peer" / scene.name).string(), bar.callback());
    sj["peer"] = peer_json(pr);
    sj["peer_variant"] = changes;
    fmt::print("bench: {}: done\n", what);
}

} // namespace

void validate_peer_options(const bench::BenchOptions& o) {
    if (o.peer_spp < 2) input_error("--peer-spp must be at least 2, got {}", o.peer_spp);
    if (o.peer_threads.empty()) input_error("--peer-threads must not be empty");
}

bench::Section peer_section() {
    const auto steps = [](const bench::BenchRun&) { return 2; };
    const auto run = [](bench::BenchRun& run, const bench::BenchScene& scene, json& sj) {
        efficiency(run, scene, sj);
        tutorial(run, scene, sj);
    };
    return {"peer", false, steps, run};
}

} // namespace tp::lab
