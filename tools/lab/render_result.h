// A bench result (bench.json, from `twinpath bench` or `twinpath-lab peer`, here or on another
// machine) rendered for people: its plots, CSV files and markdown section (bench.md) beside it,
// and the section merged into a markdown file such as BENCHMARKS.md (markdown.h). Everything is
// derived from the JSON alone, so a result brought back without its files renders the same way.
#pragma once

#include <string>

namespace tp::lab {

// Renders the result at `path` into its own directory and, when `markdown` is not empty, merges
// its section there, with links relative to the markdown file. InputError for a file that is
// missing, not JSON, not a bench result (schema twinpath-bench/1) or missing a field it needs.
void render_result(const std::string& path, const std::string& markdown);

} // namespace tp::lab
