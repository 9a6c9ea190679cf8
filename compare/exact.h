// `compare --exact`: pixel-by-pixel equality of deterministic layers. This is the simple
// version issue 3 asks for: every channel the two files share is compared, a pixel mismatches
// when any channel differs by more than the tolerance (NaN equals NaN, inf equals inf of the
// same sign). The AOV-aware comparison of issue 7 (silhouette pixels, per-layer rules) will
// build on it.
#pragma once

#include "image/exr_io.h"

#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

namespace tp {

struct ExactResult {
    std::string path_a, path_b;
    int width = 0, height = 0;
    double tolerance = 0;
    std::vector<std::string> only_a, only_b;  // channels present in one file only
    std::map<std::string, size_t> mismatches; // per compared channel
    size_t mismatching_pixels = 0;            // pixels with any compared channel off
    double max_abs_difference = 0;            // over finite pairs
    bool identical() const { return mismatching_pixels == 0; }
};

// Throws InputError naming the files for different sizes or no channel in common.
ExactResult exact_compare(const std::string& path_a, const ExrImage& a, const std::string& path_b,
                          const ExrImage& b, double tolerance);

nlohmann::json exact_json(const ExactResult& r);
std::string exact_verdict_line(const ExactResult& r);

} // namespace tp
