// --quick: the CI smoke size of a benchmark run (24x24, the Cornell box, a ladder to 4 spp, a
// reference of 32 spp, two depths and two sample counts in the table, ...), so that every
// section runs in seconds. It checks that a run works, not how fast.
#pragma once

#include "bench/options.h"

#include <functional>
#include <string>

namespace tp::bench {

// Sets the smoke size of each setting whose option the command line did not give:
// `given("--width")` says whether it did.
void apply_quick(BenchOptions& o, const std::function<bool(const std::string& option)>& given);

} // namespace tp::bench
