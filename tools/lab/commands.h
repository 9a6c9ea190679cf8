// The twinpath-lab subcommands (docs/bench.md, "The lab"). Each registers its options on the
// CLI11 app and returns the function that runs it; that function returns the exit code.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace tp::lab {

struct Subcommand {
    CLI::App* app;
    std::function<int()> run;
};

Subcommand add_peer_command(CLI::App& app);
Subcommand add_markdown_command(CLI::App& app);

} // namespace tp::lab
