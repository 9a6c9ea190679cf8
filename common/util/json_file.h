// JSON files the commands write (statistics, comparison results, benchmark results): indented
// by two spaces for people and diffs, with a final newline, through write_output_file (so a
// failed write is a RuntimeError naming the file, and never leaves half a file).
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace tp {

void write_json(const std::string& path, const nlohmann::json& j);

} // namespace tp
