// Error against time for one backend and mode on one scene (docs/bench.md, "Error, reference
// and efficiency"): one render with checkpoints at 1, 2, 4, ... spp (RenderOptions::checkpoints),
// each snapshot measured against the scene's reference.
//
// relMSE and MAPE are compare/metrics.h's (relative to the reference, eps = 0.01). The
// reference is itself noisy: E[relMSE] = error of the image + mean(w Var r), so the excess
// relMSE - mean(w Var r) (compare/convergence.h) estimates the error against the true image and
// is what the efficiency and the times to reach 1e-2 and 1e-3 use. Efficiency is the
// thesis's epsilon = 1 / (V T) (sec. 2.6, after Veach 1997): error times the time it took,
// inverted, so that a backend twice as fast at the same error is twice as efficient.
#pragma once

#include "bench/backends.h"
#include "bench/fit.h"
#include "bench/options.h"
#include "bench/reference.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <vector>

namespace tp::bench {

struct LadderPoint {
    uint32_t spp = 0;
    double wall_s = 0; // rendering time up to this snapshot, snapshot overhead excluded
    double gpu_s = -1; // GPU time (timestamp queries); < 0 when not measured
    RayCounts rays;    // traced up to this snapshot
    double relmse = 0, excess = 0, mape = 0;
};

struct LadderRun {
    Backend backend;
    std::string sampler; // render/sampler.h
    uint32_t threads = 0;
    uint64_t accel_bytes = 0;
    double build_s = 0;
    std::vector<LadderPoint> points;
    double reference_noise = 0; // mean(w Var r)
    double V = 0;               // excess relMSE ~ V / spp + B (compare/convergence.h)
    double spp_slope = 0;       // of log excess on log spp; -1 for an unbiased estimator
    LogLogFit fit;              // excess against wall time
    std::optional<double> time_to_1e2, time_to_1e3;
};

// 1, 2, 4, ... up to max_spp (which is included).
std::vector<uint32_t> ladder_counts(uint32_t max_spp);

LadderRun run_ladder(const FlatScene& scene, const Backend& backend, const std::string& sampler,
                     const Reference& reference, const BenchOptions& options,
                     const std::function<void(double)>& progress);

nlohmann::json ladder_json(const LadderRun& run);

} // namespace tp::bench
