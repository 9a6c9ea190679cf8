// twinpath pathdiff A.json B.json: the first vertex and field where two path logs diverge
// (compare/pathdiff.h, docs/debugging.md). Exit codes: 0 identical within tolerance, 1 they
// diverge, 2 bad input.
#include "arg_parse.h"
#include "commands.h"

#include "compare/pathdiff.h"
#include "util/error.h"

#include <fmt/core.h>

#include <limits>
#include <memory>

namespace tp {
namespace {

struct PathDiffArgs {
    std::vector<std::string> files;
    PathDiffTolerances tol;
};

int run_pathdiff(const PathDiffArgs& a) {
    if (a.files.size() != 2) input_error("pathdiff compares two path logs, got {}", a.files.size());
    const nlohmann::json la = read_path_log(a.files[0]);
    const nlohmann::json lb = read_path_log(a.files[1]);
    const PathDiffResult r = pathdiff(a.files[0], la, a.files[1], lb, a.tol);
    fmt::print("{}", r.report);
    return r.diverged ? 1 : 0;
}

} // namespace

Subcommand add_pathdiff_command(CLI::App& app) {
    auto a = std::make_shared<PathDiffArgs>();
    CLI::App* c = app.add_subcommand(
        "pathdiff", "First vertex and field where two path logs (render --debug-log) diverge");
    c->add_option("logs", a->files, "A.json B.json")->required();
    c->add_option("--geometry-tolerance", a->tol.geometry,
                  "Positions and distances: relative to max(1, |value|) (default 1e-4)")
        ->check(number_in(0.0, std::numeric_limits<double>::max()));
    c->add_option("--direction-tolerance", a->tol.direction,
                  "Directions, normals, barycentrics: absolute (default 1e-3)")
        ->check(number_in(0.0, std::numeric_limits<double>::max()));
    c->add_option("--radiometric-tolerance", a->tol.radiometric,
                  "pdfs, BRDF values, weights, radiance: relative (default 1e-2)")
        ->check(number_in(0.0, std::numeric_limits<double>::max()));
    return {c, [a] { return run_pathdiff(*a); }};
}

} // namespace tp
