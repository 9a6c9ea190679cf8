// What one benchmark run is asked to do: which sections, scenes and backends, at which size and
// sample counts, and where its result goes. cli/cmd_bench.cpp fills it for `twinpath bench`,
// tools/lab/cmd_peer.cpp for the lab's peer comparison; every section reads it and nothing else,
// and every result records it (settings).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tp::bench {

// The seed of every cached reference. The measured renders use BenchOptions::seed, which must
// differ: a reference that shares samples with the image it judges hides their error.
constexpr uint32_t kReferenceSeed = 0x7e5f0001u;

struct BenchOptions {
    // twinpath bench's sections; when none is chosen the ladder runs.
    bool ladder = false;         // error against time for each backend and mode (ladder.h)
    bool table = false;          // rays/s and time over depth and spp (thesis Table 5.3)
    bool specialization = false; // scene-specialized vs all-features time per spp
    uint32_t spec_spp = 16, spec_rounds = 3; // specialization: spp per render, rounds per variant
    bool pipeline_stats = false; // specialization: the Vulkan driver's pipeline statistics
    bool sizes = false;          // rays/s against image size (bench/sizes.h)
    // Sizes: WxH (or N for NxN) in any order; each point renders at least sizes_time_s seconds,
    // best of sizes_rounds.
    std::vector<std::string> sizes_list{"64x64",     "128x128",   "256x256",  "512x512",
                                        "1024x1024", "1920x1080", "3840x2160"};
    double sizes_time_s = 0.5;
    uint32_t sizes_rounds = 2;
    // Sizes: a point renders exactly this many spp instead of for sizes_time_s; 0: by time.
    uint32_t sizes_spp = 0;
    // Sizes' scene-size axis: the scenes `<scene_sizes_family>_<N>` for each N (scenes.h,
    // SizedScene), after those of `scenes`.
    std::vector<uint32_t> scene_sizes;
    std::string scene_sizes_family = "buddhas";

    bool frame_loop = false; // the viewer's frame loop on each Vulkan backend (frame_loop.h)
    std::vector<uint32_t> frame_loop_spp{1, 4, 16}; // samples per frame of each point
    uint32_t frame_loop_frames = 100;               // timed frames of each point

    std::vector<std::string> scenes;             // catalogue names (scenes.h) or .json/.obj files
    std::vector<std::string> backends;           // cpu, vulkan (every mode), vulkan:compute, ...
    std::vector<std::string> samplers{"random"}; // ladder: each backend with each sampler
    std::string device;                          // Vulkan --device selector

    uint32_t width = 256, height = 256;
    std::optional<uint32_t> max_depth; // overrides the scene's
    uint32_t max_spp = 64;             // ladder: 1, 2, 4, ... up to this
    uint32_t ref_spp = 1024;           // reference
    uint32_t seed = 1;
    uint32_t threads = 0; // CPU renders other than the peer comparison; 0: all cores

    // Table 5.3: depths at table_fixed_spp, then sample counts at table_fixed_depth. Russian
    // roulette is off there (min depth = max depth), as in the thesis's fixed-depth runs.
    std::vector<uint32_t> table_depths{1, 2, 3, 5, 10};
    std::vector<uint32_t> table_spp{1, 10, 100, 1000};
    uint32_t table_fixed_spp = 10, table_fixed_depth = 3;

    // The lab's peer comparison (tools/lab/peer_section.h), recorded in every result's settings:
    // time per sample from renders at 1 and peer_spp samples next to Embree's tutorial, for each
    // thread count, path length = the scene's max depth (or max_depth); and time to error next
    // to Blender's Cycles, each renderer sampling for peer_budget_s seconds.
    uint32_t peer_spp = 16;
    std::vector<uint32_t> peer_threads{1, 2};
    std::string peer_binary = "/usr/bin/pathtracer";
    double peer_budget_s = 10;
    std::string blender = "/usr/bin/blender";

    std::string out_dir = "out/bench";
    std::string cache_dir;  // empty: the project's cache directory (util/cache_dir.h)
    std::string assets_dir; // empty: $TWINPATH_ASSETS, else ../shared/assets of the source tree
    std::string section;    // id of the result's section in BENCHMARKS.md (twinpath-lab markdown)
    bool quick = false;     // the CI smoke size (quick.h)

    std::string command; // the command line, recorded with every number
};

} // namespace tp::bench
