// Holm's step-down procedure (Holm 1979, "A simple sequentially rejective multiple test
// procedure"): controls the family-wise error rate at `level` under any dependence between
// the tests, which matters here because the R, G, B values of one pixel come from the same
// paths. Its first step is Bonferroni, so "any rejection" happens exactly when
// m * min(p) <= level, and that adjusted minimum is the family's p-value.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tp {

struct HolmResult {
    double p_value = 1.0;          // min(1, m * min p): the family-wise p-value
    std::vector<uint8_t> rejected; // per hypothesis, in input order
    size_t count = 0;              // number rejected
};

HolmResult holm(const std::vector<double>& p, double level);

} // namespace tp
