// twinpath verify SCENE: the CPU reference against the GPU, from the scene to a verdict and,
// when they differ, to the diverging field (verify/verify.h, docs/debugging.md).
// Exit codes as compare's: 0 consistent, 1 different, 2 bad input, 3 runtime failure.
#include "arg_parse.h"
#include "commands.h"
#include "scene_args.h"

#include "render/sampler.h"
#include "scene/features.h"
#include "util/error.h"
#include "util/progress_bar.h"
#include "verify/render_engines.h"
#include "verify/report.h"
#include "verify/summary.h"
#include "verify/verify.h"

#include <fmt/core.h>

#include <filesystem>
#include <memory>
#include <optional>

namespace tp {
namespace {

struct VerifyArgs : SceneArgs {
    std::string detect = "1%";
    std::optional<double> time_budget;
    double alpha = 0.01;
    std::optional<std::string> report;
    std::optional<std::string> bvh;
};

// The verify command these arguments make, for the report's headers.
std::string command_line(const VerifyArgs& a, const std::vector<std::string>& scene_args) {
    std::string s = "twinpath verify";
    for (const std::string& arg : scene_args) s += " " + arg;
    s += fmt::format(" --sampler {} --seed {} --vk-mode {} --detect {} --alpha {}", a.sampler,
                     a.seed, a.vk_mode, a.detect, a.alpha);
    if (!a.device.empty()) s += " --device " + a.device;
    if (a.bvh) s += " --bvh " + *a.bvh;
    if (a.spp) s += fmt::format(" --spp {}", *a.spp);
    if (a.time_budget) s += fmt::format(" --time-budget {}", *a.time_budget);
    return s;
}

int run_verify(const VerifyArgs& a) {
    const double detect = parse_relative_bias("--detect", a.detect);
    if (!(a.alpha > 0.0 && a.alpha < 1.0))
        input_error("--alpha must lie strictly between 0 and 1, got {}", a.alpha);
    if (a.report) {
        // Made before any work, so that a place where it cannot be is bad input (exit 2), not a
        // failure after the renders.
        std::error_code ec;
        if (a.report->empty()) input_error("--report: the path is empty");
        std::filesystem::create_directories(*a.report, ec);
        if (ec || !std::filesystem::is_directory(*a.report))
            input_error("--report {}: cannot make the directory ({})", *a.report,
                        ec ? ec.message() : "a file is in the way");
    }
    const Scene scene = load_scene_args(a);
    const FlatScene flat = flatten(scene);
    if (const std::optional<std::string> w = dark_scene_warning(flat, scene.path))
        fmt::print(stderr, "twinpath: warning: {}\n", *w);

    EngineSetup setup;
    setup.scene = &flat;
    setup.scene_path = scene.path;
    setup.scene_args = scene_render_args(a, flat.params.camera.width, flat.params.camera.height);
    setup.sampler = sampler_from_name(a.sampler);
    setup.threads = a.threads;
    VulkanOptions vk;
    vk.device = a.device;
    if (a.bvh) vk.bvh = parse_bvh_layout(*a.bvh);
    const std::vector<std::unique_ptr<Engine>> owned =
        make_engines(setup, vulkan_engine_modes(a.vk_mode, a.device), vk);
    std::vector<Engine*> engines;
    for (const auto& e : owned) engines.push_back(e.get());

    VerifyOptions o;
    o.plan.detect = detect;
    o.plan.alpha = a.alpha;
    o.plan.budget_s = a.time_budget;
    o.plan.spp = a.spp;
    o.seed = a.seed;
    o.max_depth = flat.params.max_depth;

    std::string against;
    for (size_t k = 1; k < engines.size(); ++k)
        against += (k > 1 ? ", " : "") + engines[k]->label();
    fmt::print(
        "verify {}, {}x{}: {} against {}; finds a uniform bias of {} with probability {:.2g} "
        "at alpha {}\n",
        a.scene, flat.params.camera.width, flat.params.camera.height, engines[0]->label(), against,
        percent(detect), o.plan.power, a.alpha);
    std::fflush(stdout);
    std::unique_ptr<ProgressBar> bar;
    std::string bar_phase;
    VerifyObserver observer;
    observer.line = [&](const std::string& line) {
        bar.reset();
        fmt::print("{}\n", line);
        std::fflush(stdout);
    };
    observer.progress = [&](const std::string& phase, const std::vector<double>& fractions) {
        if (!bar || bar_phase != phase) {
            bar = std::make_unique<ProgressBar>("verify: " + phase);
            bar_phase = phase;
        }
        double least = 1.0;
        std::string note;
        for (size_t k = 0; k < fractions.size(); ++k) {
            least = std::min(least, fractions[k]);
            note += fmt::format("{}{} {:.0f}%", k ? ", " : "", engines[k]->label(),
                                100.0 * fractions[k]);
        }
        bar->update(least, note);
    };
    const VerifyResult v = verify(engines, o, observer);
    bar.reset();
    if (a.report) {
        const ReportContext ctx{command_line(a, setup.scene_args),
                                std::filesystem::read_symlink("/proc/self/exe").string()};
        write_verify_report(*a.report, v, ctx);
        fmt::print("report: {} (commands.sh redoes every step by hand)\n", *a.report);
    }
    return v.different() ? 1 : 0;
}

} // namespace

Subcommand add_verify_command(CLI::App& app) {
    auto a = std::make_shared<VerifyArgs>();
    CLI::App* c = app.add_subcommand(
        "verify", "Check the GPU against the CPU reference: plan, render both at once, compare, "
                  "and on a difference find the diverging field (docs/debugging.md)");
    add_scene_options(c, *a, {"auto", "compute", "pipeline", "both"});
    c->add_option("--detect", a->detect,
                  "Relative bias to find with probability 0.9 (default 1%; also 0.01)");
    c->add_option("--time-budget", a->time_budget,
                  "Seconds for the pilots and the images; when too short, verify says what it "
                  "can detect in them")
        ->check(number_in(1e-3, 1e9));
    c->add_option("--alpha", a->alpha,
                  "False-alarm probability of the whole verdict (default 0.01)");
    c->add_option("--report", a->report,
                  "Write both images, compare's report, the triage and commands.sh into DIR");
    c->add_option("--bvh", a->bvh, "Compute mode's BVH layout: binary, wide, or auto (default)")
        ->check(CLI::IsMember({"binary", "wide", "auto"}));
    return {c, [a] { return run_verify(*a); }};
}

} // namespace tp
