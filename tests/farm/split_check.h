// What the split-render tests check on either backend (tests/farm): that --sample-offset shifts
// the samples a render traces, and that merged parts equal one render of all their samples up
// to the float rounding of the EXRs.
#pragma once

#include <string>
#include <vector>

namespace tp::test {

// Renders the bundled cornell scene at 16x16, depth 4, with `args` (backend, spp, offset,
// seed ...) to dir/name; requires exit code 0 and returns the path.
std::string render_part(const std::string& dir, const std::string& name, const std::string& args);

// Samples 0 and 1 of every pixel, x0 and x1, from three renders: spp 1 at offset 0 (x0), spp 1
// at offset 1 (x1) and spp 2 at offset 0 (mean (x0 + x1) / 2, variance of the mean
// (x0 - x1)^2 / 4). Checks x1 = 2 mean - x0 and the variance, and that x1 differs from x0 in
// most pixels (an ignored offset would repeat sample 0).
void check_offset_shifts_samples(const std::string& dir, const std::string& backend_args);

// `merge` of `parts` (tiling [0, N) of one seed) against `single` (one render of [0, N)):
// check_merged_equals_single on dir/merged.exr; returns its tolerance.
double check_merge_equals_single(const std::string& dir, const std::vector<std::string>& parts,
                                 const std::string& single);

// The merge of `parts` in `merged` against `single`: every channel per pixel within the bound
// that the float32 rounding of the files allows (split_check.cpp derives it), and
// `compare --exact` with the largest bound as tolerance, which it returns.
double check_merged_equals_single(const std::string& merged, const std::vector<std::string>& parts,
                                  const std::string& single);

} // namespace tp::test
