// `twinpath bench --specialization`: for each scene and backend/mode, the time per
// spp of the path loop specialized to the scene's features against the one with every feature
// compiled in (`--features all`), as a ratio measured in one run. Renders alternate between the
// two variants (all, scene, all, scene, ...) with the same seed, and each variant's time is the
// best of its rounds, so that warm-up and drifting clocks do not favour either side. The
// Vulkan pipelines are created (and cached) before the timed part of a render, so the ratio is
// of rendering alone.
#pragma once

#include "bench/backends.h"
#include "bench/options.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>

namespace tp::bench {

// Renders per variant and round count: the section's spp and rounds (BenchOptions).
nlohmann::json run_specialization(const FlatScene& scene, const Backend& backend,
                                  const BenchOptions& options,
                                  const std::function<void(double)>& progress);

} // namespace tp::bench
