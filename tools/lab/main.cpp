// twinpath-lab: the benchmark laboratory beside twinpath (docs/bench.md, "The lab"). `peer`
// measures the peer comparisons into a bench result; `markdown` renders results (from
// `twinpath bench` or `peer`) as CSV, SVG plots and markdown, and merges them into
// BENCHMARKS.md. Exit codes as twinpath's: 0 success, 2 bad usage or bad input, 3 runtime
// failure.
#include "tools/lab/commands.h"

#include "util/run_command.h"

#include <fmt/core.h>

#include <vector>

int main(int argc, char** argv) {
    CLI::App app{"twinpath-lab: twinpath's benchmark lab (peer comparisons, BENCHMARKS.md)"};
    app.require_subcommand(1);
    const std::vector<tp::lab::Subcommand> commands = {tp::lab::add_peer_command(app),
                                                       tp::lab::add_markdown_command(app)};
    return tp::parse_and_run(app, argc, argv, commands, "twinpath-lab");
}
