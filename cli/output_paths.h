// The output files one command names (-o, --png, --stats, --json, ...), checked before any work:
// each must be writable, and no two may name the same file. Bad paths are usage errors (exit 2).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace tp {

// (option, path) for each output the command will write; options whose path is empty because
// they were not given are left out by the caller. Throws InputError naming the option: for an
// empty path, a missing or unwritable directory, a directory or read-only file at the path,
// and for two options that name the same file (but for a device such as /dev/null).
void check_output_paths(const std::vector<std::pair<std::string, std::string>>& outputs);

} // namespace tp
