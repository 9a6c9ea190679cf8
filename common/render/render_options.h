// What a render is asked to do beyond the scene itself, and what it returns; the same for
// every backend.
#pragma once

#include "render/debug_output.h"
#include "render/film.h"
#include "render/stats.h"
#include "shared/rng.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

namespace tp {

struct RenderResult;

struct RenderOptions {
    uint32_t seed = 0;
    // SAMPLER_* (shared/rng.h, render/sampler.h); Sobol by default (docs/sampling.md, "Which is
    // the default, and why").
    uint32_t sampler = SAMPLER_SOBOL;
    // What render_exr writes (render/film.h): lean by default, full for parts to be merged.
    FilmLayout film = FilmLayout::lean;
    // `--sample-offset K`: the render traces samples K, K+1, ... of every pixel (of the seed's
    // sequence) instead of 0, 1, ...; the scene's spp says how many. The random numbers depend
    // only on (seed, pixel, sample, dimension) (shared/rng.h), so renders of disjoint ranges
    // are disjoint sets of samples of one estimator and merge exactly (docs/farm.md). Counts,
    // checkpoints and progress stay relative to K. K + spp must fit in 32 bits.
    uint32_t sample_offset = 0;
    // When set, the render takes its samples in ranges from here instead of tracing
    // [sample_offset, sample_offset + spp) (the Vulkan engine's --device all shares one render's
    // samples among devices this way, vulkan_rt/renderer/sample_share.h). It is called with the
    // render's rate so far (pixel-samples per second; 0 before its first range) and returns the
    // next range, or a count of 0 when none is left. Successive ranges ascend.
    struct SampleGrant {
        uint32_t begin = 0, count = 0;
    };
    std::function<SampleGrant(double pixel_samples_per_second)> sample_source;
    double time_limit_s = 0; // 0: none; otherwise stop after the pass that crosses it
    uint32_t threads = 0;    // CPU threads; 0: all cores
    // Vulkan: render invocations per launch, which share its samples (docs/gpu.md, "Work
    // items"); 0: as many as the device keeps resident where it says (NVIDIA), else one per
    // sample.
    uint32_t gpu_invocations = 0;
    // `--features all`: render with the path loop that has every feature compiled in instead
    // of the one specialized to the scene's features (scene/features.h), for comparisons.
    bool all_features = false;
    // When set and true (the first SIGINT/SIGTERM, util/interrupt.h), the render ends after the
    // pass in flight: every pixel then has the same number of samples, reported as stats.spp.
    const std::atomic<bool>* stop = nullptr;
    bool stop_requested() const { return stop && stop->load(); }
    // Called once the setup (acceleration structures, device, pipelines) is done, as the first
    // pass begins; with several devices, by each device's thread. May be empty.
    std::function<void()> on_first_pass;
    // Called after every pass with the fraction of samples done; may be empty.
    std::function<void(double fraction)> progress;
    // Sample counts at which a snapshot is wanted: a benchmark ladder renders once and reads
    // the film at 1, 2, 4, ... spp, with the time spent so far. Passes end exactly at these
    // counts and on_checkpoint receives the film and statistics up to there. Ascending;
    // counts above the render's spp are ignored.
    std::vector<uint32_t> checkpoints;
    std::function<void(const RenderResult& snapshot)> on_checkpoint;
    // Path logs, AOVs and debug views (render/debug_output.h, docs/debugging.md).
    DebugRequest debug;

    // The first checkpoint above `done`, or `spp` when there is none.
    uint32_t next_stop(uint32_t done, uint32_t spp) const {
        for (uint32_t c : checkpoints)
            if (c > done && c < spp) return c;
        return spp;
    }
    bool is_checkpoint(uint32_t done) const {
        for (uint32_t c : checkpoints)
            if (c == done) return true;
        return false;
    }
};

struct RenderResult {
    Film film;
    RenderStats stats;
    DebugOutput debug; // what options.debug asked for
};

} // namespace tp
