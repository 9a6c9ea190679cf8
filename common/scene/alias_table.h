// Walker's alias method with Vose's numerically stable construction (M. D. Vose, "A linear
// algorithm for generating random numbers with a given distribution", IEEE TSE 17(9), 1991).
// Sampling is O(1): shared/sampling.h alias_slot + alias_resolve.
#pragma once

#include "shared/types.h"

#include <vector>

namespace tp {

// weights: non-negative, finite, with a positive sum. Entry i's pdf is weights[i] / sum.
std::vector<AliasEntry> build_alias_table(const std::vector<double>& weights);

} // namespace tp
