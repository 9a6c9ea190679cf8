// `twinpath pathdiff A.json B.json`: holds two path logs (render --debug-log) against each
// other vertex by vertex and field by field, in the order the path loop computes the fields
// (render/debug_output.h, path_log_fields), and reports the first field that differs by more
// than its tolerance (docs/debugging.md).
#pragma once

#include "render/debug_output.h"

#include <nlohmann/json.hpp>

#include <string>

namespace tp {

struct PathDiffTolerances {
    double geometry = 1e-4;    // |a - b| <= geometry * max(1, |a|, |b|)
    double direction = 1e-3;   // |a - b| <= direction
    double radiometric = 1e-2; // |a - b| <= radiometric * max(|a|, |b|) + 1e-6
};

struct PathDiffResult {
    bool diverged = false;
    size_t paths_compared = 0, vertices_compared = 0;
    // The first divergence: the path (sample), the vertex index in that path and the field;
    // field "vertex count" when one path ends before the other with every shared field equal.
    uint32_t sample = 0;
    size_t vertex = 0;
    std::string field;
    std::string value_a, value_b; // the field's values as the report shows them
    std::string why;              // which component differs by how much, against which tolerance
    std::string report;           // the human-readable account, several lines
};

// Throws InputError naming the file for a missing or malformed log, or logs of different
// pixels, seeds or image sizes.
nlohmann::json read_path_log(const std::string& path);

PathDiffResult pathdiff(const std::string& name_a, const nlohmann::json& a,
                        const std::string& name_b, const nlohmann::json& b,
                        const PathDiffTolerances& tol);

} // namespace tp
