// Time to error next to a production renderer (docs/bench.md, "Time to error next to a
// production renderer"): twinpath's CPU backend (each sampler of --samplers) and every peer
// installed (Blender's Cycles, peer_cycles.h) render the same
// scene for the same time budget; each image's relMSE is measured against a converged render of
// the same renderer, and the efficiency is eps = 1 / (relMSE * t) (Veach 1997, sec. 2.4.1;
// docs/bench.md), so eps(twinpath) / eps(peer) is how much sooner twinpath reaches an error.
//
// Time: the sampling time of N spp, (t(N) - t(1)) N / (N - 1) with t the render's wall time
// (twinpath: render_cpu's, from its 1-spp checkpoint; a peer: its process's), which leaves out
// what does not scale with the samples (process start, scene import, BVH build) for both. N is
// chosen per renderer to fill the budget from its time per spp in a short calibration (1 and
// kCalibrationSpp spp).
//
// Error: excess relMSE = relMSE(I, R) - mean(w Var R), w = 1 / (R^2 + 0.01), the error against the
// true image of the renderer's estimator (compare/convergence.h). twinpath's R is the bench's
// cached reference (bench/reference.h), Var R its variance channels; a peer's R is the mean of two
// renders R1, R2 of half the reference spp with seeds other than the measured one, and
// Var R = E[(R1 - R2)^2] / 4 is estimated from their difference. Different renderers' images are
// not compared with each other: their materials and light models differ in detail.
#pragma once

#include "bench/options.h"
#include "scene/flatten.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>

namespace tp::lab {

constexpr uint32_t kCalibrationSpp = 8;

// `scene` at the benchmark's size (bench::flatten_for_bench); `name` names its cache files.
nlohmann::json run_efficiency(const FlatScene& scene, const std::string& name,
                              const bench::BenchOptions& options, const std::string& cache_dir,
                              const std::function<void(double)>& progress);

} // namespace tp::lab
