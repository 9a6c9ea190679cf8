// twinpath compare A.exr B.exr: do two renderings estimate the same image? (docs/compare.md)
// Also --exact (deterministic layers, bit for bit) and --convergence (error against spp).
// Exit codes: 0 consistent, 1 different (or biased), 2 bad input.
#include "arg_parse.h"
#include "commands.h"
#include "output_paths.h"

#include "compare/compare.h"
#include "compare/convergence.h"
#include "compare/exact.h"
#include "compare/report.h"
#include "compare/summary.h"
#include "image/png_io.h"
#include "util/error.h"
#include "util/json_file.h"

#include <fmt/core.h>

#include <array>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>

namespace tp {
namespace {

struct CompareArgs {
    std::vector<std::string> files;
    double alpha = 0.01;
    std::optional<std::string> json, report; // given (perhaps as "") or not
    std::string reference;
    bool exact = false, convergence = false;
    double tolerance = 0.0;
    int tile = kDefaultTile;
    double floor = kDefaultRelativeFloor;
};

// Runs `write` to fill the report directory; where it fails, the directory goes too if this
// call created it, so a failed report leaves nothing behind.
template <typename Write>
void write_report_dir(const std::string& dir, Write&& write) {
    std::error_code ec;
    const bool existed = std::filesystem::exists(dir, ec);
    try {
        write();
    } catch (...) {
        if (!existed) std::filesystem::remove_all(dir, ec);
        throw;
    }
}

int run_exact(const CompareArgs& a) {
    if (a.files.size() != 2) input_error("--exact compares two images, got {}", a.files.size());
    const ExactResult r = exact_compare(a.files[0], read_exr(a.files[0]), a.files[1],
                                        read_exr(a.files[1]), a.tolerance);
    if (a.json) write_json(*a.json, exact_json(r));
    if (a.report) {
        // The mismatches as a picture: black equal, yellow on a silhouette, red elsewhere.
        std::vector<uint8_t> rgb;
        for (uint8_t m : r.mask)
            for (uint8_t v : m == 2   ? std::array<uint8_t, 3>{255, 0, 0}
                             : m == 1 ? std::array<uint8_t, 3>{255, 220, 0}
                                      : std::array<uint8_t, 3>{0, 0, 0})
                rgb.push_back(v);
        write_report_dir(*a.report, [&] {
            std::filesystem::create_directories(*a.report);
            write_png(*a.report + "/exact_mismatches.png", r.width, r.height, rgb);
        });
    }
    fmt::print("{}\n", exact_verdict_line(r));
    return r.identical() ? 0 : 1;
}

int run_convergence(const CompareArgs& a) {
    if (a.reference.empty()) input_error("--convergence needs --reference REF.exr");
    if (a.files.size() < 2)
        input_error("--convergence needs renderings at two or more spp, got {}", a.files.size());
    const RgbImage ref = load_rgb_image(a.reference);
    std::vector<RgbImage> series;
    for (const std::string& f : a.files) series.push_back(load_rgb_image(f));
    const ConvergenceResult r = convergence(ref, series, a.alpha);
    if (a.json) write_json(*a.json, convergence_json(r, ref));
    fmt::print("{}\n", convergence_verdict_line(r));
    return r.biased ? 1 : 0;
}

int run_statistical(const CompareArgs& a) {
    if (a.files.size() != 2) input_error("compare needs two images, got {}", a.files.size());
    const RgbImage img_a = load_rgb_image(a.files[0]);
    const RgbImage img_b = load_rgb_image(a.files[1]);
    CompareOptions opt;
    opt.alpha = a.alpha;
    opt.tile = a.tile;
    opt.relative_floor = a.floor;
    const CompareResult r = compare_images(img_a, img_b, opt);
    for (const std::string& w : r.warnings) fmt::print(stderr, "twinpath: warning: {}\n", w);
    if (a.json) write_json(*a.json, compare_json(r, img_a, img_b));
    if (a.report) write_report_dir(*a.report, [&] { write_report(*a.report, r, img_a, img_b); });
    fmt::print("{}\n", compare_verdict_line(r));
    return r.different ? 1 : 0;
}

int run_compare(const CompareArgs& a) {
    // Checked first: the JSON below reports every later bad input. The report is a directory
    // that write_report creates, so only its name is checked.
    if (a.json) check_output_paths({{"--json", *a.json}});
    if (a.report && a.report->empty()) input_error("--report: the path is empty");
    try {
        if (!(a.alpha > 0.0 && a.alpha < 1.0))
            input_error("--alpha must lie strictly between 0 and 1, got {}", a.alpha);
        if (a.exact) return run_exact(a);
        if (a.convergence) return run_convergence(a);
        return run_statistical(a);
    } catch (const InputError& e) {
        // The JSON consumer learns why there is no result (the message names the file).
        if (a.json) write_json(*a.json, {{"verdict", "bad input"}, {"error", e.what()}});
        throw;
    }
}

} // namespace

Subcommand add_compare_command(CLI::App& app) {
    auto a = std::make_shared<CompareArgs>();
    CLI::App* c = app.add_subcommand(
        "compare", "Test whether two renderings (OpenEXR with variance) estimate the same image");
    c->add_option("images", a->files, "A.exr B.exr (with --convergence: the spp series)")
        ->required();
    c->add_option("--alpha", a->alpha, "False-alarm probability of the whole test (default 0.01)");
    c->add_option("--json", a->json, "Write the result as JSON");
    c->add_option("--report", a->report, "Write PNGs and index.html into this directory");
    CLI::Option* exact =
        c->add_flag("--exact", a->exact, "Pixel-by-pixel equality of all common channels");
    c->add_option("--tolerance", a->tolerance, "--exact: largest |a - b| counted as equal")
        ->check(number_in(0.0, std::numeric_limits<double>::max()))
        ->needs(exact);
    CLI::Option* conv = c->add_flag("--convergence", a->convergence,
                                    "Fit error against spp over the images, vs --reference")
                            ->excludes(exact);
    c->add_option("--reference", a->reference, "--convergence: the reference image")->needs(conv);
    c->add_option("--tile", a->tile, "Tile size of the global test (default 8)")
        ->check(CLI::Range(1, 4096));
    c->add_option("--floor", a->floor,
                  "Relative floor of the difference's standard deviation (default 1e-4)")
        ->check(number_in(0.0, 1.0));
    return {c, [a] { return run_compare(*a); }};
}

} // namespace tp
