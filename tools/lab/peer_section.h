// The peer section of a bench result (twinpath-lab peer; docs/bench.md, "Peer comparisons"):
// on each scene, time to error next to Blender's Cycles (peer_efficiency.h), then time per spp
// next to Embree's path tracer tutorial (peer_tutorial.h) on the scene's peer variant
// (peer_scene.h). A peer that is not installed, or a scene it cannot render, is skipped with the
// reason.
#pragma once

#include "bench/run_sections.h"

namespace tp::lab {

// InputError for --peer-spp below 2 or an empty --peer-threads.
void validate_peer_options(const bench::BenchOptions& o);

bench::Section peer_section();

} // namespace tp::lab
