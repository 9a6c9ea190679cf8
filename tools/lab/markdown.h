// The human-readable form of a benchmark result: a markdown section (run facts, the ladder
// summary per scene, the Table 5.3 sweep, the peer comparison), and its merge into a file
// such as BENCHMARKS.md, where each section sits between
//   <!-- twinpath-bench:begin ID -->  and  <!-- twinpath-bench:end ID -->
// and is replaced in place when the same ID is generated again; text outside the markers is
// kept as it is.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace tp::lab {

// The section for `result`; links (plots) are written relative to `link_base`, the directory
// of the result's files as seen from the markdown file.
std::string markdown_section(const nlohmann::json& result, const std::string& link_base);

// Replaces (or appends) section `id` of the markdown file `path` with `text`, creating the
// file with a short preamble when it does not exist.
void merge_markdown_section(const std::string& path, const std::string& id,
                            const std::string& text);

} // namespace tp::lab
