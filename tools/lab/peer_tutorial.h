// Throughput next to a peer in the same run (docs/bench.md, "Peer comparisons"): our CPU backend
// and Embree's path tracer tutorial on the same scene (peer_scene.h), camera, film, spp and path
// length, for each thread count.
//
// Time per spp (one sample of every pixel): both programs are timed at 1 and at N samples per
// pixel and the difference is divided by N - 1, which cancels what does not scale with the samples
// (the tutorial's process start, OBJ parsing and BVH build; our build is outside the render time
// anyway). Each is the best of kPeerRepeats runs. The tutorial does not count its rays; one more,
// untimed, pair of runs (1 and N spp) with peer_ray_counter.c preloaded counts them, so its rays/s
// is measured: its rays per spp over its time per spp. (It ends paths whose throughput drops
// below 0.01 and sends one shadow ray per light per vertex, so its ray count differs from ours.)
// Without the counter module its rays/s is inferred as our rays per spp over its time per spp. Path
// length: our max depth D (scattering events) with Russian roulette off, the tutorial's
// --max-path-length D ("1 = primary + shadow"): both sum paths of up to D scattering events.
#pragma once

#include "bench/options.h"
#include "scene/flatten.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace tp::lab {

constexpr int kPeerRepeats = 2;

struct PeerRow {
    uint32_t threads = 0;
    double ours_low_s = 0, ours_high_s = 0; // render time at 1 and at N spp
    double ours_rays_per_spp = 0;           // over the whole image
    double peer_low_s = 0, peer_high_s = 0; // process wall time at 1 and at N spp
    int peer_exit = 0;                      // non-zero: the tutorial failed (row unusable)
};

struct PeerRun {
    uint32_t spp = 0;
    std::string obj;                         // the exported scene
    std::vector<std::string> peer_arguments; // after the binary, for the N-spp run
    std::vector<PeerRow> rows;
    double peer_rays_per_spp = 0; // counted by the preloaded module; 0: not counted
};

// `scene` is the peer variant, flattened at the benchmark's size, with min depth = max depth.
PeerRun run_peer(const FlatScene& scene, const bench::BenchOptions& options,
                 const std::string& work_dir, const std::function<void(double)>& progress);

nlohmann::json peer_json(const PeerRun& run);

} // namespace tp::lab
