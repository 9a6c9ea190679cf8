// twinpath-lab: the benchmark laboratory beside twinpath (docs/bench.md, "The lab"). `peer`
// measures the peer comparisons into a bench result; `markdown` renders results (from
// `twinpath bench` or `peer`) as CSV, SVG plots and markdown, and merges them into
// BENCHMARKS.md. Exit codes as twinpath's: 0 success, 2 bad usage or bad input, 3 runtime
// failure.
#include "tools/lab/commands.h"

#include "util/error.h"

#include <fmt/core.h>

#include <vector>

int main(int argc, char** argv) {
    CLI::App app{"twinpath-lab: twinpath's benchmark lab (peer comparisons, BENCHMARKS.md)"};
    app.require_subcommand(1);
    const std::vector<tp::lab::Subcommand> commands = {tp::lab::add_peer_command(app),
                                                       tp::lab::add_markdown_command(app)};
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return 2;
    }
    try {
        for (const tp::lab::Subcommand& c : commands)
            if (c.app->parsed()) return c.run();
        return 2;
    } catch (const tp::InputError& e) {
        fmt::print(stderr, "twinpath-lab: error: {}\n", e.what());
        return 2;
    } catch (const tp::RuntimeError& e) {
        fmt::print(stderr, "twinpath-lab: error: {}\n", e.what());
        return 3;
    } catch (const std::bad_alloc&) {
        fmt::print(stderr, "twinpath-lab: error: out of host memory\n");
        return 3;
    } catch (const std::exception& e) {
        fmt::print(stderr, "twinpath-lab: internal error: {}\n", e.what());
        return 3;
    }
}
