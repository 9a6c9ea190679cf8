// The twinpath subcommands (docs/design.md, "Command line"). Each registers its options on the
// CLI11 app and returns the function that runs it; that function returns the exit code.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace tp {

struct Subcommand {
    CLI::App* app;
    std::function<int()> run;
};

Subcommand add_render_command(CLI::App& app);
Subcommand add_compare_command(CLI::App& app);
Subcommand add_merge_command(CLI::App& app);
Subcommand add_info_command(CLI::App& app);
Subcommand add_bench_command(CLI::App& app);
Subcommand add_pathdiff_command(CLI::App& app);
Subcommand add_view_command(CLI::App& app);
Subcommand add_verify_command(CLI::App& app);

} // namespace tp
