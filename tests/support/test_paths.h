// Locations the tests need, fixed at configure time, and helpers to run the twinpath binary
// and read what it writes.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace tp::test {

std::string twinpath_bin();
std::string lab_bin(); // twinpath-lab (tools/lab)
std::string scenes_dir();
std::string assets_dir(); // ../shared/assets; may be absent (asset tests then skip loudly)
std::string source_dir();
std::string glslang_validator();

// A fresh empty directory under the build tree's temporary area, unique per call.
std::string temp_dir(const std::string& tag);

struct ProcessResult {
    int exit_code = -1;
    std::string out; // stdout and stderr together
};

// Runs a command line through /bin/sh, capturing its output.
ProcessResult run(const std::string& command);

// Single-quotes s for /bin/sh.
std::string shell_quote(const std::string& s);

// The command line that runs the twinpath binary with `args` (already quoted as needed).
std::string twinpath(const std::string& args);

// The same for twinpath-lab.
std::string twinpath_lab(const std::string& args);

// A JSON file (stats, compare results, path logs); throws when it is missing or malformed.
nlohmann::json read_json(const std::string& path);

} // namespace tp::test
