// The thesis's Table 5.3 for one backend and mode on one scene: time and rays per second over
// the maximum depth D at a fixed spp, then over the spp S at a fixed depth. Russian roulette
// is off (min depth = max depth), as in the thesis's fixed-depth measurements, so D is the
// path length every path that stays in the scene reaches. The spp rows come from one render
// with checkpoints at each S (no setup cost in T, unlike the thesis, whose T included it).
#pragma once

#include "bench/backends.h"
#include "bench/options.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace tp::bench {

struct SweepRow {
    uint32_t depth = 0, spp = 0;
    double wall_s = 0, gpu_s = -1;
    RayCounts rays;
    uint64_t samples = 0; // pixel samples
};

struct SweepRun {
    Backend backend;
    uint64_t accel_bytes = 0;
    double build_s = 0;
    std::map<std::string, std::string> extra; // the renderer's own notes (RenderStats::extra)
    std::vector<SweepRow> depth_rows, spp_rows;
};

SweepRun run_sweep(const FlatScene& scene, const Backend& backend, const BenchOptions& options,
                   const std::function<void(double)>& progress);

nlohmann::json sweep_json(const SweepRun& run);

} // namespace tp::bench
