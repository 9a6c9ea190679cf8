// What an engine answers for a batch of rays aimed directly rather than rendered (the stress
// suite's watertightness check): per ray the closest hit's distance and whether there was one,
// and how many traversals a loop budget cut short (compute mode on lavapipe), whose answers are
// not final.
#pragma once

#include <cstdint>
#include <vector>

namespace tp {

struct ClosestHits {
    std::vector<float> t;
    std::vector<uint8_t> found;
    uint64_t truncated = 0;
};

} // namespace tp
