// The last step of every executable of the project (twinpath, twinpath-lab): parse the command
// line into its subcommands, run the one given, and turn each failure into the documented exit
// code (docs/design.md, exit codes; error.h): a usage error 2 with CLI11's message, InputError 2,
// RuntimeError and running out of host memory 3, anything else 3 as an internal error. Header
// only: the executables have CLI11, the libraries need not.
#pragma once

#include "util/error.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <exception>
#include <new>

namespace tp {

// `commands`: each with `app` (its CLI::App*) and `run()` (its exit code); `program` prefixes
// the messages.
template <typename Commands>
int parse_and_run(CLI::App& app, int argc, char** argv, const Commands& commands,
                  const char* program) {
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
        for (const auto& c : commands)
            if (c.app->parsed()) return c.run();
        return 2;
    } catch (const InputError& e) {
        fmt::print(stderr, "{}: error: {}\n", program, e.what());
        return 2;
    } catch (const RuntimeError& e) {
        fmt::print(stderr, "{}: error: {}\n", program, e.what());
        return 3;
    } catch (const std::bad_alloc&) {
        fmt::print(stderr, "{}: error: out of host memory\n", program);
        return 3;
    } catch (const std::exception& e) {
        fmt::print(stderr, "{}: internal error: {}\n", program, e.what());
        return 3;
    }
}

} // namespace tp
