// Runs another program (the peer renderer) and times it.
#pragma once

#include <string>
#include <vector>

namespace tp::lab {

struct ProcessRun {
    int exit_code = -1; // -1: could not start or killed by a signal
    double wall_s = 0;  // from start to exit
};

// Runs argv[0] (a path) with the arguments, stdout and stderr appended to `log_path`, in this
// process's environment plus `env` ("NAME=value" entries).
ProcessRun run_process(const std::vector<std::string>& argv, const std::string& log_path,
                       const std::vector<std::string>& env = {});

} // namespace tp::lab
