// `twinpath bench --frame-loop`: the viewer's frame loop without a window (as `view --headless`:
// one batch of the same samples of every pixel, its resolve pass and the display pass, one
// submission a frame) at each of --frame-loop-spp samples per frame, on each Vulkan backend. A
// point times --frame-loop-frames frames after two unmeasured ones (pipelines warm, buffers
// grown): wall time per frame on the host, and per frame the GPU time of the trace, resolve and
// display passes from timestamps, the rest of the wall time being the host's. The lab's table
// adds the fixed cost of a frame: the line through the fewest and the most samples per frame,
// at zero samples.
#pragma once

#include "bench/backends.h"
#include "bench/options.h"

#include <nlohmann/json.hpp>

#include <functional>

namespace tp::bench {

// The points of one Vulkan backend, in the order of options.frame_loop_spp (docs/bench.md,
// "--frame-loop").
nlohmann::json run_frame_loop(const FlatScene& scene, const Backend& backend,
                              const BenchOptions& options,
                              const std::function<void(double)>& progress);

} // namespace tp::bench
