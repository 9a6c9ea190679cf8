// twinpath-lab markdown RESULT.json ... [--markdown FILE]: each bench result rendered beside
// itself (render_result.h), its section merged into FILE.
#include "tools/lab/commands.h"

#include "tools/lab/render_result.h"

#include <memory>
#include <string>
#include <vector>

namespace tp::lab {

Subcommand add_markdown_command(CLI::App& app) {
    struct Args {
        std::vector<std::string> results;
        std::string markdown;
    };
    auto args = std::make_shared<Args>();
    CLI::App* c = app.add_subcommand(
        "markdown",
        "Plots, CSV and bench.md beside each bench result; sections into BENCHMARKS.md");
    c->add_option("results", args->results,
                  "bench.json files (twinpath bench, twinpath-lab peer; from any machine)")
        ->required();
    c->add_option("--markdown", args->markdown,
                  "Merge each result's section into this file (BENCHMARKS.md)");
    return {c, [args] {
                for (const std::string& path : args->results) render_result(path, args->markdown);
                return 0;
            }};
}

} // namespace tp::lab
