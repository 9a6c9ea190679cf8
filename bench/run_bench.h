// twinpath bench (docs/bench.md): the sections BenchOptions asks for, on each scene and
// each backend and mode, into one JSON result and the files derived from it.
#pragma once

#include "bench/options.h"

namespace tp::bench {

// Measures and writes bench.json, bench.md, CSV files and plots into o.out_dir (and the section
// into o.markdown when given). Returns 0, or 3 when a render failed at run time (the files are
// written all the same); throws InputError for bad options.
int run_bench(const BenchOptions& o);

// --from-json: the derived files of earlier results again, beside each JSON file, and their
// sections merged into o.markdown.
int render_results(const BenchOptions& o);

} // namespace tp::bench
