// `compare --exact`: pixel-by-pixel equality of deterministic layers (docs/compare.md, "Exact
// mode"). Without AOV layers every channel the two files share is compared, a pixel mismatches
// when any channel differs by more than the tolerance (NaN equals NaN, inf equals inf of the
// same sign). When both files carry the AOV layers of `render --aov` (id.instance among them),
// only the AOV layers are compared (R, G, B are Monte Carlo estimates), under per-layer rules:
// ids exactly, albedo, normal and depth within max(tolerance, 1e-4 max(1, |a|, |b|)); and a
// mismatch on a silhouette pixel (one whose instance id differs from a 4-neighbour's in either
// image: the two ray-triangle tests may disagree there by one rounding) is counted and listed
// apart, and does not make the images different.
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
    bool aov_mode = false;                    // AOV layers in both: compared as above
    size_t silhouette_pixels = 0;             // AOV mode: pixels on an instance boundary
    size_t silhouette_mismatches = 0;         // AOV mode: mismatches there (not counted above)
    std::vector<std::pair<int, int>> silhouette_examples; // up to 20 (x, y)
    std::vector<std::pair<int, int>> mismatch_examples;   // up to 20 (x, y), off silhouettes
    std::vector<uint8_t> mask; // per pixel: 0 equal, 1 silhouette mismatch, 2 mismatch
    bool identical() const { return mismatching_pixels == 0; }
};

// Throws InputError naming the files for different sizes or no channel in common.
ExactResult exact_compare(const std::string& path_a, const ExrImage& a, const std::string& path_b,
                          const ExrImage& b, double tolerance);

nlohmann::json exact_json(const ExactResult& r);
std::string exact_verdict_line(const ExactResult& r);

} // namespace tp
