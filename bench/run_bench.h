// twinpath bench (docs/bench.md): the sections BenchOptions asks for, on each scene and each
// backend and mode, into one JSON result (bench.json).
#pragma once

#include "bench/options.h"

namespace tp::bench {

// Measures and writes o.out_dir/bench.json. Returns 0, or 3 when a render failed at run time
// (the result is written all the same); throws InputError for bad options.
int run_bench(const BenchOptions& o);

} // namespace tp::bench
